"""What writing the lines as SVG adds to a frame: EdgeLight with and without SVG Output, and
EEVEE + Freestyle with and without Blender's Freestyle SVG Exporter add-on
(render_freestyle_svg, shipped with Blender 3.4), on the sample scenes (blend_samples/) and a
hard-surface part built here ("holes": cube.blend's cube with two crossing bores and a corner
notch cut by booleans); and what the two files hold, per line type.

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \
        --python bench/svg_bench.py -- [--repeat 5] [--samples cube,fandisk,prop,toon,holes]

Each scene renders with its own resolution and EdgeLight samples, lines on (its line types);
Freestyle draws one line set per EdgeLight line type it has (visible silhouettes, borders,
creases; material boundaries and edge marks when drawn), each at that type's width, with the
scene's crease angle, so that each type is one group (<g>) in both files. Every method renders
once to warm up, then REPEAT rounds time each once, round-robin (the machine is shared); the
median of the wall time of bpy.ops.render.render() is kept, and of the SVG writing alone (the
engine's svg_output.write_render, timed in place). Prints two markdown tables: the times and
bytes, and per scene and line type, from the last round's files: the polylines (EdgeLight's
<polyline>s, Freestyle's <path>s; each moveto a polyline), their median length in pixels, and
how many end within NEAR_PX of another polyline's start of the same type (a stroke cut in
pieces that could be one).
"""

import argparse
import math
import os
import re
import statistics
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

import addon_utils
import bmesh
import bpy
import numpy as np

import edgelight.host.svg_output as svg_output
import edgelight.linework.lines as lines
import edgelight.linework.svg_write as svg_write

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NEAR_PX = 1.5
# EdgeLight line type -> Freestyle's edge type (its line set's select_<this>); contours have none.
FREESTYLE_TYPES = {
    "silhouette": "silhouette",
    "border": "border",
    "crease": "crease",
    "material": "material_boundary",
    "marked": "edge_mark",
}


def args():
    argv = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="svg_bench.py")
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--samples", default="cube,fandisk,prop,toon,holes")
    return p.parse_args(argv)


def open_scene(name):
    """Opens the sample `name` (blend_samples/), or builds "holes" from cube.blend."""
    if name != "holes":
        bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", name + ".blend"))
        return bpy.context.scene
    bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", "cube.blend"))
    scene = bpy.context.scene
    cube = scene.objects["Cube"]  # 2 x 2 x 2 at the origin; the camera sees +x, -y and +z
    cutters = []

    def cut(name, make, location, rotation=(0.0, 0.0, 0.0)):
        bm = bmesh.new()
        make(bm)
        mesh = bpy.data.meshes.new(name)
        bm.to_mesh(mesh)
        bm.free()
        ob = bpy.data.objects.new(name, mesh)
        scene.collection.objects.link(ob)
        ob.location, ob.rotation_euler = location, rotation
        mod = cube.modifiers.new(name, "BOOLEAN")
        mod.operation, mod.object = "DIFFERENCE", ob
        cutters.append(ob)

    def cylinder(r):
        return lambda bm: bmesh.ops.create_cone(bm, cap_ends=True, segments=32, radius1=r, radius2=r, depth=3.0)

    cut("BoreZ", cylinder(0.45), (0.0, 0.0, 0.0))
    cut("BoreX", cylinder(0.3), (0.0, -0.2, -0.35), (0.0, math.pi / 2, 0.0))
    cut("Notch", lambda bm: bmesh.ops.create_cube(bm, size=1.0), (1.0, -1.0, 1.0))
    # Applied: the part is one plain mesh, as if modelled so.
    mesh = bpy.data.meshes.new_from_object(cube.evaluated_get(bpy.context.evaluated_depsgraph_get()))
    cube.modifiers.clear()
    cube.data = mesh
    for ob in cutters:
        bpy.data.objects.remove(ob)
    return scene


def freestyle_setup(scene):
    """One Freestyle line set per EdgeLight line type with a Freestyle counterpart: its visible
    edges of that type at the type's width (pixels); the crease angle EdgeLight's."""
    vl = scene.view_layers[0]
    vl.use_freestyle = True
    fs = vl.freestyle_settings
    fs.mode = "EDITOR"
    # EdgeLight: a crease bends more than crease_angle; Freestyle: its faces meet at less than this.
    fs.crease_angle = math.pi - scene.edgelight.crease_angle
    for ls in fs.linesets:
        ls.show_render = False
    for kind, _ in lines.settings_of(scene.edgelight).styles:
        if kind not in FREESTYLE_TYPES:
            continue
        ls = fs.linesets.new(kind)
        ls.select_by_visibility, ls.visibility = True, "VISIBLE"
        ls.select_by_edge_types = True
        for t in ("silhouette", "border", "crease"):  # on by default
            setattr(ls, "select_" + t, False)
        setattr(ls, "select_" + FREESTYLE_TYPES[kind], True)
        ls.linestyle = bpy.data.linestyles.new("Ink " + kind)
        prop = getattr(scene.edgelight, "line_" + kind)
        ls.linestyle.thickness = prop.width if prop.unit == "PIXELS" else 1.5
        ls.linestyle.use_export_strokes = True  # what the SVG exporter writes


