"""Cost against triangle count, in the 3D view and in the final render, one UI session under xvfb-run:

    xvfb-run -a -s "-screen 0 1400x1000x24" blender --factory-startup --addons edgelight \
        --python bench/scaling_bench.py -- out/scaling_bench.md [--sizes 10k,40k,100k,400k,1M,4M]

Scenes: bench/viewport_bench.py's cube grids (every cube edge rounded: one rounded edge per
triangle, the worst case) of 10k, 40k, 100k, 400k, 1M and 4M triangles. Per scene:

  viewport   ms per orbit draw (Rendered shading, 1 viewport sample, viewport_bench's timing: the
             view turns 1 degree before every draw, each mode warmed up on a view no timed draw
             sees, the modes taking turns, best of the rounds): EdgeLight surface only,
             + highlights, + lines (the scene's silhouettes, creases, borders, as viewport_bench),
             and Workbench (the scene's engine set to BLENDER_WORKBENCH, no anti-aliasing);
  render     wall time of bpy.ops.render.render at RES_X x RES_Y (1 sample; Workbench without
             anti-aliasing) from a 3/4 camera framing the grid (bench/lines_bench.py's
             frame_camera): EdgeLight surface only, + highlights, + lines; Workbench; Line Art
             (bench/lines_bench.py's add_lineart over the grid, contour + crease at EdgeLight's
             crease angle, strokes EdgeLight's width in pixels, rendered with Workbench: the
             Line Art column minus the Workbench column is what Line Art adds). Each method renders
             once to warm up (writing a PNG beside the output), then the methods take turns, best
             of the rounds. Once a Line Art render takes more than LINEART_LIMIT_S, Line Art is
             recorded once on that scene and skipped on the larger ones.

Writes the markdown at the given path (rewritten after every scene), a CSV beside it and the PNGs
in a directory beside it. Slopes: numpy polyfit of log(ms) against log(triangles), over all the
sizes measured and over 100k..4M.
"""
import argparse
import datetime
import math
import os
import sys
import time

import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import lines_bench  # noqa: E402
import viewport_bench as vb  # noqa: E402

SIZES = (10_000, 40_000, 100_000, 400_000, 1_000_000, 4_000_000)
RES_X, RES_Y = 960, 540
LINEART_LIMIT_S = 10.0
FIT_FROM = 100_000  # the second slope: 100k..4M


def plan(tris):
    """(viewport draws per run, viewport rounds, render rounds): fewer on the big scenes, whose
    draws take seconds on llvmpipe."""
    if tris <= 100_000:
        return 10, 5, 3
    if tris <= 400_000:
        return 5, 3, 2
    if tris <= 1_000_000:
        return 3, 3, 2
    return 2, 2, 1


VIEW_MODES = (  # label, engine, highlights, lines
    ("surface", "EDGELIGHT", False, False),
    ("+ highlights", "EDGELIGHT", True, False),
    ("+ lines", "EDGELIGHT", False, True),
    ("Workbench", "BLENDER_WORKBENCH", False, False),
)
RENDER_MODES = VIEW_MODES + (("Line Art", "BLENDER_WORKBENCH", False, False),)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="scaling_bench.py")
    p.add_argument("out", nargs="?", default=os.path.join(ROOT, "out", "scaling_bench.md"))
    p.add_argument("--sizes", default=",".join(f"{s // 1000}k" for s in SIZES),
                   help="triangle counts, e.g. 10k,40k,1M")
    a = p.parse_args(argv)
    a.sizes = [int(float(s[:-1]) * {"k": 1e3, "m": 1e6}[s[-1].lower()]) if s[-1].isalpha() else int(s)
               for s in a.sizes.split(",") if s]
    a.png_dir = os.path.splitext(os.path.abspath(a.out))[0] + "_png"
    return a


def log(msg):
    print(f"[scaling_bench {time.strftime('%H:%M:%S')}] {msg}", flush=True)


def use(scene, engine, highlights, lines):
    scene.render.engine = engine
    if engine == "EDGELIGHT":
        scene.edgelight.highlights = highlights
        scene.edgelight.use_lines = lines


def measure_viewport(scene, distance, frames, rounds):
    rv3d = vb.rendered_view(distance)
    scene.display.viewport_aa = 'OFF'  # Workbench: one sample per draw, like EdgeLight's
    start = rv3d.view_rotation.copy()
    best = {}
    for r in range(rounds):
        for label, engine, highlights, lines in VIEW_MODES:
            use(scene, engine, highlights, lines)
            vb.warm_up(start)
            best[label] = min(best.get(label, float("inf")), vb.draw_ms(True, frames, 1))
        log(f"  viewport round {r + 1}/{rounds}: " + ", ".join(f"{k} {v:.0f}" for k, v in best.items()) + " ms (best so far)")
    return best


