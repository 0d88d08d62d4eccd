"""Temporal stability on a camera orbit: how much each edge's highlight and line change from one
frame to the next, against the same measure on true rounded geometry.

    blender -b --factory-startup --addons edgelight --python bench/temporal_stability.py -- [OUT.csv] [RADII]

The cube sample; its camera orbits the cube's vertical axis at its own distance and height,
FRAMES frames over 360 degrees. Per frame, EdgeLight renders (SAMPLES samples, Standard view):
  sharp   the cube with highlights and lines off (the surface alone)
  edge    highlights on: the edge signal of edge e is sum(L(edge) - L(sharp)) over the pixels
          within MASK_PX of e's projection (L: display luminance, sRGB curve, in [0, 1])
  bevel   the true geometry: circular fillets of the same radius (bench/fillets.py, 32
          segments), highlights off; its edge signal is sum(L(bevel) - L(sharp)) alike
  lines   lines on: line coverage of e = sum of the line buffer's alpha over the same pixels
  footprint  the number of those pixels: how much the edge's own image changes
Flicker of an edge between consecutive frames = |signal(t+1) - signal(t)|, in luminance x
pixels. Reported per method: the mean over edges and frame pairs, the 95th percentile, the max,
and "pops": an edge whose EdgeLight signal jumps by more than POP x the bevel's jump and by more
than POP_FLOOR of the edge's largest bevel signal, or whose line coverage appears or vanishes
(crosses 30% of its largest value) while its two faces keep their facing (no silhouette
forms or breaks there).
Radii: the fillet radius in scene units (default: the sample's material radius, and 0.05).
"""
import csv
import math
import os
import sys

import bpy
import numpy as np
from bpy_extras.object_utils import world_to_camera_view
from mathutils import Vector

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import fillets  # noqa: E402
import gt_scenes  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else os.path.join(ROOT, "out", "temporal_stability.csv")
RADII = [float(r) for r in ARGS[1].split(",")] if len(ARGS) > 1 else None
FRAMES = 24
RESOLUTION = (320, 240)
SAMPLES = 4
MASK_PX = 3.0
POP = 3.0
POP_FLOOR = 0.25


def addon():
    import edgelight
    return edgelight


def open_cube(radius):
    bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", "cube.blend"))
    s = gt_scenes.edgelight_scene(RESOLUTION, SAMPLES)
    if radius is not None:
        for mat in bpy.data.materials:
            mat.edgelight.radius = radius
    return s


def orbit(s, frame):
    """The camera at orbit angle frame x 360 / FRAMES about +Z, looking at the origin."""
    cam = s.camera
    start = Vector(ORBIT_START)
    a = 2.0 * math.pi * frame / FRAMES
    cam.location = (start.x * math.cos(a) - start.y * math.sin(a), start.x * math.sin(a) + start.y * math.cos(a), start.z)
    cam.rotation_euler = (-cam.location).to_track_quat('-Z', 'Y').to_euler()


def render(s):
    el = addon()
    el.host.engine.capture = True
    el.host.engine.last_render.clear()
    bpy.ops.render.render()
    rec = el.host.engine.last_render
    return np.array(rec["pixels"], np.float64), np.array(rec["lines"], np.float64)


def luminance(rgb):
    c = np.clip(rgb[..., :3], 0.0, 1.0)
    c = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)
    return c @ np.array([0.2126, 0.7152, 0.0722])


def edge_masks(s, edges, verts):
    """Per edge, the pixels within MASK_PX of its projected segment ((h, w) bools)."""
    w, h = RESOLUTION
    ys, xs = np.mgrid[0:h, 0:w] + 0.5
    masks = []
    for a, b in edges:
        pa, pb = (np.array(world_to_camera_view(s, s.camera, Vector(verts[i]))[:2]) * (w, h) for i in (a, b))
        d = pb - pa
        t = np.clip(((xs - pa[0]) * d[0] + (ys - pa[1]) * d[1]) / max(d @ d, 1e-9), 0.0, 1.0)
        dist = np.hypot(xs - pa[0] - t * d[0], ys - pa[1] - t * d[1])
        masks.append(dist <= MASK_PX)
    return masks


def facing(s, faces, verts):
    """Per face: True where it faces the camera."""
    eye = np.array(s.camera.location)
    return [float(np.dot(n, eye - verts[f[0]])) > 0.0 for f, n in faces]


