"""Issue 42's scene zoo (tests/blender/material_zoo.py) rendered by EdgeLight, EEVEE and Cycles,
for bench/zoo_flip.py to compare with NVIDIA's FLIP. Per scene, at 320 x 240 with the Standard
view transform (display values, as the artist sees them), into OUT_DIR:

- NAME_edgelight.png: EdgeLight, highlights off (the surface as EEVEE would draw it);
- NAME_edgelight_rounded.png: EdgeLight, highlights on (scenes with rounded edges);
- NAME_eevee.png: EEVEE at 16 samples;
- NAME_cycles_bevel.png: Cycles at 64 samples with a Bevel node of each material's EdgeLight
  radius in its normal (the beveled render the artist previews; scenes with rounded edges);
- times.json: each render's wall time (the second of two, so no program builds count).

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup --addons edgelight \\
        --python bench/zoo_renders.py -- [OUT_DIR]
"""
import json
import os
import sys
import time

import bpy

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "blender"))
import material_zoo  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else os.path.join(ROOT, "out", "zoo")
EEVEE_SAMPLES = 16
CYCLES_SAMPLES = 64


def eevee_engine():
    items = {e.identifier for e in bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items}
    return 'BLENDER_EEVEE_NEXT' if 'BLENDER_EEVEE_NEXT' in items else 'BLENDER_EEVEE'


def add_bevel_nodes():
    """A Bevel node of each rounding material's radius into its Principled BSDF's normal (after
    a Normal Map where there is one)."""
    for mat in bpy.data.materials:
        if not mat.use_nodes or not mat.edgelight.use_rounding:
            continue
        tree = mat.node_tree
        for node in [n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED']:
            bevel = tree.nodes.new('ShaderNodeBevel')
            bevel.samples = 8
            bevel.inputs["Radius"].default_value = mat.edgelight.radius
            normal = node.inputs["Normal"]
            if normal.is_linked:
                tree.links.new(normal.links[0].from_socket, bevel.inputs["Normal"])
            tree.links.new(bevel.outputs["Normal"], normal)


def render(path, repeat=2):
    scene = bpy.context.scene
    scene.render.filepath = path
    scene.render.image_settings.file_format = 'PNG'
    scene.render.image_settings.color_mode = 'RGB'
    scene.view_settings.view_transform = 'Standard'
    best = None
    for _ in range(repeat):
        t = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        best = time.perf_counter() - t
    return best


def main():
    os.makedirs(OUT, exist_ok=True)
    times = {}
    for build in material_zoo.SCENES:
        info = build()
        scene = bpy.context.scene
        name = info.name
        entry = times[name] = {"about": info.about, "rounded": info.rounded, "unsupported": list(info.unsupported)}
        scene.edgelight.highlights = False
        entry["edgelight"] = render(os.path.join(OUT, f"{name}_edgelight.png"))
        if info.rounded:
            scene.edgelight.highlights = True
            entry["edgelight_rounded"] = render(os.path.join(OUT, f"{name}_edgelight_rounded.png"))
        scene.render.engine = eevee_engine()
        scene.eevee.taa_render_samples = EEVEE_SAMPLES
        if hasattr(scene.eevee, "use_soft_shadows"):
            scene.eevee.use_soft_shadows = True
        entry["eevee"] = render(os.path.join(OUT, f"{name}_eevee.png"))
        if info.rounded:
            add_bevel_nodes()
            scene.render.engine = 'CYCLES'
            scene.cycles.samples = CYCLES_SAMPLES
            scene.cycles.use_denoising = False
            scene.cycles.device = 'CPU'
            scene.cycles.seed = 1
            entry["cycles_bevel"] = render(os.path.join(OUT, f"{name}_cycles_bevel.png"), repeat=1)
        print(f"ZOO {name}: " + ", ".join(f"{k} {v:.2f} s" for k, v in entry.items() if isinstance(v, float)), flush=True)
    with open(os.path.join(OUT, "times.json"), "w") as f:
        json.dump({"blender": bpy.app.version_string, "resolution": material_zoo.RESOLUTION, "scenes": times}, f, indent=1)


if __name__ == "__main__":
    main()
