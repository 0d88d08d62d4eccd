"""The rounded outline's coverage against exact fillets': how much of each part EdgeLight's
outline leaves out that the fillets keep (lost: holes, notches) and keeps that they leave out
(past), per part and width, in the ground truth's framing on a transparent film.

    blender -b --factory-startup --addons edgelight --python bench/outline_coverage.py -- PARTS WIDTHS [OUT_DIR]

PARTS and WIDTHS as bench/ground_truth.py takes them (comma-separated). Reference: the part with
exactly circular fillets (bench/fillets.py, 32 segments, highlights off, 64 samples); EdgeLight
at 8 samples. Prints per part and width the lost and past coverage summed over the image (in
pixels) and the worst 3 x 3 window of lost coverage with where it lies (row, column from the
bottom); with OUT_DIR, saves both renders as .npy there."""
import os
import sys

import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import fillets  # noqa: E402
import gt_scenes  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
PARTS = ARGS[0].split(",") if len(ARGS) > 0 and ARGS[0] else ["joint", "fandisk", "flange", "anchor", "pinion", "l_step"]
WIDTHS = [float(w) for w in ARGS[1].split(",")] if len(ARGS) > 1 and ARGS[1] else [4.0, 8.0]
OUT_DIR = ARGS[2] if len(ARGS) > 2 else None


def render(name, width_px, fillet):
    scene = gt_scenes.open_scene(name, 0.01, 1, gt_scenes.RESOLUTION)
    radius = width_px / gt_scenes.px_per_unit_at_centre(scene)
    scene = gt_scenes.open_scene(name, radius, 64 if fillet else 8, gt_scenes.RESOLUTION)
    scene.render.film_transparent = True
    if fillet:
        fillets.add_fillets(scene, radius, 32, exact=True)
    scene.edgelight.highlights = not fillet
    import edgelight
    edgelight.host.engine.capture = True
    bpy.ops.render.render()
    return np.asarray(edgelight.host.engine.last_render["pixels"], np.float32)


def main():
    if OUT_DIR:
        os.makedirs(OUT_DIR, exist_ok=True)
    for name in PARTS:
        for width in WIDTHS:
            ref, el = render(name, width, True), render(name, width, False)
            lost = np.clip(ref[..., 3] - el[..., 3], 0.0, None)
            past = np.clip(el[..., 3] - ref[..., 3], 0.0, None)
            window = sum(np.roll(np.roll(lost, dy, 0), dx, 1) for dy in (-1, 0, 1) for dx in (-1, 0, 1))
            y, x = np.unravel_index(np.argmax(window), window.shape)
            print(f"{name} {width:g} px: lost {lost.sum():.1f}, worst 3 x 3 {window.max():.2f} at {y},{x}; "
                  f"past {past.sum():.1f}", flush=True)
            if OUT_DIR:
                np.save(os.path.join(OUT_DIR, f"{name}_{width:g}px_reference.npy"), ref)
                np.save(os.path.join(OUT_DIR, f"{name}_{width:g}px_EdgeLight.npy"), el)


if __name__ == "__main__":
    main()