def setups(scene, out):
    """method -> function that sets the scene up for it."""
    eevee = "BLENDER_EEVEE_NEXT" if bpy.app.version >= (4, 2, 0) else "BLENDER_EEVEE"
    has_fs_svg = addon_utils.enable("render_freestyle_svg", default_set=False) is not None
    scene.edgelight.use_lines = True

    def edgelight(svg):
        def f():
            scene.render.engine = "EDGELIGHT"
            scene.render.filepath = os.path.join(out, "el_")
            scene.render.use_freestyle = False
            scene.edgelight.use_lines = True
            scene.edgelight_svg.enabled = svg
            if has_fs_svg:
                scene.svg_export.use_svg_export = False

        return f

    def freestyle(svg):
        def f():
            scene.render.engine = eevee
            scene.render.filepath = os.path.join(out, "fs_")
            scene.eevee.taa_render_samples = 1
            scene.render.use_freestyle = True
            scene.svg_export.use_svg_export = svg
            scene.svg_export.mode = "FRAME"

        return f

    out_methods = {"edgelight": edgelight(False), "edgelight_svg": edgelight(True)}
    if has_fs_svg:
        freestyle_setup(scene)
        out_methods.update(freestyle=freestyle(False), freestyle_svg=freestyle(True))
    return out_methods


WRITE_SECONDS = []
_write_render = svg_output.write_render


def timed_write_render(*a, **k):
    t = time.perf_counter()
    _write_render(*a, **k)
    WRITE_SECONDS.append(time.perf_counter() - t)


svg_output.write_render = timed_write_render


def time_render():
    t = time.perf_counter()
    bpy.ops.render.render()
    return time.perf_counter() - t


def svg_files(out):
    """(EdgeLight's SVG path, Freestyle's) in `out`; None where none was written."""
    files = sorted(f for f in os.listdir(out) if f.endswith(".svg"))
    el = [f for f in files if f.startswith("el_")]
    fs = [f for f in files if f.startswith("fs_")]
    return tuple(os.path.join(out, f[-1]) if f else None for f in (el, fs))


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_PATH_TOKEN = re.compile(rf"[MmLlZz]|{_NUMBER}")


def path_polylines(d):
    """The polylines of an SVG path's d with moveto, lineto and closepath (absolute or relative;
    numbers after a moveto are linetos): one per moveto."""
    out, cur, cmd, pos, start, pending = [], None, "M", np.zeros(2), np.zeros(2), []
    for tok in _PATH_TOKEN.findall(d):
        if tok in "MmLlZz":
            cmd = tok
            if tok in "Zz" and cur is not None:
                cur.append(start.copy())
                pos = start.copy()
            continue
        pending.append(float(tok))
        if len(pending) < 2:
            continue
        p = np.array(pending)
        pending = []
        if cmd in "ml":
            p = pos + p
        if cmd in "Mm":
            cur = [p]
            out.append(cur)
            start = p
            cmd = "L" if cmd == "M" else "l"
        else:
            cur.append(p)
        pos = p
    return [np.array(c) for c in out]


