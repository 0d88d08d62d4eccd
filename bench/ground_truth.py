"""Rounded-edge highlights against real rounded geometry: frame time and error by region.

    blender -b --factory-startup --addons edgelight --python bench/ground_truth.py -- [OUT.csv] [PARTS] [WIDTHS] [METHODS] [REFERENCE]

Ground truth: the same mesh with its rounded edges replaced by circular fillets of radius r
(Bevel modifier, 32 segments, hardened normals: bench/fillets.py; REFERENCE=circular moves
the modifier's vertices onto exact circles: docs/highlight_math.md, "The reference's fillets"),
drawn by EdgeLight with highlights off (so the surface shading is exactly the other methods')
and REF_SAMPLES jittered samples per pixel. Methods, all at SAMPLES samples: highlights off;
EdgeLight; the Bevel modifier with 1, 2, 4, 8 segments and highlights off. METHODS=all adds the
earlier edge methods kept for this comparison (the paper's 1-pixel line, the whole-arc mean, the
per-pixel quadrature: bench/edge_methods.py, bench/shaders/).

Parts (bench/gt_scenes.py): the samples, libcgal-demo meshes and the parts bench/parts.py builds,
each in the fandisk sample's place. Widths are the fillet radius in pixels at the part's centre,
r f / d. Errors on display values (the Standard view transform's sRGB curve, clipped to [0, 1])
over the regions of gt_scenes.regions: RMSE over pixels and channels, max, PSNR = 10 log10(1 / MSE).
Times: median of REPEAT renders after one warm-up, all methods of one part and width back to back.
Writes OUT.csv (default out/ground_truth.csv; one row per part, width, method and region) and
the images as .npy beside it; bench/plot_ground_truth.py draws the plots and the tables.
"""
import os
import statistics
import sys
import time

import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import edge_methods  # noqa: E402
import fillets  # noqa: E402
import gt_scenes  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if len(ARGS) > 0 and ARGS[0] else os.path.join(ROOT, "out", "ground_truth.csv")
PARTS = (ARGS[1].split(",") if len(ARGS) > 1 and ARGS[1] else
         ["cube", "fandisk", "joint", "anchor", "pinion", "couplingdown",
          "l_step", "flange", "gear", "hollow_shaft", "cut_box", "filleted_box"])
WIDTHS = [float(w) for w in ARGS[2].split(",")] if len(ARGS) > 2 and ARGS[2] else [0.3, 1.0, 2.0, 4.0, 8.0]
ALL_METHODS = len(ARGS) > 3 and ARGS[3] == "all"
CIRCULAR = len(ARGS) > 4 and ARGS[4] == "circular"
RESOLUTION = gt_scenes.RESOLUTION
SAMPLES = 8
REF_SAMPLES = 256
REF_SEGMENTS = gt_scenes.REF_SEGMENTS
REPEAT = 3

# name, edge method (None: highlights off), bevel segments (0: the sharp mesh)
METHODS = [("off", None, 0), ("EdgeLight", "partial", 0)]
if ALL_METHODS:
    METHODS += [("paper", "paper", 0), ("whole-arc", "whole", 0), ("reference integral", "quadrature", 0)]
METHODS += [("bevel 1", None, 1), ("bevel 2", None, 2), ("bevel 4", None, 4), ("bevel 8", None, 8)]
REF = f"reference ({'circular' if CIRCULAR else 'bevel'} {REF_SEGMENTS} segments; {REF_SAMPLES} spp)"


def render():
    import edgelight
    edgelight.host.engine.capture = True  # the pass buffers below come from the render's record
    t0 = time.perf_counter()
    bpy.ops.render.render()
    dt = time.perf_counter() - t0
    return dt, dict(edgelight.host.engine.last_render)


def configure(name, radius, method, segments, samples, exact=False):
    s = gt_scenes.open_scene(name, radius, samples, RESOLUTION)
    if segments:
        fillets.add_fillets(s, radius, segments, exact)
    elif method is None:
        s.edgelight.highlights = False
    if method in (None, "partial"):
        edge_methods.restore()  # the add-on's own edge pass
    else:
        edge_methods.use(method)
    return s


def timed(name, radius, method, segments, samples, repeat, exact=False):
    configure(name, radius, method, segments, samples, exact)
    render()  # warm-up: shader compiles, modifier evaluation
    runs = [render() for _ in range(repeat)]
    return statistics.median(t for t, _ in runs), runs[-1][1]


def pixels(rec):
    return np.array(rec["pixels"][..., :3], np.float64)


def main():
    out_dir = os.path.dirname(OUT)
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    for name, width, radius in gt_scenes.parts_and_radii(PARTS, WIDTHS, RESOLUTION):
        t_ref, ref_rec = timed(name, radius, None, REF_SEGMENTS, REF_SAMPLES, 1, exact=CIRCULAR)
        ref = pixels(ref_rec)
        images, times = {}, {}
        for label, method, segments in METHODS:
            times[label], rec = timed(name, radius, method, segments, SAMPLES, REPEAT)
            images[label] = pixels(rec)
            if label == "EdgeLight":
                # Where EdgeLight draws a band: its highlight pass's largest channel (a band at the
                # outline is a change of colour with no alpha).
                band = np.abs(np.asarray(rec["highlight"])).max(axis=-1)
            if label == "off":  # the sharp mesh's coverage and depth
                covered = np.asarray(rec["surface"])[..., 3] > 0.5
                inv_depth = np.asarray(rec["depth"])[..., 0]
            print(f"{name} {width:4.1f}px {label:20s} {times[label]:.3f} s", flush=True)
        s = configure(name, radius, None, 0, 1)  # the sharp part, for its edges' classes
        changed = np.abs(gt_scenes.display(ref) - gt_scenes.display(images["off"])).max(axis=2) > 1.0 / 255.0
        changed |= band > 1.0 / 255.0
        region = gt_scenes.regions(s, changed, covered, width, inv_depth)
        tag = f"{name}_{width:g}px"
        np.save(os.path.join(out_dir, f"gt_{tag}_reference.npy"), ref.astype(np.float32))
        np.savez_compressed(os.path.join(out_dir, f"gt_{tag}_regions.npz"), **region)
        for label, _, _ in METHODS:
            for rname, m in region.items():
                rows.append((name, width, radius, label, times[label], rname, *gt_scenes.errors(images[label], ref, m)))
            np.save(os.path.join(out_dir, f"gt_{tag}_{label.replace(' ', '_')}.npy"), images[label].astype(np.float32))
        rows.append((name, width, radius, REF, t_ref, "all", 0.0, 0.0, float("inf"), int(region["all"].sum())))
        gt_scenes.write_csv(OUT, "part,width_px,radius,method,time_s,region,rmse,max_err,psnr_db,pixels", rows)
    print("wrote", OUT)


if __name__ == "__main__":
    main()