def measure_render(scene, ob, name, rounds, png_dir, lineart):
    """Final render wall times in ms: {label: ms}, and notes. `lineart` False: Line Art skipped."""
    _, area, _ = vb.view3d()
    area.spaces.active.shading.type = 'SOLID'  # frees the viewport engine; no viewport work between renders
    r = scene.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = RES_X, RES_Y, 100
    r.image_settings.file_format = 'PNG'
    r.use_freestyle = False
    scene.edgelight.samples = 1
    scene.display.render_aa = 'OFF'
    cam = scene.camera
    lines_bench.frame_camera(cam, ob, scene)
    cam.location += ob.location  # frame_camera reads the mesh's local coordinates; the grid is only moved
    gp_ob = None
    modes = [m for m in RENDER_MODES if lineart or m[0] != "Line Art"]
    if lineart:
        # EdgeLight's crease angle and line width; screen-space thickness (in world space, the
        # default, strokes on a grid tens of units across are thinner than a pixel and vanish).
        el = scene.edgelight
        gp_ob, _ = lines_bench.add_lineart(scene, ob, crease_deg=math.degrees(el.crease_angle),
                                           thickness=round(el.line_silhouette.width), screen_space=True)
        gp_ob.hide_viewport = True  # not evaluated in the view layer's depsgraph, only in renders

    def once(mode, png=None):
        label, engine, highlights, lines = mode
        use(scene, engine, highlights, lines)
        if gp_ob is not None:
            gp_ob.hide_render = label != "Line Art"
        return lines_bench.render_once(png) * 1000.0

    best, notes = {}, {}
    for mode in modes:
        label = mode[0]
        ms = once(mode, os.path.join(png_dir, f"{name}_{label.strip('+ ').replace(' ', '_')}.png"))
        log(f"  render warm-up {label}: {ms:.0f} ms")
        if label == "Line Art" and ms > LINEART_LIMIT_S * 1000.0:
            best[label] = ms
            notes[label] = f"one render, warm-up included ({ms / 1000:.0f} s > {LINEART_LIMIT_S:.0f} s)"
    for i in range(rounds):
        for mode in modes:
            if mode[0] in notes:
                continue
            best[mode[0]] = min(best.get(mode[0], float("inf")), once(mode))
        log(f"  render round {i + 1}/{rounds}: " + ", ".join(f"{k} {v:.0f}" for k, v in best.items()) + " ms (best so far)")
    if gp_ob is not None:
        gp_ob.hide_render = True
    scene.render.engine = "EDGELIGHT"
    return best, notes


def slope(rows, key, fit_from=0):
    """The log-log slope of `key` over the rows of at least `fit_from` triangles (nominal), with
    the number of points when some of them have no time."""
    span = [(t, r.get(key)) for t, nominal, r in rows if nominal >= fit_from]
    pts = [(t, ms) for t, ms in span if ms]
    if len(pts) < 2:
        return "n/a"
    t, ms = np.array(pts, dtype=np.float64).T
    return f"{np.polyfit(np.log(t), np.log(ms), 1)[0]:.2f}" + ("" if len(pts) == len(span) else f" ({len(pts)} sizes)")


def fmt(ms, note=""):
    if ms is None:
        return "skipped"
    return (f"{ms:,.0f}" if ms >= 100 else f"{ms:.1f}") + ("*" if note else "")


def table(title, rows, keys, notes):
    head = "| triangles | " + " | ".join(keys) + " | highlights / surface | lines / surface |"
    out = [f"**{title}** (ms)", "", head, "|---:|" + "---:|" * (len(keys) + 2)]
    for tris, _, r in rows:
        cells = [fmt(r.get(k), notes.get((tris, k), "")) for k in keys]
        out.append(f"| {tris:,} | " + " | ".join(cells) + f" | {r['+ highlights'] / r['surface']:.2f} "
                   f"| {r['+ lines'] / r['surface']:.2f} |")
    for caption, lo in (("slope, all sizes", 0), (f"slope, {FIT_FROM // 1000}k..", FIT_FROM)):
        if sum(1 for _, n, _ in rows if n >= lo) >= 2:
            out.append(f"| {caption} | " + " | ".join(slope(rows, k, lo) for k in keys)
                       + f" | {slope_ratio(rows, '+ highlights', lo)} | {slope_ratio(rows, '+ lines', lo)} |")
    return out


