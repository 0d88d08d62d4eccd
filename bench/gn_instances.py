"""Geometry Nodes instances with ink: EdgeLight's final render of N cube instances (Instance on
Points on a grid) against the same geometry realised into one mesh (Realize Instances), and the
process's peak memory (issue 41: 10,000 instances at most 1.5x the realised mesh, peak under
1.5 GB). Lines on, 1 sample, 640 x 480, Persistent Data off, best of `--repeat` after a warm-up.
Each mode runs in its own Blender, so that each peak is its own: `--mode both` (the default)
starts one for each and prints the table; --write rewrites its section of BENCHMARKS.md
(bench/bench_table.py).

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\
        --python bench/gn_instances.py -- --count 10000 --repeat 3 [--write]
"""
import argparse
import resource
import sys
import time

import bpy


def scene(count, realize):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import addon_utils
    addon_utils.enable("edgelight", default_set=True)
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y, sc.render.resolution_percentage = 640, 480, 100
    sc.edgelight.samples = 1
    sc.edgelight.use_lines = True
    side = int(count ** 0.5 + 0.999)
    me = bpy.data.meshes.new("Host")
    host = bpy.data.objects.new("Host", me)
    sc.collection.objects.link(host)
    mod = host.modifiers.new("Grid", 'NODES')
    tree = bpy.data.node_groups.new("Grid", 'GeometryNodeTree')
    if hasattr(tree, "interface"):
        tree.interface.new_socket("Geometry", in_out='OUTPUT', socket_type='NodeSocketGeometry')
    else:
        tree.outputs.new('NodeSocketGeometry', "Geometry")
    nodes, links = tree.nodes, tree.links
    out = nodes.new('NodeGroupOutput')
    grid = nodes.new('GeometryNodeMeshGrid')
    grid.inputs["Size X"].default_value = grid.inputs["Size Y"].default_value = float(side)
    grid.inputs["Vertices X"].default_value = grid.inputs["Vertices Y"].default_value = side
    cube = nodes.new('GeometryNodeMeshCube')
    cube.inputs["Size"].default_value = (0.4, 0.4, 0.4)
    inst = nodes.new('GeometryNodeInstanceOnPoints')
    links.new(grid.outputs["Mesh"], inst.inputs["Points"])
    links.new(cube.outputs["Mesh"], inst.inputs["Instance"])
    last = inst.outputs["Instances"]
    if realize:
        real = nodes.new('GeometryNodeRealizeInstances')
        links.new(last, real.inputs[0])
        last = real.outputs[0]
    links.new(last, out.inputs[0])
    mod.node_group = tree
    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    sc.collection.objects.link(cam)
    sc.camera = cam
    cam.location = (0.0, -0.7 * side, 0.6 * side)
    cam.rotation_euler = (0.9, 0.0, 0.0)
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", 'SUN'))
    sc.collection.objects.link(sun)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--count", type=int, default=10000)
    ap.add_argument("--mode", choices=("instanced", "realized", "both"), default="both")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--write", action="store_true", help="rewrite BENCHMARKS.md's section with the table")
    args = ap.parse_args(argv)
    if args.mode == "both":
        both(args)
        return
    scene(args.count, args.mode == "realized")
    bpy.context.scene.render.engine = 'EDGELIGHT'
    bpy.ops.render.render()
    times = []
    for _ in range(args.repeat):
        t = time.perf_counter()
        bpy.ops.render.render()
        times.append(time.perf_counter() - t)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(f"| {args.count} | {args.mode} | {min(times):.2f} s | {peak:.0f} MB |", flush=True)



def both(args):
    """Each mode in a Blender of its own (this one's binary, add-ons and environment): the table."""
    import os
    import subprocess
    rows = ["| instances | mode | EdgeLight, lines on | peak memory |", "|---|---|---|---|"]
    for mode in ("instanced", "realized"):
        run = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", "--addons", "edgelight", "--python",
                              os.path.abspath(__file__), "--", "--count", str(args.count), "--mode", mode,
                              "--repeat", str(args.repeat)], capture_output=True, text=True, check=True)
        rows += [line for line in run.stdout.splitlines() if line.startswith(f"| {args.count} | {mode} |")][:1]
    print("\n".join(rows), flush=True)
    if args.write:
        import datetime
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import bench_table
        bench_table.rewrite("gn_instances", f"""A final render of {args.count:,} Geometry Nodes cube instances against the same geometry realised
into one mesh, and each process's peak memory (issue 41's targets: 1.5×, 1.5 GB).

Command:

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\
        --python bench/gn_instances.py -- --count {args.count} --repeat {args.repeat} --write

Run of {datetime.date.today().isoformat()}, Blender {bpy.app.version_string}; 640 × 480, 1 sample,
Persistent Data off, best of {args.repeat} after a warm-up, each mode in its own Blender.

""" + "\n".join(rows) + """

History and method: docs/benchmark_history.md, "Geometry Nodes instances with ink, against the same geometry realised".""")


main()
