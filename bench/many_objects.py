"""Many separate objects with ink: EdgeLight's final render against Workbench's (issue 41's
1,000 separate cubes). Each cube is its own object with its own copy of the mesh (Shift+D), as
artists' scenes of many parts are; lines on, 1 sample, 640 x 480, best of `--repeat` after a
warm-up, Persistent Data off (every render extracts afresh).

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\
        --python bench/many_objects.py -- --counts 300 1000 --repeat 3 [--write]

--write rewrites its section of BENCHMARKS.md (bench/bench_table.py).
"""
import argparse
import sys
import time

import bpy


def scene(count):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import addon_utils
    addon_utils.enable("edgelight", default_set=True)
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y, sc.render.resolution_percentage = 640, 480, 100
    sc.edgelight.samples = 1
    sc.edgelight.use_lines = True
    bpy.ops.mesh.primitive_cube_add(size=0.4)
    src = bpy.context.object
    side = int(count ** 0.5 + 0.999)
    for i in range(1, count):
        ob = src.copy()
        ob.data = src.data.copy()
        ob.location = ((i % side) - side / 2, (i // side) - side / 2, 0.0)
        sc.collection.objects.link(ob)
    src.location = (-side / 2, -side / 2, 0.0)
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    sc.collection.objects.link(cam)
    sc.camera = cam
    cam.location = (0.0, -1.2 * side, 1.0 * side)
    cam.rotation_euler = (0.9, 0.0, 0.0)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", 'SUN'))
    sc.collection.objects.link(sun)
    return sc


def best(engine, repeat):
    bpy.context.scene.render.engine = engine
    bpy.ops.render.render()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        bpy.ops.render.render()
        times.append(time.perf_counter() - t)
    return min(times)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--counts", type=int, nargs="+", default=[300, 1000])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--write", action="store_true", help="rewrite BENCHMARKS.md's section with the table")
    args = ap.parse_args(argv)
    rows = ["| separate cubes | EdgeLight, lines on | ratio | shadows off | ratio | Workbench |", "|---|---|---|---|---|---|"]
    print("\n".join(rows))
    for count in args.counts:
        sc = scene(count)
        ours = best('EDGELIGHT', args.repeat)
        sc.edgelight.use_shadows = False  # Workbench draws none by default
        plain = best('EDGELIGHT', args.repeat)
        theirs = best('BLENDER_WORKBENCH', args.repeat)
        rows.append(f"| {count} | {ours:.2f} s | {ours / theirs:.1f}x | {plain:.2f} s | {plain / theirs:.1f}x | {theirs:.2f} s |")
        print(rows[-1], flush=True)
    if args.write:
        write(rows, args)


def write(rows, args):
    """BENCHMARKS.md's section (bench/bench_table.py) with this run's table."""
    import datetime
    import os
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import bench_table
    text = f"""A final render of many cubes, each its own object with its own copy of the mesh, lines on,
against Workbench (issue 41's target: 3×), under one sun: EdgeLight with its defaults (the sun
casts shadows, docs/shadows.md) and with Shadows off, as Workbench draws it.

Command:

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\
        --python bench/many_objects.py -- --counts {' '.join(map(str, args.counts))} --repeat {args.repeat} --write

Run of {datetime.date.today().isoformat()}, Blender {bpy.app.version_string}; 640 × 480, 1 sample,
Persistent Data off, best of {args.repeat} after a warm-up.

""" + "\n".join(rows) + """

History and method: docs/benchmark_history.md, "Many separate objects with ink, against Workbench"."""
    bench_table.rewrite("many_objects", text)


main()
