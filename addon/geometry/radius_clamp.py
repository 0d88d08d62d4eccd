"""The largest radius an edge's faces allow, as the Bevel modifier's Clamp Overlap: a fillet of
radius r between faces whose normals differ by alpha sets back r * tan(alpha / 2) from the edge
on each face, and two fillets across a face must not overlap, so the setback may be at most half
the face's width across the edge. A face is the smooth patch the edge's polygon belongs to: a
triangulated curved surface is one face to a fillet, which runs on across its facets. So the
width is the larger of the polygon's own (the farthest of its corners from the edge's line) and
the length of a walk straight across the patch from the edge's middle to the next edge that is
rounded, sharp or open. Past that the band stops meaning a fillet: it would run off its faces
(docs/highlight_math.md, "Radius clamp").
"""
from dataclasses import dataclass

import numpy as np

from ..bridge import native

# Pairs (edge, polygon corner) expanded at once: bounds the temporary arrays on dense meshes.
_CHUNK = 1 << 21
# Folds no larger than this are facets of one smooth patch: a fillet runs on across them.
SMOOTH_FOLD_DEG = 30.0
# Polygons a walk across a patch crosses at most; a walk that gets no farther stops there.
MAX_WALK_STEPS = 64


@dataclass
class Polygons:
    """What the widths and the band ends (band_ends.py) need of a mesh's polygons."""
    start: np.ndarray        # per polygon: first loop
    total: np.ndarray        # per polygon: loop count
    loop_vert: np.ndarray    # per loop: vertex
    tri_poly: np.ndarray     # per loop triangle: its polygon
    loop_edge: np.ndarray = None  # per loop: the edge from its vertex to the next loop's
    normal: np.ndarray = None     # per polygon: unit normal as the file winds it (zero: no area)


def widths(polys, positions, edges, faces):
    """(N, 2) width of each edge's faces across it; faces (N, 2) are triangle indices (-1: none,
    width 0). edges (N, 2) vertex indices."""
    out = np.zeros(faces.shape, np.float64)
    for side in range(2):
        has = np.flatnonzero(faces[:, side] >= 0)
        poly = polys.tri_poly[faces[has, side]]
        count = polys.total[poly]
        step = max(1, _CHUNK // max(int(count.max(initial=1)), 1))
        for lo in range(0, len(has), step):
            e, p, n = has[lo:lo + step], poly[lo:lo + step], count[lo:lo + step]
            pair = np.repeat(np.arange(len(e)), n)
            corner = np.arange(len(pair)) - np.repeat(np.cumsum(n) - n, n)
            v = positions[polys.loop_vert[polys.start[p][pair] + corner]].astype(np.float64)
            a = positions[edges[e, 0]].astype(np.float64)[pair]
            d = positions[edges[e, 1]].astype(np.float64)[pair] - a
            dist = np.linalg.norm(np.cross(d, v - a), axis=1) / np.maximum(np.linalg.norm(d, axis=1), 1e-30)
            w = np.zeros(len(e))
            np.maximum.at(w, pair, dist)
            out[e, side] = w
    return out


def _centroids(polys, positions, which):
    """Mean corner of polygons `which`."""
    n = polys.total[which]
    pair = np.repeat(np.arange(len(which)), n)
    corner = np.arange(len(pair)) - np.repeat(np.cumsum(n) - n, n)
    v = positions[polys.loop_vert[polys.start[which][pair] + corner]].astype(np.float64)
    out = np.zeros((len(which), 3))
    np.add.at(out, pair, v)
    return out / np.maximum(n, 1)[:, None]


def _into(polys, positions, poly, a, u):
    """Unit direction in polygon `poly`'s plane, square to the line through a along u (unit),
    pointing into the polygon (towards its centroid)."""
    nrm = polys.normal[poly].astype(np.float64)
    d = np.cross(nrm, u)
    d /= np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-30)
    inward = np.einsum("ij,ij->i", _centroids(polys, positions, poly) - a, d)
    return np.where((inward < 0.0)[:, None], -d, d)