def measure(radius):
    s = open_cube(radius)
    cube = next(ob for ob in s.objects if ob.type == 'MESH')
    me = cube.data
    mw = np.array(cube.matrix_world)
    verts = np.array([(mw @ np.r_[v.co[:], 1.0])[:3] for v in me.vertices])
    edges = [tuple(e.vertices) for e in me.edges]
    faces = [(list(p.vertices), np.array(mw[:3, :3] @ np.array(p.normal[:]))) for p in me.polygons]
    edge_faces = [[i for i, (f, _) in enumerate(faces) if a in f and b in f] for a, b in edges]
    radius = radius if radius is not None else cube.active_material.edgelight.radius
    rows = []
    for frame in range(FRAMES):
        per = {}
        for mode in ("sharp", "edge", "lines", "bevel"):
            s = open_cube(radius)
            orbit(s, frame)
            s.edgelight.highlights = mode == "edge"
            s.edgelight.use_lines = mode == "lines"
            if mode == "bevel":
                fillets.add_fillets(s, radius, 32)
            per[mode] = render(s)
        masks = edge_masks(s, edges, verts)
        front = facing(s, faces, verts)
        lum = {m: luminance(per[m][0]) for m in ("sharp", "edge", "bevel")}
        for e, mask in enumerate(masks):
            rows.append(dict(radius=radius, frame=frame, edge=e,
                             edge_signal=float((lum["edge"] - lum["sharp"])[mask].sum()),
                             bevel_signal=float((lum["bevel"] - lum["sharp"])[mask].sum()),
                             line_coverage=float(per["lines"][1][..., 3][mask].sum()),
                             footprint=int(mask.sum()),
                             silhouette=int(len(edge_faces[e]) == 2 and front[edge_faces[e][0]] != front[edge_faces[e][1]])))
        print(f"temporal_stability: radius {radius} frame {frame} done", flush=True)
    return rows


def summarize(rows):
    radius = rows[0]["radius"]
    by_edge = {}
    for r in rows:
        by_edge.setdefault(r["edge"], []).append(r)
    jumps = {"edge_signal": [], "bevel_signal": [], "line_coverage": [], "footprint": []}
    pops = []
    for e, seq in by_edge.items():
        seq.sort(key=lambda r: r["frame"])
        top_bevel = max(abs(r["bevel_signal"]) for r in seq) or 1.0
        top_line = max(r["line_coverage"] for r in seq) or 1.0
        for a, b in zip(seq, seq[1:] + seq[:1]):  # the orbit closes: frame 23 -> 0
            d = {k: abs(b[k] - a[k]) for k in jumps}
            for k in jumps:
                jumps[k].append(d[k])
            if d["edge_signal"] > POP * d["bevel_signal"] and d["edge_signal"] > POP_FLOOR * top_bevel:
                pops.append(f"highlight edge {e} frames {a['frame']}->{b['frame']}: {a['edge_signal']:.2f} -> "
                            f"{b['edge_signal']:.2f} (bevel {a['bevel_signal']:.2f} -> {b['bevel_signal']:.2f})")
            on_a, on_b = a["line_coverage"] > 0.3 * top_line, b["line_coverage"] > 0.3 * top_line
            if on_a != on_b and a["silhouette"] == b["silhouette"]:
                pops.append(f"line edge {e} frames {a['frame']}->{b['frame']}: coverage {a['line_coverage']:.1f} -> "
                            f"{b['line_coverage']:.1f}, silhouette {a['silhouette']} both")
    print(f"\nradius {radius}: flicker per edge and frame step (luminance x pixels; lines: alpha x pixels)")
    print("| measure | mean | 95th pct | max | mean / mean value |\n|---|---|---|---|---|")
    for k, label in (("edge_signal", "EdgeLight highlight"), ("bevel_signal", "bevel (32 segments)"),
                     ("line_coverage", "EdgeLight lines"), ("footprint", "edge's mask (pixels)")):
        v = np.array(jumps[k])
        level = np.mean([abs(r[k]) for r in rows]) or 1.0
        print(f"| {label} | {v.mean():.3f} | {np.percentile(v, 95):.3f} | {v.max():.3f} | {v.mean() / level:.3f} |")
    print(f"pops: {len(pops)}")
    for p in pops:
        print("  " + p)


def main():
    global ORBIT_START
    os.makedirs(os.path.dirname(os.path.abspath(OUT)), exist_ok=True)
    bpy.ops.wm.open_mainfile(filepath=os.path.join(ROOT, "blend_samples", "cube.blend"))
    ORBIT_START = tuple(bpy.context.scene.camera.location)
    all_rows = []
    for radius in RADII or [None, 0.05]:
        rows = measure(radius)
        summarize(rows)
        all_rows += rows
    with open(OUT, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(all_rows[0]))
        writer.writeheader()
        writer.writerows(all_rows)
    print(f"\nwrote {OUT}")


ORBIT_START = (0.0, 0.0, 0.0)
main()
