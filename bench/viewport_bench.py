"""view_draw time in the 3D view (Rendered shading), one UI session under xvfb-run:

    xvfb-run -a -s "-screen 0 1400x1000x24" blender --factory-startup --addons edgelight \
        --python bench/viewport_bench.py -- out/viewport_bench.md

Scenes: the samples, and generated scenes of 100k and 1M triangles: grids of cubes with every
cube edge rounded (a stress case: one rounded edge per triangle), and arrays of the fandisk part
(linked duplicates, rounded at its creases). EDGELIGHT_BENCH_SCENES=cube,100k,parts100k picks
scenes. Modes: 'orbit' turns the view 1 degree before every draw (a new image each
time), with highlights off (surface only), on, on with the edge pass's floor (its quads with a
fragment shader that does next to nothing: its cost before any shading; bench/edge_methods.py), and off
with ink lines (silhouettes, creases above 45 degrees, borders: a native view update and new
silhouette batches per draw); 'static' redraws an unchanged view (the cached image). Times come from bpy.ops.wm.redraw_timer, best of REPEAT runs.
Before each run, a mode draws once a view the run never draws (turned -1 degree), so that no
timed orbit draw finds its image cached. bench/scaling_bench.py imports the helpers here.
"""
import math
import os
import sys
import time

import bpy
import numpy as np
from mathutils import Quaternion

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import edge_methods  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else os.path.join(ROOT, "out", "viewport_bench.md")
FRAMES = 10
REPEAT = 5
BIG_REPEAT = 3  # the 1M scenes: runs of 3 draws
# EDGELIGHT_BENCH_SCENES=cube,100k,parts1000k: only those (samples by name; grids, part arrays).
ONLY = [x for x in os.environ.get("EDGELIGHT_BENCH_SCENES", "").split(",") if x]
rows = []


def view3d():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == 'VIEW_3D')
    region = next(r for r in area.regions if r.type == 'WINDOW')
    return window, area, region


