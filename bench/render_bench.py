"""Final-render time of each sample at 1280x720, EdgeLight beside the ways artists get rounded
edges today, all in one Blender run (ratios are what to read: the machine is shared).

    blender -b --factory-startup --addons edgelight --python bench/render_bench.py -- OUT.md [SAMPLES]

Each configuration renders once to warm up (shader compiles, BVH), then REPEAT times; the table
keeps the fastest. Configurations change only the in-memory copy of the sample, never the file.
"""
import os
import sys
import time

import bpy

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else os.path.join(ROOT, "out", "render_bench.md")
SAMPLE_NAMES = ARGS[1].split(",") if len(ARGS) > 1 else ["cube", "fandisk", "prop"]
AA_SAMPLES = 8
REPEAT = 3


def open_sample(name):
    bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", name + ".blend"))
    s = bpy.context.scene
    s.render.resolution_x, s.render.resolution_y, s.render.resolution_percentage = 1280, 720, 100
    s.view_settings.view_transform = 'Standard'
    return s


def edgelight(highlights):
    def setup(s):
        s.render.engine = "EDGELIGHT"
        s.edgelight.samples = AA_SAMPLES
        s.edgelight.highlights = highlights
    return setup


def workbench(s):
    s.render.engine = "BLENDER_WORKBENCH"
    s.display.render_aa = str(AA_SAMPLES)


def eevee(s):
    import edgelight
    s.render.engine = edgelight.compat.eevee_engine_id()
    s.eevee.taa_render_samples = AA_SAMPLES


def cycles(s):
    s.render.engine = "CYCLES"
    s.cycles.device = 'CPU'
    s.cycles.samples = AA_SAMPLES
    s.cycles.use_denoising = False
    if hasattr(s.cycles, "use_adaptive_sampling"):
        s.cycles.use_adaptive_sampling = False


def cycles_bevel_node(s):
    cycles(s)
    for mat in bpy.data.materials:
        if not (mat.use_nodes and mat.node_tree):
            continue
        nodes, links = mat.node_tree.nodes, mat.node_tree.links
        for bsdf in [n for n in nodes if n.type == 'BSDF_PRINCIPLED']:
            bevel = nodes.new("ShaderNodeBevel")
            bevel.inputs["Radius"].default_value = mat.edgelight.radius
            bevel.samples = 8
            links.new(bevel.outputs["Normal"], bsdf.inputs["Normal"])


def cycles_bevel_modifier(s):
    cycles(s)
    for ob in s.objects:
        if ob.type != 'MESH':
            continue
        radius = ob.active_material.edgelight.radius if ob.active_material else 0.01
        mod = ob.modifiers.new("Bevel", 'BEVEL')
        mod.width = radius
        mod.segments = 4
        mod.limit_method = 'ANGLE'
        if hasattr(mod, "harden_normals"):
            mod.harden_normals = False


CONFIGS = [
    ("EdgeLight, surface only", edgelight(False)),
    ("EdgeLight, surface + highlights", edgelight(True)),
    ("Workbench", workbench),
    ("EEVEE", eevee),
    ("Cycles + Bevel node", cycles_bevel_node),
    ("Cycles + Bevel modifier (4 segments)", cycles_bevel_modifier),
]


def time_render():
    t0 = time.perf_counter()
    bpy.ops.render.render()
    return time.perf_counter() - t0


def main():
    results = {}
    for name in SAMPLE_NAMES:
        for label, setup in CONFIGS:
            s = open_sample(name)
            setup(s)
            time_render()  # warm-up
            results[(name, label)] = min(time_render() for _ in range(REPEAT))
            print(f"{name:8s} {label:40s} {results[(name, label)]:.3f} s", flush=True)
    lines = [f"Blender {bpy.app.version_string}, 1280x720, {AA_SAMPLES} samples per pixel in every engine, "
             f"best of {REPEAT} after a warm-up; ratios against EdgeLight surface + highlights.", "",
             "| sample | " + " | ".join(label for label, _ in CONFIGS) + " |",
             "|---|" + "---|" * len(CONFIGS)]
    for name in SAMPLE_NAMES:
        full = results[(name, "EdgeLight, surface + highlights")]
        cells = [f"{results[(name, label)]:.2f} s ({results[(name, label)] / full:.2f}x)" for label, _ in CONFIGS]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    lines.append("")
    for name in SAMPLE_NAMES:
        surface = results[(name, "EdgeLight, surface only")]
        full = results[(name, "EdgeLight, surface + highlights")]
        wb = results[(name, "Workbench")]
        lines.append(f"- {name}: highlights add {100.0 * (full / surface - 1.0):.0f}% to the surface pass "
                     f"(target <= 20%); full EdgeLight frame / Workbench = {full / wb:.2f} (target <= 1)")
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    with open(OUT, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


main()
