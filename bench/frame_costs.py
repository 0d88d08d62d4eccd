"""Where a final render's CPU time goes, per triangle: issue 41's targets for extraction plus GPU
batch building (at most 300 ns per triangle on a first render, 50 ns on a render of an
unchanged scene). The cube grid of bench/viewport_bench.py (every cube edge rounded, lines on,
1 sample, 1280 x 720), rendered as an animation of FRAMES frames whose camera moves and whose
meshes do not: Blender keeps the engine for every frame of a job, so frame 1 is a first render
and the later frames are renders of an unchanged scene.

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\
        --python bench/frame_costs.py -- --sizes 100000 1000000 [--write]

Per frame: the wall time of the frame (engine.render), of the extraction (scene_sync.collect)
and of the GPU batches' building (passes/batches.GpuMesh), each measured by wrapping that
function; the first frame's and the best later frame's. --write rewrites its section of
BENCHMARKS.md (bench/bench_table.py).
"""
import argparse
import datetime
import importlib
import math
import os
import sys
import tempfile
import time

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import viewport_bench  # noqa: E402  (the cube grid)

FRAMES = 3


def timed(owner, name, spent):
    """Wraps owner.name so that each call's wall time is added to spent[name]; returns an undo."""
    real = getattr(owner, name)

    def wrapper(*args, **kwargs):
        t = time.perf_counter()
        try:
            return real(*args, **kwargs)
        finally:
            spent[name] = spent.get(name, 0.0) + time.perf_counter() - t
    setattr(owner, name, wrapper)
    return lambda: setattr(owner, name, real)


def grid_animation(triangles):
    size = viewport_bench.grid_scene(triangles)
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y, sc.render.resolution_percentage = 1280, 720, 100
    sc.render.engine = "EDGELIGHT"
    sc.edgelight.samples = 1
    sc.edgelight.use_lines = True
    sc.frame_start, sc.frame_end = 1, FRAMES
    sc.render.filepath = os.path.join(tempfile.mkdtemp(prefix="edgelight_frames_"), "f_")
    cam = sc.camera
    cam.location = (1.2 * size, -1.6 * size, 1.0 * size)
    cam.rotation_euler = (math.radians(60.0), 0.0, math.radians(35.0))
    for f in (1, FRAMES):  # the view turns; the meshes stay
        cam.rotation_euler.z = math.radians(35.0 + 2.0 * (f - 1))
        cam.keyframe_insert("rotation_euler", frame=f)
    return len(bpy.data.objects["Grid"].data.polygons) * 2


def measure(triangles):
    module = os.environ.get("EDGELIGHT_MODULE", "edgelight")
    engine = importlib.import_module(module + ".host.engine")
    scene_sync = importlib.import_module(module + ".extract.scene_sync")
    batches = importlib.import_module(module + ".passes.batches")
    tris = grid_animation(triangles)
    frames, spent = [], {}
    undo = [timed(scene_sync, "collect", spent), timed(batches.GpuMesh, "__init__", spent)]
    real_render = engine.EdgeLightRenderEngine.render

    def render(self, depsgraph):
        spent.clear()
        t = time.perf_counter()
        real_render(self, depsgraph)
        frames.append((time.perf_counter() - t, spent.get("collect", 0.0), spent.get("__init__", 0.0)))
    engine.EdgeLightRenderEngine.render = render
    try:
        bpy.ops.render.render(animation=True)
    finally:
        engine.EdgeLightRenderEngine.render = real_render
        for u in undo:
            u()
    return tris, frames


def row(tris, frame):
    total, extract, build = frame
    ns = (extract + build) / tris * 1e9
    return f"{total:.2f} s | {extract * 1e3:.0f} ms | {build * 1e3:.0f} ms | {ns:.0f} ns"


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", type=int, nargs="+", default=[100_000, 1_000_000])
    ap.add_argument("--write", action="store_true")
    args = ap.parse_args(argv)
    lines = ["| triangles | frame | wall | extraction | GPU batches | extraction + batches per triangle |",
             "|---|---|---|---|---|---|"]
    for size in args.sizes:
        tris, frames = measure(size)
        later = min(frames[1:], key=lambda f: f[1] + f[2])
        lines.append(f"| {tris:,} | first | {row(tris, frames[0])} |")
        lines.append(f"| {tris:,} | later (best of {len(frames) - 1}) | {row(tris, later)} |")
        print("\n".join(lines[-2:]), flush=True)
    text = "\n".join([
        f"The cube grid (every cube edge rounded, lines on), 1 sample, 1280 x 720, an animation of {FRAMES} "
        "frames whose camera turns and whose meshes stay. The first frame extracts and builds everything; "
        "later frames draw the engine's last extractions (scene_sync.only_moved) from its kept GPU batches "
        "(passes/batches.GpuCache). Issue 41's targets for extraction plus batches: 300 ns per triangle "
        "on the first, 50 ns on a repeat. The wall time is llvmpipe's drawing for the most part.", "",
        "Command:", "",
        "    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\",
        "        --python bench/frame_costs.py -- --sizes 100000 1000000 --write", "",
        f"Run of {datetime.date.today()}, Blender {bpy.app.version_string}.", "", *lines])
    print(text)
    if args.write:
        import bench_table
        bench_table.rewrite("frame_costs", text)


if __name__ == "__main__":
    main()