def svg_polylines(path):
    """type -> [(k, 2) arrays] of an SVG: each <g> whose id (after the last "_": Freestyle's
    group is <view layer>_<line set>) names a line type, maybe with "-hidden", holds that type's
    <polyline> (EdgeLight) or <path> (Freestyle, inside a group per frame) elements."""
    out = {}
    for g in ET.parse(path).getroot().iter():
        if not g.tag.endswith("}g") and g.tag != "g":
            continue
        kind = g.get("id", "").rsplit("_", 1)[-1]
        if kind.removesuffix("-hidden") not in svg_write.LABELS:
            continue
        polys = out.setdefault(kind, [])
        for e in g.iter():
            tag = e.tag.rsplit("}", 1)[-1]
            if tag == "polyline":
                pts = np.array([float(v) for v in re.findall(_NUMBER, e.get("points", ""))])
                polys.append(pts[: len(pts) // 2 * 2].reshape(-1, 2))
            elif tag == "path":
                polys += path_polylines(e.get("d", ""))
    return out


def polyline_stats(polys):
    """(count, median length in pixels (None for none), how many end within NEAR_PX of another's
    start)."""
    polys = [p for p in polys if len(p)]
    if not polys:
        return 0, None, 0
    length = [float(np.sum(np.linalg.norm(np.diff(p, axis=0), axis=1))) for p in polys]
    starts = np.array([p[0] for p in polys])
    ends = np.array([p[-1] for p in polys])
    near = 0
    for i in range(0, len(ends), 1024):
        d = np.linalg.norm(ends[i : i + 1024, None, :] - starts[None, :, :], axis=2)
        rows = np.arange(i, min(i + 1024, len(ends)))
        d[rows - i, rows] = np.inf  # not its own start (a closed loop)
        near += int(np.sum(d.min(axis=1) < NEAR_PX))
    return len(polys), statistics.median(length), near


def main():
    a = args()
    rows, type_rows = [], []
    for name in a.samples.split(","):
        scene = open_scene(name)
        out = tempfile.mkdtemp(prefix=f"svg_bench_{name}_")
        methods = setups(scene, out)
        times = {m: [] for m in methods}
        for m, f in methods.items():  # warm up
            f()
            time_render()
        WRITE_SECONDS.clear()
        for _ in range(a.repeat):
            for m, f in methods.items():
                f()
                times[m].append(time_render())
        med = {m: statistics.median(v) for m, v in times.items()}
        el_svg, fs_svg = svg_files(out)
        el_bytes = os.path.getsize(el_svg) if el_svg else 0
        fs_bytes = os.path.getsize(fs_svg) if fs_svg else 0
        med["write"] = statistics.median(WRITE_SECONDS)
        rows.append(
            (
                name,
                f"{scene.render.resolution_x}x{scene.render.resolution_y}",
                scene.edgelight.samples,
                med,
                el_bytes,
                fs_bytes,
            )
        )
        el_polys = svg_polylines(el_svg) if el_svg else {}
        fs_polys = svg_polylines(fs_svg) if fs_svg else {}
        drawn = [k for k, _ in lines.settings_of(scene.edgelight).styles]
        for kind in drawn + sorted(set(el_polys) - set(drawn)):
            el, fs = polyline_stats(el_polys.get(kind, [])), polyline_stats(fs_polys.get(kind, []))
            if el[0] or fs[0]:
                type_rows.append((name, kind, el, fs if fs_svg and kind in FREESTYLE_TYPES else None))
    print(
        "| scene | size | EL samples | EdgeLight + lines | + SVG | SVG adds | of which writing | EdgeLight SVG bytes "
        "| EEVEE + Freestyle | + Freestyle SVG | Freestyle SVG adds | Freestyle SVG bytes |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, size, samples, med, el_bytes, fs_bytes in rows:
        el, el_svg = med["edgelight"] * 1000, med["edgelight_svg"] * 1000
        fs = [f"{med[k] * 1000:.0f} ms" if k in med else "n/a" for k in ("freestyle", "freestyle_svg")]
        fs_add = (
            f"{(med['freestyle_svg'] - med['freestyle']) * 1000:+.0f} ms "
            f"({(med['freestyle_svg'] / med['freestyle'] - 1) * 100:+.0f} %)"
            if "freestyle" in med
            else "n/a"
        )
        print(
            f"| {name} | {size} | {samples} | {el:.0f} ms | {el_svg:.0f} ms | {el_svg - el:+.0f} ms "
            f"({(el_svg / el - 1) * 100:+.1f} %) | {med['write'] * 1000:.0f} ms | {el_bytes} | {fs[0]} | {fs[1]} "
            f"| {fs_add} | {fs_bytes or 'n/a'} |"
        )
    print()
    print(
        f"| scene | type | polylines EdgeLight | Freestyle | median length EdgeLight | Freestyle "
        f"| end ≤ {NEAR_PX} px from another's start EdgeLight | Freestyle |"
    )
    print("|---|---|---|---|---|---|---|---|")
    for name, kind, el, fs in type_rows:
        fs = fs or ("n/a",) * 3
        length = [f"{v:.1f} px" if isinstance(v, float) else v or "–" for v in (el[1], fs[1])]
        print(f"| {name} | {kind} | {el[0]} | {fs[0]} | {length[0]} | {length[1]} | {el[2]} | {fs[2]} |")
    sys.stdout.flush()


main()
