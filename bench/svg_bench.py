"""What writing the lines as SVG adds to a frame: EdgeLight with and without SVG Output, and
EEVEE + Freestyle with and without Blender's Freestyle SVG Exporter add-on
(render_freestyle_svg, shipped with Blender 3.4), on the sample scenes (blend_samples/).

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \
        --python bench/svg_bench.py -- [--repeat 5] [--samples cube,fandisk,prop,toon]

Each scene renders with its own resolution and EdgeLight samples, lines on (its line types);
Freestyle draws visible silhouettes, creases and borders at 1.5 px. Every method renders once
to warm up, then REPEAT rounds time each once, round-robin (the machine is shared); the median
of the wall time of bpy.ops.render.render() is kept, and of the SVG writing alone (the
engine's svg_output.write_render, timed in place). Prints a markdown table.
"""
import argparse
import os
import statistics
import sys
import tempfile
import time

import addon_utils
import bpy

import edgelight.svg_output as svg_output

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="svg_bench.py")
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--samples", default="cube,fandisk,prop,toon")
    return p.parse_args(argv)


def freestyle_setup(scene):
    """One Freestyle line set: visible silhouettes, creases and borders, 1.5 px."""
    vl = scene.view_layers[0]
    vl.use_freestyle = True
    fs = vl.freestyle_settings
    fs.mode = 'EDITOR'
    ls = fs.linesets[0] if len(fs.linesets) else fs.linesets.new("Lines")
    ls.select_by_visibility, ls.visibility = True, 'VISIBLE'
    ls.select_by_edge_types = True
    for t in ("silhouette", "border", "crease"):
        setattr(ls, "select_" + t, True)
    ls.linestyle = ls.linestyle or bpy.data.linestyles.new("Ink")
    ls.linestyle.thickness = 1.5
    ls.linestyle.use_export_strokes = True  # what the SVG exporter writes


def setups(scene, out):
    """method -> function that sets the scene up for it."""
    eevee = "BLENDER_EEVEE_NEXT" if bpy.app.version >= (4, 2, 0) else "BLENDER_EEVEE"
    has_fs_svg = addon_utils.enable("render_freestyle_svg", default_set=False) is not None

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
            scene.svg_export.mode = 'FRAME'
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


def svg_size(path_prefix):
    files = [f for f in os.listdir(os.path.dirname(path_prefix)) if f.endswith(".svg")]
    return {f: os.path.getsize(os.path.join(os.path.dirname(path_prefix), f)) for f in files}


def main():
    a = args()
    rows = []
    for name in a.samples.split(","):
        bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", name + ".blend"))
        scene = bpy.context.scene
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
        sizes = svg_size(os.path.join(out, "el_"))
        el_bytes = sum(v for k, v in sizes.items() if k.startswith("el_"))
        fs_bytes = sum(v for k, v in sizes.items() if not k.startswith("el_"))
        med["write"] = statistics.median(WRITE_SECONDS)
        rows.append((name, f"{scene.render.resolution_x}x{scene.render.resolution_y}", scene.edgelight.samples,
                     med, el_bytes, fs_bytes))
    print("| scene | size | EL samples | EdgeLight + lines | + SVG | SVG adds | of which writing | EdgeLight SVG bytes "
          "| EEVEE + Freestyle | + Freestyle SVG | Freestyle SVG adds | Freestyle SVG bytes |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, size, samples, med, el_bytes, fs_bytes in rows:
        el, el_svg = med["edgelight"] * 1000, med["edgelight_svg"] * 1000
        fs = [f"{med[k] * 1000:.0f} ms" if k in med else "n/a" for k in ("freestyle", "freestyle_svg")]
        fs_add = (f"{(med['freestyle_svg'] - med['freestyle']) * 1000:+.0f} ms "
                  f"({(med['freestyle_svg'] / med['freestyle'] - 1) * 100:+.0f} %)" if "freestyle" in med else "n/a")
        print(f"| {name} | {size} | {samples} | {el:.0f} ms | {el_svg:.0f} ms | {el_svg - el:+.0f} ms "
              f"({(el_svg / el - 1) * 100:+.1f} %) | {med['write'] * 1000:.0f} ms | {el_bytes} | {fs[0]} | {fs[1]} "
              f"| {fs_add} | {fs_bytes or 'n/a'} |")
    sys.stdout.flush()


main()