def patch_walks(polys, positions, edges, edge_polys, stop, sel, start_poly, cap):
    """Per row: how far a walk goes from the middle of edge sel[i] straight across polygon
    start_poly[i] and on across the smooth patch (unfolding over each edge it crosses) until it
    crosses an edge marked in `stop` (E,) or the patch ends; at most cap[i]. edge_polys (E, 2):
    each edge's first two polygons (-1: none). Polygons without area end a walk where it is."""
    rows = len(sel)
    out = np.zeros(rows)
    if rows == 0:
        return out
    a0 = positions[edges[sel, 0]].astype(np.float64)
    u = positions[edges[sel, 1]].astype(np.float64) - a0
    u /= np.maximum(np.linalg.norm(u, axis=1, keepdims=True), 1e-30)
    x = a0 + 0.5 * (positions[edges[sel, 1]] - positions[edges[sel, 0]])
    live = np.flatnonzero(np.any(polys.normal[start_poly] != 0.0, axis=1))
    row, poly, came = live, start_poly[live].astype(np.int64), sel[live].astype(np.int64)
    x, d = x[live], _into(polys, positions, start_poly[live], a0[live], u[live])
    scale = float(np.ptp(positions, axis=0).max()) if len(positions) else 1.0
    for _ in range(MAX_WALK_STEPS):
        if not len(row):
            break
        # Where the walk leaves its polygon: the nearest side ahead other than the one it came in by.
        n = polys.total[poly]
        pair = np.repeat(np.arange(len(row)), n)
        corner = np.arange(len(pair)) - np.repeat(np.cumsum(n) - n, n)
        first = polys.start[poly][pair]
        loop = first + corner
        nxt = first + (corner + 1) % n[pair]
        a = positions[polys.loop_vert[loop]].astype(np.float64)
        w = positions[polys.loop_vert[nxt]].astype(np.float64) - a
        nrm = polys.normal[poly][pair].astype(np.float64)
        den = np.einsum("ij,ij->i", np.cross(d[pair], w), nrm)
        safe = np.where(np.abs(den) > 1e-30, den, 1.0)
        t = np.einsum("ij,ij->i", np.cross(a - x[pair], w), nrm) / safe
        s = np.einsum("ij,ij->i", np.cross(a - x[pair], d[pair]), nrm) / safe
        side = polys.loop_edge[loop]
        ok = ((np.abs(den) > 1e-12 * np.linalg.norm(w, axis=1)) & (t > 1e-9 * scale) & (s >= -1e-9) & (s <= 1.0 + 1e-9)
              & (side != came[pair]))
        t = np.where(ok, t, np.inf)
        best = np.full(len(row), np.inf)
        np.minimum.at(best, pair, t)
        hit = np.full(len(row), -1, np.int64)
        at = np.flatnonzero(ok & (t == best[pair]))
        hit[pair[at]] = at
        gone = hit >= 0
        out[row[gone]] += best[gone]
        g = np.where(gone, side[np.maximum(hit, 0)], -1)
        other = np.where(edge_polys[np.maximum(g, 0), 0] == poly, edge_polys[np.maximum(g, 0), 1],
                         edge_polys[np.maximum(g, 0), 0])
        on = gone & (out[row] < cap[row]) & ~stop[np.maximum(g, 0)] & (other >= 0) & (other != poly)
        on &= np.any(polys.normal[np.maximum(other, 0)] != 0.0, axis=1)
        keep = np.flatnonzero(on)
        if not len(keep):
            break
        h = hit[keep]
        # Where it leaves, kept a hair inside the side: through a vertex exactly (a fan's centre,
        # a row of apexes) the next polygon would be entered at its corner, heading out of it.
        x_exit = a[h] + np.clip(s[h], 1e-4, 1.0 - 1e-4)[:, None] * w[h]
        ga = a[h]
        gu = w[h] / np.maximum(np.linalg.norm(w[h], axis=1, keepdims=True), 1e-30)
        q = other[keep]
        along = np.einsum("ij,ij->i", d[keep], gu)
        # Unfolded over the side: the same angle to it, now in the next polygon's plane.
        m = _into(polys, positions, q, ga, gu)
        d = along[:, None] * gu + np.sqrt(np.maximum(1.0 - along * along, 0.0))[:, None] * m
        row, poly, came, x = row[keep], q, g[keep], x_exit
    return np.minimum(out, cap)


def width_bounds(polys, positions, edges, edge_polys):
    """(N, 2) a lower bound of widths() for edges (N, 2) whose polygons are edge_polys (N, 2)
    (-1: none, bound 0): the farthest from the edge's line of three of the polygon's corners
    (the first, and a third and two thirds of the way round), found without expanding every
    corner (the library's el_width_bounds). An edge whose fillets need no more than this is not
    clamped."""
    if not len(edges):
        return np.zeros((0, 2))
    return native.width_bounds(polys, positions, edges, edge_polys)


def setback(angle_deg):
    """How far a fillet of unit radius between faces folded by angle_deg meets each face from the
    edge: tan(alpha / 2), capped short of a full fold."""
    half = np.radians(np.asarray(angle_deg, np.float64)) / 2.0
    return np.tan(np.clip(half, 0.0, np.radians(89.9)))


def across_patches(polys, positions, edges, edge_polys, stop, sel, face_widths, need):
    """face_widths (N, 2) of edges `sel` (widths()), widened where a polygon is narrower than
    the need (N,) of its edge's fillet (twice its setback) to the walk across its smooth patch
    (patch_walks), which need not go farther than that."""
    out = np.array(face_widths, np.float64)
    for side in range(2):
        short = np.flatnonzero(out[:, side] < need)
        poly = edge_polys[sel[short], side]
        short, poly = short[poly >= 0], poly[poly >= 0]
        walk = patch_walks(polys, positions, edges, edge_polys, stop, sel[short], poly, need[short])
        out[short, side] = np.maximum(out[short, side], walk)
    return out


def max_radius(face_widths, angle_deg):
    """Per edge, the largest radius its faces allow (inf where the faces are nearly coplanar)."""
    step = setback(angle_deg)
    narrow = np.min(face_widths, axis=1)
    return np.where(step > 1e-9, 0.5 * narrow / np.maximum(step, 1e-9), np.inf)