def slope_ratio(rows, key, lo):
    """The slope of key / surface: how much faster than the surface the extra cost grows."""
    ratios = [(t, n, {"r": r[key] / r["surface"]}) for t, n, r in rows]
    return slope(ratios, "r", lo)


def write(args, region, view_rows, render_rows, notes, extra):
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    md = [f"Blender {bpy.app.version_string}, cube grids (every cube edge rounded); "
          f"{datetime.date.today().isoformat()}, load {load}.", "",
          f"Viewport: 3D view {region.width}x{region.height} px, Rendered shading, 1 viewport sample "
          "(Workbench: viewport_aa OFF); ms per orbit draw, best of R runs of F draws, the modes taking turns "
          "(F x R: " + ", ".join(f"{n // 1000}k {plan(n)[0]}x{plan(n)[1]}" for _, n, _ in view_rows) + ").", "",
          *table("Viewport", view_rows, [m[0] for m in VIEW_MODES], notes), "",
          f"Final render: bpy.ops.render.render wall time at {RES_X}x{RES_Y}, 1 sample (Workbench: render_aa OFF), "
          "best of the rounds after a warm-up render, the methods taking turns (rounds: "
          + ", ".join(f"{n // 1000}k {plan(n)[2]}" for _, n, _ in render_rows) + "). Line Art: "
          "a Grease Pencil Line Art modifier (contour + crease at EdgeLight's crease angle, screen-space strokes of "
          "EdgeLight's line width; bench/lines_bench.py) rendered with Workbench.", "",
          *table("Final render", render_rows, [m[0] for m in RENDER_MODES], notes), "",
          "Slopes: numpy polyfit of log(ms) against log(triangles) (1.0: linear); under the ratios, the slope "
          "of the ratio.", ""]
    for (tris, key), note in sorted(notes.items()):
        md.append(f"- {tris:,} triangles, {key}: {note}")
    md += [f"- {line}" for line in extra]
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.splitext(args.out)[0] + ".csv", "w") as f:
        f.write("triangles,where,mode,ms\n")
        for where, rows in (("viewport", view_rows), ("render", render_rows)):
            for tris, _, r in rows:
                for key, ms in r.items():
                    f.write(f"{tris},{where},{key},{'' if ms is None else f'{ms:.3f}'}\n")
    return "\n".join(md)


def steps(args):
    os.makedirs(args.png_dir, exist_ok=True)
    view_rows, render_rows, notes, extra = [], [], {}, []
    lineart = True
    for nominal in args.sizes:
        frames, view_rounds, render_rounds = plan(nominal)
        t0 = time.perf_counter()
        size = vb.grid_scene(nominal)
        scene = bpy.context.scene
        ob = bpy.data.objects["Grid"]
        tris = 2 * len(ob.data.polygons)
        log(f"{tris:,} triangles: scene built in {time.perf_counter() - t0:.1f} s")
        yield  # the UI draws the new file's 3D view
        scene.render.engine = "EDGELIGHT"
        t0 = time.perf_counter()
        view = measure_viewport(scene, size * 2.2, frames, view_rounds)
        view_rows.append((tris, nominal, view))
        log(f"{tris:,} viewport: {view} ({time.perf_counter() - t0:.0f} s)")
        yield
        t0 = time.perf_counter()
        render, render_notes = measure_render(scene, ob, f"{nominal // 1000}k", render_rounds, args.png_dir, lineart)
        if not lineart:
            render["Line Art"] = None
            notes[(tris, "Line Art")] = "skipped: a smaller scene's Line Art render took more than " \
                                        f"{LINEART_LIMIT_S:.0f} s"
        for key, note in render_notes.items():
            notes[(tris, key)] = note
        if render.get("Line Art") and render["Line Art"] > LINEART_LIMIT_S * 1000.0:
            lineart = False
        render_rows.append((tris, nominal, render))
        log(f"{tris:,} render: {render} ({time.perf_counter() - t0:.0f} s)")
        write(args, vb.view3d()[2], view_rows, render_rows, notes, extra)
        yield
    log("\n" + write(args, vb.view3d()[2], view_rows, render_rows, notes, extra))
    log(f"wrote {args.out}")


if __name__ == "__main__":  # Blender's --python runs the script as __main__
    vb.run(steps(parse_args()))
