"""Plots and tables from bench/ground_truth.py's CSV (plain python3 with numpy and matplotlib).

    python3 bench/plot_ground_truth.py [out/ground_truth.csv]

Writes out/ground_truth_pareto.png (frame time against error, every method and width; the
Pareto front of each scene drawn), out/ground_truth_error_curve.png (error against the radius in
pixels, the wide-edge curve before and after) and out/ground_truth.md (the tables for
BENCHMARKS.md).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CSV = sys.argv[1] if len(sys.argv) > 1 else os.path.join("out", "ground_truth.csv")
OUT = os.path.dirname(CSV) or "."
REF = "reference (bevel 32 segments; 64 spp)"
TABLE_WIDTHS = (0.3, 1.0, 2.0, 4.0, 8.0)


def load():
    rows = []
    with open(CSV) as f:
        for r in csv.DictReader(f):
            for k in r:
                if k not in ("scene", "method"):
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


def main():
    rows = load()
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    methods = [m for m in dict.fromkeys(r["method"] for r in rows) if m != REF]
    colours = {m: plt.cm.tab10(i % 10) for i, m in enumerate(methods)}
    by = {(r["scene"], r["method"], r["width_px"]): r for r in rows}
    widths = sorted({r["width_px"] for r in rows})

    fig, axes = plt.subplots(1, len(scenes), figsize=(7 * len(scenes), 5.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        pts = []
        for m in methods:
            rs = [by[scene, m, w] for w in widths if (scene, m, w) in by]
            ax.scatter([r["time_s"] * 1e3 for r in rs], [r["rmse_interior"] for r in rs], s=[12 + 10 * r["width_px"] for r in rs],
                       color=colours[m], label=m, alpha=0.8)
            pts += [(r["time_s"] * 1e3, r["rmse_interior"]) for r in rs]
        front = pareto(pts)
        ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=0.8, label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("frame time, ms (median of 3)")
        ax.set_ylabel("RMSE near interior edges (display values)")
        ax.set_title(f"{scene}: time vs error (marker size ~ radius in px)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ground_truth_pareto.png"), dpi=90)

    fig, axes = plt.subplots(1, len(scenes), figsize=(7 * len(scenes), 5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for m in methods:
            rs = [by[scene, m, w] for w in widths if (scene, m, w) in by]
            style = "-o" if m in ("EdgeLight", "whole-arc (before)") else ":."
            ax.plot([r["width_px"] for r in rs], [r["rmse_interior"] for r in rs], style, color=colours[m], label=m)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.axvline(1.0, color="grey", lw=0.8)
        ax.set_xlabel("fillet radius in pixels (r f / d at the object's centre)")
        ax.set_ylabel("RMSE near interior edges (display values)")
        ax.set_title(f"{scene}: error against width")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ground_truth_error_curve.png"), dpi=90)

    md = []
    for scene in scenes:
        tw = [w for w in widths if any(abs(w - t) < 1e-9 for t in TABLE_WIDTHS)] or widths
        md += [f"**{scene}**, interior edges: RMSE / max / PSNR (dB), display values; frame time in ms", "",
               "| method | " + " | ".join(f"{w:g} px" for w in tw) + " | time (ms), " + " / ".join(f"{w:g}" for w in tw) + " |",
               "|---|" + "---|" * (len(tw) + 1)]
        for m in methods + [REF]:
            cells = []
            for w in tw:
                r = by.get((scene, m, w))
                cells.append("—" if r is None or m == REF else
                             f"{r['rmse_interior']:.4f} / {r['max_err_interior']:.3f} / {r['psnr_db_interior']:.1f}")
            times = " / ".join(f"{by[scene, m, w]['time_s'] * 1e3:.0f}" for w in tw if (scene, m, w) in by)
            md.append(f"| {m} | " + " | ".join(cells) + f" | {times} |")
        md += ["", f"**{scene}**, all pixels near edges (outline included): RMSE / PSNR (dB)", "",
               "| method | " + " | ".join(f"{w:g} px" for w in tw) + " |", "|---|" + "---|" * len(tw)]
        for m in methods:
            cells = [f"{by[scene, m, w]['rmse']:.4f} / {by[scene, m, w]['psnr_db']:.1f}" if (scene, m, w) in by else "—" for w in tw]
            md.append(f"| {m} | " + " | ".join(cells) + " |")
        md += ["", f"**{scene}**, error curve (interior RMSE) against width, before and after:", "",
               "| radius (px) | " + " | ".join(f"{w:g}" for w in widths) + " |", "|---|" + "---|" * len(widths)]
        for m in ("whole-arc (before)", "EdgeLight", "paper", "reference integral", "off"):
            md.append(f"| {m} | " + " | ".join(f"{by[scene, m, w]['rmse_interior']:.4f}" if (scene, m, w) in by else "—"
                                               for w in widths) + " |")
        md.append("")
    with open(os.path.join(OUT, "ground_truth.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


main()
