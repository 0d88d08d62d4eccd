"""Plots and tables from bench/ground_truth.py's CSV (plain python3 with numpy and matplotlib).

    python3 bench/plot_ground_truth.py [out/ground_truth.csv] [IMAGE_OUT] [CYCLES_CSV]

Writes beside the CSV: ground_truth_pareto.png (frame time against interior error, one panel
per width: every part and method, each method's mean time and RMS error, their Pareto front), ground_truth.md (the tables for BENCHMARKS.md), and
IMAGE_OUT (default ground_truth_worst.png): for each part at 2 px, the 32 x 32 pixels around
EdgeLight's largest interior error, as EdgeLight, the fillets and their difference (x4).
With CYCLES_CSV (bench/cycles_bevel.py), a table of each method's gain over no rounding against
its own engine's fillets.
"""
import csv
import math
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CSV = sys.argv[1] if len(sys.argv) > 1 else os.path.join("out", "ground_truth.csv")
OUT = os.path.dirname(CSV) or "."
WORST = sys.argv[2] if len(sys.argv) > 2 else os.path.join(OUT, "ground_truth_worst.png")
CYCLES = sys.argv[3] if len(sys.argv) > 3 else None
WORST_WIDTH = 2.0


def load():
    rows = []
    with open(CSV) as f:
        for r in csv.DictReader(f):
            for k in ("width_px", "radius", "time_s", "rmse", "max_err", "psnr_db", "pixels"):
                r[k] = float(r[k])
            rows.append(r)
    return rows


def pareto(points):
    """The points no other point beats in both time and error."""
    front = []
    for t, e in sorted(points):
        if not front or e < front[-1][1]:
            front.append((t, e))
    return front


def psnr(by, part, method, width, region):
    r = by.get((part, method, width, region))
    return r["psnr_db"] if r is not None and r["pixels"] > 0 else float("nan")


def cell(v):
    return "—" if not math.isfinite(v) else f"{v:.1f}"


