"""Silhouette lines on the rounded outline (docs/lines.md, "Silhouettes of rounded edges"). Where
the edge pass rounds a convex edge, the surface pass pulls the part's outline in to the fillet's
(rounded_outline.glsl), and the ink of a silhouette along that edge follows it there instead of
tracing the sharp edge past the part. Each end of such a segment moves to its fillet's outline
point: r from the fillet's axis along P = (Na x Nb) x V / |...|, turned towards the sharp edge,
which lies r C from the axis. That is a move of -r (C - P) in world space, judged with the
normals and the radius the strip is (zero where the end is no silhouette, as the strip's width
is), so the stroke's centre lies on the strip's inner side. No bpy: plain-Python tests import it."""
import numpy as np

from . import rounded_outline
from .radius_scale import radius_scale


def _keys(pairs, count):
    """One int64 key per unordered vertex pair."""
    pairs = np.sort(np.asarray(pairs, np.int64).reshape(-1, 2), axis=1)
    return pairs[:, 0] * max(int(count), 1) + pairs[:, 1]


def rounded_records(extract):
    """(sorted keys, records) of the mesh's convex rounded edges: the strip's own records
    (rounded_outline._edges, EDGE_TEXELS texels each), found once per extraction."""
    cached = getattr(extract, "_outline_records", None)
    if cached is None:
        recs, _, verts = rounded_outline._edges(extract)
        known = np.all(verts >= 0, axis=1)
        recs, verts = recs[known], verts[known]
        keys = _keys(verts, len(extract.edge_data.positions))
        order = np.argsort(keys)
        cached = extract._outline_records = (keys[order], recs[order])
    return cached


def records_of(extract, edge_pairs):
    """(N,) the index into rounded_records' records of each edge (by its vertex pair); -1 where
    it is not a convex rounded edge."""
    keys, _ = rounded_records(extract)
    if not len(keys) or not len(edge_pairs):
        return np.full(len(edge_pairs), -1, np.int64)
    k = _keys(edge_pairs, len(extract.edge_data.positions))
    at = np.minimum(np.searchsorted(keys, k), len(keys) - 1)
    return np.where(keys[at] == k, at, -1)


def outline_moves(recs, matrix, camera):
    """(2, N, 3) object-space moves of each record's two ends (its p0, p1) onto its fillet's
    outline as seen from `camera` (passes.camera.Camera, world space) through `matrix`; zero at
    an end where the edge is no silhouette."""
    out = np.zeros((2, len(recs), 3), np.float64)
    m = np.asarray(matrix, np.float64)
    lin = m[:3, :3]
    if not len(recs) or not abs(np.linalg.det(lin)) > 1e-30:
        return out
    inv = np.linalg.inv(lin)
    r = np.asarray(recs, np.float64)
    ma, mb, o0, o1, ta, tb = (r[:, k, :3] for k in range(6))
    radius = r[:, 0, 3] * radius_scale(m, ma, mb, o1 - o0)
    for end, (o, half) in enumerate(((o0, -0.5), (o1, 0.5))):
        w = o @ lin.T + m[:3, 3]
        # Normals into world space by the inverse transpose, as el_normal_matrix does.
        ea = _unit((ma + half * ta) @ inv)
        eb = _unit((mb + half * tb) @ inv)
        v = np.broadcast_to(-np.asarray(camera.view_dir, np.float64), w.shape) if camera.orthographic \
            else np.asarray(camera.eye, np.float64) - w
        p, c, sil = fillet_outline(ea, eb, _unit(v))
        move = -radius[:, None] * (c - p)
        out[end] = np.where(sil[:, None], move @ inv.T, 0.0)
    return out


def fillet_outline(na, nb, v):
    """(P, C, silhouette) of convex fillets of radius 1 between faces of unit normals na, nb
    (N, 3) seen along v (unit, towards the eye): P the unit direction from the axis to the
    outline point, turned towards the sharp edge, which lies C from the axis; silhouette where
    one face faces the eye and the other does not (elsewhere P = 0). The numpy copy of
    rounded_outline.glsl's el_fillet_outline, pinned to it by test_fillet_outline."""
    c = (na + nb) / np.maximum(1.0 + _dot(na, nb), 1e-3)[:, None]
    p = np.cross(np.cross(na, nb), v)
    length = np.linalg.norm(p, axis=1)
    sil = (_dot(na, v) * _dot(nb, v) < 0.0) & (length > 1e-6)
    p = p / np.maximum(length, 1e-30)[:, None]
    p *= np.where(_dot(p, c) < 0.0, -1.0, 1.0)[:, None]
    return np.where(sil[:, None], p, 0.0), c, sil


