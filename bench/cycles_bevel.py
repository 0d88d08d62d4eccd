"""Cycles' Bevel shader node against true fillets in Cycles: the gain an offline renderer gets
from shading-only rounding, to hold EdgeLight's gain against (bench/ground_truth.py).

    blender -b --factory-startup --addons edgelight --python bench/cycles_bevel.py -- OUT.csv [PARTS] [WIDTHS] [GT_DIR]

Per part and width, three Cycles renders at SAMPLES samples (denoising off): the sharp mesh; the
sharp mesh with a Bevel node of radius r (8 samples) feeding every Principled BSDF's normal; and,
as the reference, the mesh with 32-segment fillets (bench/fillets.py) at REF_SAMPLES. Errors on
display values over the regions ground_truth.py saved for the same part and width (GT_DIR,
default out/): the same pixels EdgeLight is judged on.
"""
import os
import sys
import time

import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import fillets  # noqa: E402
import gt_scenes  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else os.path.join(ROOT, "out", "cycles_bevel.csv")
PARTS = ARGS[1].split(",") if len(ARGS) > 1 and ARGS[1] else ["cube", "fandisk", "l_step", "gear"]
WIDTHS = [float(w) for w in ARGS[2].split(",")] if len(ARGS) > 2 and ARGS[2] else [1.0, 2.0, 4.0]
GT_DIR = ARGS[3] if len(ARGS) > 3 else os.path.join(ROOT, "out")
RESOLUTION = gt_scenes.RESOLUTION
SAMPLES = 64
REF_SAMPLES = 256


def cycles_scene(name, radius, samples):
    s = gt_scenes.open_scene(name, radius, 1, RESOLUTION)
    s.render.engine = 'CYCLES'
    s.cycles.samples = samples
    s.cycles.use_denoising = False
    s.cycles.device = 'CPU'
    s.cycles.seed = 1
    return s


def add_bevel_node(radius):
    for mat in bpy.data.materials:
        if not mat.use_nodes:
            continue
        tree = mat.node_tree
        bevel = tree.nodes.new('ShaderNodeBevel')
        bevel.samples = 8
        bevel.inputs["Radius"].default_value = radius
        for node in tree.nodes:
            if node.type == 'BSDF_PRINCIPLED':
                tree.links.new(bevel.outputs["Normal"], node.inputs["Normal"])


def render(path):
    s = bpy.context.scene
    s.render.filepath = path
    s.render.image_settings.file_format = 'OPEN_EXR'
    s.render.image_settings.color_depth = '32'
    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    dt = time.perf_counter() - t0
    img = bpy.data.images.load(path + ".exr" if not path.endswith(".exr") else path)
    px = np.array(img.pixels[:], np.float32).reshape(img.size[1], img.size[0], 4)[..., :3]
    bpy.data.images.remove(img)
    return dt, px.astype(np.float64)


def main():
    out_dir = os.path.dirname(OUT)
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    for name, width, radius in gt_scenes.parts_and_radii(PARTS, WIDTHS, RESOLUTION):
        regions = np.load(os.path.join(GT_DIR, f"gt_{name}_{width:g}px_regions.npz"))
        tag = os.path.join(out_dir, f"cy_{name}_{width:g}px")
        s = cycles_scene(name, radius, REF_SAMPLES)
        fillets.add_fillets(s, radius, gt_scenes.REF_SEGMENTS)
        s.render.engine = 'CYCLES'  # add_fillets turns EdgeLight's highlights off only
        t_ref, ref = render(tag + "_reference")
        images = {}
        cycles_scene(name, radius, SAMPLES)
        images["Cycles"] = render(tag + "_plain")
        cycles_scene(name, radius, SAMPLES)
        add_bevel_node(radius)
        images["Cycles + Bevel node"] = render(tag + "_bevel")
        for label, (dt, img) in images.items():
            for rname in ("interior", "all"):
                rows.append((name, width, label, dt, rname, *gt_scenes.errors(img, ref, regions[rname])))
            print(f"{name} {width:g}px {label}: {dt:.1f} s", flush=True)
        rows.append((name, width, f"reference ({REF_SAMPLES} spp)", t_ref, "all", 0.0, 0.0, float("inf"), 0))
        gt_scenes.write_csv(OUT, "part,width_px,method,time_s,region,rmse,max_err,psnr_db,pixels", rows)
    print("wrote", OUT)


if __name__ == "__main__":
    main()
