"""How much of EdgeLight's error against the fillets is its pixel filter: one part at one width,
EdgeLight and the reference (bench/ground_truth.py's) each rendered at SCALE times the
resolution, averaged over each pixel's SCALE x SCALE, and compared per region of a ground-truth
run with the 1x renders of that run.

    blender -b --factory-startup --addons edgelight --python bench/pixel_filter.py -- GT_DIR [PART] [WIDTH] [SCALE]

GT_DIR: a ground_truth.py output directory holding PART at WIDTH (its 1x EdgeLight, reference
and regions). The radius stays the same in the scene, so the band is SCALE times wider in
pixels there; averaged back, EdgeLight's image is what its band gives a square pixel. Prints
PSNR (dB) per region: EdgeLight against the reference at 1x, at SCALE x averaged, and EdgeLight
at 1x against its own SCALE x average.
"""
import os
import sys

import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import fillets  # noqa: E402
import gt_scenes  # noqa: E402
from gt_scenes import REF_SEGMENTS, RESOLUTION  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
GT_DIR = ARGS[0] if ARGS else os.path.join(ROOT, "out")
PART = ARGS[1] if len(ARGS) > 1 else "pinion"
WIDTH = float(ARGS[2]) if len(ARGS) > 2 else 1.0
SCALE = int(ARGS[3]) if len(ARGS) > 3 else 4
SAMPLES = 16  # per fine pixel: SCALE^2 x 16 per pixel of the 1x image


def fine_render(radius, reference):
    import edgelight
    s = gt_scenes.open_scene(PART, radius, SAMPLES, (RESOLUTION[0] * SCALE, RESOLUTION[1] * SCALE))
    if reference:
        fillets.add_fillets(s, radius, REF_SEGMENTS)
    edgelight.host.engine.capture = True
    bpy.ops.render.render()
    fine = np.array(edgelight.host.engine.last_render["pixels"][..., :3], np.float64)
    h, w = RESOLUTION[1], RESOLUTION[0]
    return fine.reshape(h, SCALE, w, SCALE, 3).mean(axis=(1, 3))  # linear light, then display


def main():
    (_, _, radius), = gt_scenes.parts_and_radii([PART], [WIDTH], RESOLUTION)
    tag = os.path.join(GT_DIR, f"gt_{PART}_{WIDTH:g}px")
    el1 = np.load(tag + "_EdgeLight.npy").astype(np.float64)
    ref1 = np.load(tag + "_reference.npy").astype(np.float64)
    regions = np.load(tag + "_regions.npz")
    el_fine = fine_render(radius, reference=False)
    ref_fine = fine_render(radius, reference=True)
    print(f"{PART} {WIDTH:g} px, {SCALE}x: PSNR (dB) EdgeLight-reference at 1x | at {SCALE}x averaged | "
          f"EdgeLight 1x-{SCALE}x averaged")
    for name in ("interior", "convex", "concave", "corners", "outline"):
        m = regions[name]
        if not m.any():
            continue
        psnr = [gt_scenes.errors(a, b, m)[2] for a, b in ((el1, ref1), (el_fine, ref_fine), (el1, el_fine))]
        print(f"  {name:9s} {psnr[0]:5.1f} | {psnr[1]:5.1f} | {psnr[2]:5.1f}  ({int(m.sum())} pixels)")


if __name__ == "__main__":
    main()