def _dot(a, b):
    return np.einsum("ij,ij->i", a, b)


def _unit(a):
    return a / np.maximum(np.linalg.norm(a, axis=1, keepdims=True), 1e-30)


def on_rounded_outline(extract, edge_pairs, p0, p1, matrix, camera):
    """The ends p0, p1 (object space) of silhouette segments along the mesh edges `edge_pairs`
    (vertex pairs, p0's vertex first), those on convex rounded edges moved onto their fillets'
    outline: new arrays, the others' ends unchanged."""
    at = records_of(extract, edge_pairs)
    hit = np.flatnonzero(at >= 0)
    if not len(hit):
        return p0, p1
    _, recs = rounded_records(extract)
    rec = recs[at[hit]]
    moves = outline_moves(rec, matrix, camera)
    p0, p1 = np.array(p0, np.float32), np.array(p1, np.float32)
    d = p1[hit] - p0[hit]
    # The record runs as the segment does: both take their ends from the mesh's edge array.
    p0[hit] += moves[0].astype(np.float32)
    p1[hit] += moves[1].astype(np.float32)
    clip = np.asarray(camera.projection, np.float64) @ np.asarray(camera.view, np.float64) @ np.asarray(matrix, np.float64)
    _join_corners(np.asarray(edge_pairs, np.int64)[hit], hit, d, p0, p1, clip)
    return p0, p1


def _join_corners(pairs, hit, d, p0, p1, clip):
    """Where two moved silhouette segments meet at a vertex (a box's corner seen from outside),
    each was moved square to its own edge, and their ends overshoot each other: both end at one
    point where their images cross, on the first one's line (so neither image tilts, and the
    SVG output's polylines still join there); along a smooth rim, where the two nearly continue
    each other, at the mean of their two ends. `clip`: object space -> clip space (4 x 4)."""
    verts = pairs.reshape(-1)                               # end k of segment i: 2 i + k
    order = np.argsort(verts, kind="stable")
    v = verts[order]
    first = np.flatnonzero((v[:-1] == v[1:]) & np.r_[True, v[1:-1] != v[:-2]] & np.r_[v[2:] != v[1:-1], True])
    if not len(first):
        return
    e1, e2 = order[first], order[first + 1]

    def point(e):
        i = hit[e // 2]
        return np.where((e % 2 == 0)[:, None], p0[i], p1[i]).astype(np.float64)

    x1, x2 = point(e1), point(e2)
    d1, d2 = d[e1 // 2].astype(np.float64), d[e2 // 2].astype(np.float64)
    m = np.asarray(clip, np.float64)
    # Each line's image as a homogeneous 2D line through its clip-space point and direction;
    # the images cross at their cross product.
    c1, f1 = _clip(x1, m), _clip(d1, m, 0.0)
    c2, f2 = _clip(x2, m), _clip(d2, m, 0.0)
    cross = np.cross(np.cross(c1, f1), np.cross(c2, f2))
    # On line 1 at the parameter whose clip point is proportional to the crossing.
    a, b = np.cross(c1, cross), np.cross(f1, cross)
    lam = -_dot(a, b) / np.maximum(_dot(b, b), 1e-300)
    joint = x1 + lam[:, None] * d1
    # Where the images nearly continue each other (or the crossing lies off beyond the ends),
    # the mean: no farther from the vertex than the two ends lie apart.
    sin2 = _dot(np.cross(d1, d2), np.cross(d1, d2)) / np.maximum(_dot(d1, d1) * _dot(d2, d2), 1e-300)
    gap = np.linalg.norm(x1 - x2, axis=1)
    near = (sin2 > 0.04) & np.isfinite(lam) & (np.linalg.norm(joint - x1, axis=1) <= 4.0 * gap) \
        & (np.linalg.norm(joint - x2, axis=1) <= 4.0 * gap)
    joint = np.where(near[:, None], joint, 0.5 * (x1 + x2)).astype(np.float32)
    for e in (e1, e2):
        for k, ends in ((0, p0), (1, p1)):
            sel = e % 2 == k
            ends[hit[e[sel] // 2]] = joint[sel]


def _clip(x, m, w=1.0):
    """(x, y, w) of points (w = 1) or directions (w = 0) in clip space."""
    return (np.c_[x, np.full(len(x), w)] @ m.T)[:, [0, 1, 3]]