def cube_grid(count):
    """One mesh of `count` unit cubes on a grid (12 triangles, 12 creases each)."""
    side = int(math.ceil(count ** (1.0 / 3.0)))
    idx = np.arange(count)
    centres = np.c_[idx % side, (idx // side) % side, idx // (side * side)].astype(np.float32) * 2.0
    corners = np.array([(x, y, z) for z in (-.5, .5) for y in (-.5, .5) for x in (-.5, .5)], np.float32)
    quads = np.array([(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])
    verts = (centres[:, None, :] + corners[None]).reshape(-1, 3)
    faces = (quads[None] + 8 * idx[:, None, None]).reshape(-1, 4)
    me = bpy.data.meshes.new("Grid")
    me.vertices.add(len(verts))
    me.vertices.foreach_set("co", verts.ravel())
    me.loops.add(faces.size)
    me.loops.foreach_set("vertex_index", faces.ravel())
    me.polygons.add(len(faces))
    me.polygons.foreach_set("loop_start", np.arange(0, faces.size, 4))
    me.polygons.foreach_set("loop_total", np.full(len(faces), 4))
    me.update(calc_edges=True)
    return me, side * 2.0


def grid_scene(triangles):
    bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", "cube.blend"))
    cube = bpy.data.objects["Cube"]
    mat = cube.active_material
    bpy.data.objects.remove(cube)
    me, size = cube_grid(triangles // 12)
    me.materials.append(mat)
    ob = bpy.data.objects.new("Grid", me)
    bpy.context.scene.collection.objects.link(ob)
    ob.location = (-size / 2, -size / 2, -size / 2)
    return size


def part_array(triangles):
    """The fandisk sample repeated as linked duplicates (one mesh, many objects) on a grid until
    the scene has `triangles`: a dense hard-surface scene, rounded where its creases are (~5 %
    of its edges), unlike the cube grid where every cube edge is."""
    bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", "fandisk.blend"))
    part = bpy.data.objects["Fandisk"]
    count = int(math.ceil(triangles / len(part.data.polygons)))
    side = int(math.ceil(count ** (1.0 / 3.0)))
    step = 1.3 * max(part.dimensions)
    for k in range(count):
        ob = part if k == 0 else part.copy()  # copy() shares the mesh
        if k:
            bpy.context.scene.collection.objects.link(ob)
        ob.location = ((k % side - (side - 1) / 2) * step, ((k // side) % side - (side - 1) / 2) * step,
                       (k // (side * side) - (side - 1) / 2) * step)
    return side * step


def turned(rotation, degrees):
    """`rotation` (a view rotation) turned by `degrees` about the view's Z: one orbit step."""
    return rotation @ Quaternion((0, 0, 1), math.radians(degrees))


def draw_ms(orbit, frames=FRAMES, repeat=REPEAT):
    window, area, region = view3d()
    rv3d = region.data
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(frames):
            if orbit:
                rv3d.view_rotation = turned(rv3d.view_rotation, 1.0)
            with bpy.context.temp_override(window=window, area=area, region=region):
                bpy.ops.wm.redraw_timer(type='DRAW', iterations=1)
        best = min(best, (time.perf_counter() - t0) / frames * 1000.0)
    return best


def warm_up(start):
    """One draw of a view that no timed orbit draws (`start` turned by -1 degree; the timed runs
    turn +1 degree per draw from `start`): extraction, batches, shaders, a new mode's first image,
    without leaving the timed run's first view in a cache. Then back to `start`."""
    rv3d = view3d()[2].data
    rv3d.view_rotation = turned(start, -1.0)
    draw_ms(False, 1, 1)
    rv3d.view_rotation = start


def rendered_view(distance=None):
    """The 3D view in Rendered shading without overlays, in perspective, looking at the origin
    from `distance` if given; 1 EdgeLight viewport sample. Returns the view's RegionView3D."""
    _, area, region = view3d()
    space = area.spaces.active
    space.shading.type = 'RENDERED'
    space.overlay.show_overlays = False
    rv3d = region.data
    rv3d.view_perspective = 'PERSP'
    if distance:
        rv3d.view_location = (0, 0, 0)
        rv3d.view_distance = distance
    bpy.context.scene.edgelight.viewport_samples = 1
    return rv3d


def measure(name, distance=None, frames=FRAMES, repeat=REPEAT):
    rv3d = rendered_view(distance)
    scene = bpy.context.scene
    result = {}
    start = rv3d.view_rotation.copy()
    # The modes take turns, `repeat` rounds, best of each: load from elsewhere on this shared
    # machine then hits all modes alike instead of one mode's whole run. Every run starts from the
    # same view (orbiting, each run would otherwise see the model from elsewhere).
    for round_ in range(repeat):
        for label, highlights, floor, lines, orbit in (("surface only, orbit", False, False, False, True),
                                                       ("surface + lines, orbit", False, False, True, True),
                                                       ("surface + highlights, orbit", True, False, False, True),
                                                       ("edge quads, no shading, orbit", True, True, False, True),
                                                       ("static redraw (cache hit)", True, False, False, False)):
            scene.edgelight.highlights = highlights
            scene.edgelight.use_lines = lines
            if floor:
                edge_methods.use("partial", floor=True)
            else:
                edge_methods.restore()
            warm_up(start)
            if not orbit:
                draw_ms(False, 1, 1)  # the image of the start view, which the static runs redraw
            result[label] = min(result.get(label, float("inf")), draw_ms(orbit, frames, 1))
    edge_methods.restore()
    import edgelight
    c = edgelight.host.viewport.last_state.counters
    tris = sum(len(inst.mesh.corner_pos) // 3 for inst in edgelight.host.viewport.last_state.instances)
    rows.append((name, tris, c.edges_drawn, c.edges_culled, result))
    print(name, tris, result, flush=True)


def steps():
    for name in ("cube", "fandisk", "prop", "toon"):
        if ONLY and name not in ONLY:
            continue
        bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", name + ".blend"))
        yield
        measure(name)
    for tris in (100_000, 1_000_000):
        big = tris >= 1_000_000  # a draw takes seconds on llvmpipe: fewer of them
        if not ONLY or f"{tris // 1000}k" in ONLY:
            size = grid_scene(tris)
            yield
            measure(f"{tris // 1000}k-triangle cube grid", distance=size * 2.2, frames=3 if big else FRAMES, repeat=BIG_REPEAT if big else REPEAT)
        if not ONLY or f"parts{tris // 1000}k" in ONLY:
            size = part_array(tris)
            yield
            measure(f"{tris // 1000}k-triangle fandisk array", distance=size * 1.6, frames=3 if big else FRAMES, repeat=BIG_REPEAT if big else REPEAT)
    _, _, region = view3d()
    lines = [f"Blender {bpy.app.version_string}, 3D view {region.width}x{region.height} px, Rendered shading, "
             f"1 viewport sample; ms per view_draw, best of {REPEAT} runs of {FRAMES} draws, the modes taking turns "
             f"(the 1M scenes: best of {BIG_REPEAT} runs of 3).", "",
             "| scene | triangles | edges drawn / culled | surface only, orbit | surface + lines, orbit "
             "| surface + highlights, orbit | edge quads, no shading | static redraw | lines add | highlights add "
             "| quads alone add | static / surface only |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, tris, drawn, culled, r in rows:
        s, ln, h, fl, st = (r["surface only, orbit"], r["surface + lines, orbit"], r["surface + highlights, orbit"],
                            r["edge quads, no shading, orbit"], r["static redraw (cache hit)"])
        lines.append(f"| {name} | {tris:,} | {drawn:,} / {culled:,} | {s:.1f} | {ln:.1f} | {h:.1f} | {fl:.1f} | {st:.1f} | "
                     f"{100 * (ln / s - 1):.0f}% | {100 * (h / s - 1):.0f}% | {100 * (fl / s - 1):.0f}% | {st / s:.2f} |")
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines), flush=True)


def run(gen):
    """Runs the generator `gen` from a timer, one step per tick, so that the UI redraws between
    steps (a freshly opened file gets its 3D view); Blender exits when it ends (status 1 on an
    exception)."""
    def tick():
        try:
            next(gen)
            return 0.5
        except StopIteration:
            os._exit(0)
        except Exception:
            import traceback
            traceback.print_exc()
            os._exit(1)

    bpy.app.timers.register(tick, first_interval=1.0, persistent=True)  # survives open_mainfile


def main():
    import edgelight
    edgelight.host.engine.capture = True  # keep the viewport state and renders for the counts read here
    run(steps())


if __name__ == "__main__":  # Blender's --python runs the script as __main__; bench/scaling_bench.py imports it
    main()