def main():
    rows = load()
    parts = list(dict.fromkeys(r["part"] for r in rows))
    methods = [m for m in dict.fromkeys(r["method"] for r in rows) if not m.startswith("reference")]
    widths = sorted({r["width_px"] for r in rows})
    by = {(r["part"], r["method"], r["width_px"], r["region"]): r for r in rows}
    colours = {m: plt.cm.tab10(i % 10) for i, m in enumerate(methods)}

    cols = 3
    rows_ = (len(widths) + cols - 1) // cols
    fig, axes = plt.subplots(rows_, cols, figsize=(5.5 * cols, 4.5 * rows_), squeeze=False)
    for ax in axes.flat[len(widths):]:
        ax.axis("off")
    for ax, w in zip(axes.flat, widths):
        stars = []
        for m in methods:
            rs = [by[p, m, w, "interior"] for p in parts if (p, m, w, "interior") in by]
            ax.scatter([r["time_s"] * 1e3 for r in rs], [r["rmse"] for r in rs], s=10, color=colours[m], alpha=0.5)
            mean_t = np.mean([r["time_s"] * 1e3 for r in rs])
            mean_e = np.sqrt(np.mean([r["rmse"] ** 2 for r in rs]))
            ax.scatter([mean_t], [mean_e], s=140, marker="*", color=colours[m], edgecolor="k", label=m)
            stars.append((mean_t, mean_e))
        # The front of the methods (their mean time, RMS error over the parts): parts differ too
        # much in both for a front over single renders to mean anything.
        front = pareto(stars)
        ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=0.8, label="Pareto front (methods)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("frame time, ms (median of 3)")
        ax.set_ylabel("RMSE, interior pixels (display values)")
        ax.set_title(f"{w:g} px: each part (dots); mean time, RMS error (stars)")
        ax.grid(True, which="both", alpha=0.3)
    axes.flat[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ground_truth_pareto.png"), dpi=70)

    head = "| part | " + " | ".join(f"{w:g} px" for w in widths) + " |"
    rule = "|---|" + "---|" * len(widths)
    md = ["**Interior pixels, PSNR (dB): EdgeLight / highlights off / Bevel modifier 4 segments**", "", head, rule]
    for p in parts:
        md.append(f"| {p} | " + " | ".join(
            f"{cell(psnr(by, p, 'EdgeLight', w, 'interior'))} / {cell(psnr(by, p, 'off', w, 'interior'))}"
            f" / {cell(psnr(by, p, 'bevel 4', w, 'interior'))}" for w in widths) + " |")
    for region, title in (("convex", "along convex edges"), ("concave", "along concave edges"),
                          ("corners", "at corners (where rounded edges meet or end)"),
                          ("outline", "at the outline (the fillets move it inwards)")):
        md += ["", f"**{title}, PSNR (dB): EdgeLight / highlights off**", "", head, rule]
        for p in parts:
            md.append(f"| {p} | " + " | ".join(
                f"{cell(psnr(by, p, 'EdgeLight', w, region))} / {cell(psnr(by, p, 'off', w, region))}" for w in widths) + " |")
    md += ["", "**Frame time (ms, median of 3), RMS over parts of the interior RMSE, per width**", "",
           "| method | " + " | ".join(f"{w:g} px" for w in widths) + " |", "|---|" + "---|" * len(widths)]
    for m in methods:
        cells = []
        for w in widths:
            rs = [by[p, m, w, "interior"] for p in parts if (p, m, w, "interior") in by]
            cells.append(f"{np.median([r['time_s'] for r in rs]) * 1e3:.0f} ms, {np.sqrt(np.mean([r['rmse'] ** 2 for r in rs])):.4f}"
                         if rs else "—")
        md.append(f"| {m} | " + " | ".join(cells) + " |")
    if CYCLES:
        cy = {}
        with open(CYCLES) as f:
            for r in csv.DictReader(f):
                cy[r["part"], r["method"], float(r["width_px"]), r["region"]] = float(r["psnr_db"])
        cw = sorted({k[2] for k in cy})
        md += ["", "**Gain over no rounding on interior pixels (dB), each against its own engine's fillets: "
               "EdgeLight / Cycles' Bevel node (64 spp)**", "",
               "| part | " + " | ".join(f"{w:g} px" for w in cw) + " |", "|---|" + "---|" * len(cw)]
        for p in parts:
            cells = []
            for w in cw:
                el = psnr(by, p, "EdgeLight", w, "interior") - psnr(by, p, "off", w, "interior")
                node = cy.get((p, "Cycles + Bevel node", w, "interior"), float("nan")) - cy.get((p, "Cycles", w, "interior"), float("nan"))
                cells.append(f"{el:+.1f} / {node:+.1f}" if math.isfinite(el) and math.isfinite(node) else "—")
            md.append(f"| {p} | " + " | ".join(cells) + " |")
    with open(os.path.join(OUT, "ground_truth.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))
    worst_crops(parts)


def display(c):
    c = np.clip(c, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)


def worst_crops(parts, half=16, zoom=4):
    rows = []
    for p in parts:
        tag = os.path.join(OUT, f"gt_{p}_{WORST_WIDTH:g}px")
        if not os.path.exists(tag + "_EdgeLight.npy"):
            continue
        ours, ref = display(np.load(tag + "_EdgeLight.npy")), display(np.load(tag + "_reference.npy"))
        interior = np.load(tag + "_regions.npz")["interior"]
        err = np.where(interior, np.abs(ours - ref).max(axis=2), 0.0)
        y, x = np.unravel_index(np.argmax(err), err.shape)
        y = int(np.clip(y, half, err.shape[0] - half))
        x = int(np.clip(x, half, err.shape[1] - half))
        crop = [a[y - half:y + half, x - half:x + half][::-1] for a in (ours, ref, np.clip(4.0 * np.abs(ours - ref), 0, 1))]
        rows.append(np.concatenate([np.kron(c, np.ones((zoom, zoom, 1))) for c in crop], axis=1))
    if rows:
        plt.imsave(WORST, np.concatenate(rows, axis=0))


if __name__ == "__main__":
    main()
