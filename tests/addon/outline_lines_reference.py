"""The numpy copy of silhouettes on the rounded outline that the add-on ran until the library
took it over (native/src/outline_lines.cpp, el_outline_lines): the independent reference the
library is held to (test_outline_lines.py), itself pinned by closed forms there. Not loaded by
the add-on."""
import dataclasses

import numpy as np

from addon_modules import addon_module

rounded_outline = addon_module("geometry.rounded_outline")
radius_scale = addon_module("geometry.radius_scale").radius_scale


def ball_scale(m, m1, m2, m3):
    """Per corner patch, how its ball's radius scales under m (lighting.glsl, el_ball_scale: the
    mean of its three edges' scales, each between two of its sectors' normals)."""
    return (radius_scale(m, m1, m2, np.cross(m1, m2)) + radius_scale(m, m2, m3, np.cross(m2, m3))
            + radius_scale(m, m3, m1, np.cross(m3, m1))) / 3.0

# A corner's arc: only where the two lines' crossing lies farther than this many pixels
# outside the ball's circle, and then in chords that stay this close to the circle.
ARC_TOLERANCE_PX = 0.25
ARC_MAX_PIECES = 8


def _keys(pairs, count):
    """One int64 key per unordered vertex pair."""
    pairs = np.sort(np.asarray(pairs, np.int64).reshape(-1, 2), axis=1)
    return pairs[:, 0] * max(int(count), 1) + pairs[:, 1]


def rounded_records(extract):
    """(sorted keys, records) of the mesh's convex rounded edges: the strip's own records
    (rounded_outline._edges, EDGE_TEXELS texels each), found once per extraction."""
    def compute(extract):
        recs, _, verts = rounded_outline._edges(extract)
        known = np.all(verts >= 0, axis=1)
        recs, verts = recs[known], verts[known]
        keys = _keys(verts, len(extract.edge_data.positions))
        order = np.argsort(keys)
        return keys[order], recs[order]
    return rounded_outline.from_edges(extract, "outline lines", compute)


def corner_records(extract):
    """(sorted vertices, records) of the mesh's convex corner patches (rounded_outline._corners:
    ball centre and radius, vertex, three sectors' normals), found once per extraction."""
    def compute(extract):
        recs, verts = rounded_outline._corners(extract)
        order = np.argsort(verts, kind="stable")
        return np.asarray(verts, np.int64)[order], recs[order]
    return rounded_outline.from_edges(extract, "outline corners", compute)


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
    an end where the edge is no silhouette, and where a concave fillet meets it (the record's
    cut there): that fillet's end fills the corner, and the outline runs out round it, past the
    sharp edge's line (rounded_outline.glsl's el_strip_part)."""
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
        out[end] = np.where((sil & (r[:, 2 + end, 3] == 0.0))[:, None], move @ inv.T, 0.0)
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


def on_rounded_outline(extract, edge_pairs, seg, matrix, camera):
    """`seg` (lines.LineSegments, object space) of silhouettes along the mesh edges `edge_pairs`
    (vertex pairs, p0's vertex first), with those on convex rounded edges moved onto their
    fillets' outline, their corners joined (round a corner patch's ball, by an arc of its
    circle appended as segments of their own), and an unmoved silhouette they run on into
    ending at the fillet's foot, joined to them there: a new LineSegments."""
    at = records_of(extract, edge_pairs)
    hit = np.flatnonzero(at >= 0)
    if not len(hit):
        return seg
    _, recs = rounded_records(extract)
    rec = recs[at[hit]]
    moves = outline_moves(rec, matrix, camera)
    p0, p1 = np.array(seg.p0, np.float32), np.array(seg.p1, np.float32)
    d = p1[hit] - p0[hit]
    # The record runs as the segment does: both take their ends from the mesh's edge array.
    p0[hit] += moves[0].astype(np.float32)
    p1[hit] += moves[1].astype(np.float32)
    pairs = np.asarray(edge_pairs, np.int64)
    clip = np.asarray(camera.projection, np.float64) @ np.asarray(camera.view, np.float64) @ np.asarray(matrix, np.float64)
    e1, e2 = _two_ends(pairs[hit])  # end k of moved segment j: 2 j + k
    arcs = _corner_arcs(extract, pairs[hit], rec, e1, e2, matrix, camera)
    round_ = np.zeros(len(e1), bool) if arcs is None else arcs[0]
    _join_corners(e1[~round_], e2[~round_], hit, d, p0, p1, clip)
    out = dataclasses.replace(seg, p0=p0, p1=p1)
    if arcs is not None:
        out = _with_arcs(out, hit, e1[round_], e2[round_], *arcs[1:])
    moved = np.zeros((len(pairs), 2), bool)
    moved[hit] = np.any(moves != 0.0, axis=2).T
    setback = np.zeros(len(pairs))
    na, nb = _unit(rec[:, 0, :3].astype(np.float64)), _unit(rec[:, 1, :3].astype(np.float64))
    cos_fold = np.clip(_dot(na, nb), -0.999, 1.0)
    setback[hit] = rec[:, 0, 3] * np.sqrt((1.0 - cos_fold) / (1.0 + cos_fold))  # r tan(a / 2), object space
    return _to_the_foot(out, pairs, moved.reshape(-1), setback)


def _to_the_foot(seg, pairs, moved, setback):
    """Where a silhouette moved onto its fillet's outline runs on into one that is not moved (a
    cylinder's rounded rim into its side), the fillet's outline runs along the unmoved one's
    line to the fillet's foot, its setback from the vertex, and from there into the moved end.
    So the unmoved segment ends at the foot, along its own line (on its own faces: tilted
    instead, a long side silhouette between thin facets left them and was hidden), and a
    segment from the foot to the moved end, seen with the moved one's faces, is appended in the
    unmoved one's chain. `moved`: per end (2 i + k) of the first len(pairs) segments."""
    if not len(pairs):
        return seg
    e1, e2 = _two_ends(pairs)
    one = moved[e1] != moved[e2]
    if not one.any():
        return seg
    r_end, s_end = np.where(moved[e1], e1, e2)[one], np.where(moved[e1], e2, e1)[one]
    i_r, k_r, i_s, k_s = r_end // 2, r_end % 2, s_end // 2, s_end % 2
    p0, p1 = seg.p0, seg.p1
    pick = lambda i, k: np.where((k == 0)[:, None], p0[i], p1[i]).astype(np.float64)  # noqa: E731
    vert, far, tip = pick(i_s, k_s), pick(i_s, 1 - k_s), pick(i_r, k_r)
    length = np.linalg.norm(far - vert, axis=1)
    foot = vert + (far - vert) * (np.minimum(setback[i_r], 0.5 * length) / np.maximum(length, 1e-30))[:, None]
    for end, out in ((0, p0), (1, p1)):
        sel = k_s == end
        out[i_s[sel]] = foot[sel].astype(np.float32)
    links = seg.chain_links
    # Along the unmoved one's chain: after it where the chain arrives at the vertex, else before.
    if links is not None:
        s_at = np.where(k_s == 0, links["s0"][i_s], links["s1"][i_s])
        arrives = np.where(k_s == 0, links["s1"][i_s], links["s0"][i_s]) < s_at
    else:
        arrives = np.ones(len(i_s), bool)
    a = np.where(arrives[:, None], foot, tip).astype(np.float32)
    b = np.where(arrives[:, None], tip, foot).astype(np.float32)
    taper = np.take_along_axis(seg.taper[i_s], k_s[:, None], 1)[:, 0]
    return _appended(seg, a, b, i_r, taper, i_s, s_at if links is not None else None)


def _appended(seg, a, b, like, taper, chain_of, s):
    """`seg` with segments a -> b appended (object space), each seen with the faces and normals
    of segment `like`, its taper `taper` at both ends, and in the chain of segment `chain_of`
    at arc length `s` at both ends (so that it sorts between the two it joins, and continues
    both)."""
    new = dict(p0=np.concatenate([seg.p0, a]), p1=np.concatenate([seg.p1, b]),
               n1=np.concatenate([seg.n1, seg.n1[like]]), n2=np.concatenate([seg.n2, seg.n2[like]]),
               taper=np.concatenate([seg.taper, np.repeat(taper[:, None], 2, axis=1).astype(seg.taper.dtype)]))
    if seg.faces is not None:
        new["faces"] = np.concatenate([seg.faces, seg.faces[like]])
    if seg.chain_links is not None:
        extra = seg.chain_links[chain_of].copy()
        extra["s0"] = extra["s1"] = s
        new["chain_links"] = np.concatenate([seg.chain_links, extra])
    return dataclasses.replace(seg, **new)


def _two_ends(pairs):
    """(e1, e2): the segment ends (2 i + k: end k of segment i) at the vertices where exactly
    two ends of `pairs` meet, in pairs."""
    verts = pairs.reshape(-1)
    order = np.argsort(verts, kind="stable")
    v = verts[order]
    first = np.flatnonzero((v[:-1] == v[1:]) & np.r_[True, v[1:-1] != v[:-2]] & np.r_[v[2:] != v[1:-1], True])
    return order[first], order[first + 1]


def _join_corners(e1, e2, hit, d, p0, p1, clip):
    """Where two moved silhouette segments meet at a vertex (ends e1, e2: end k of moved segment
    j is 2 j + k) and no ball rounds it, each was moved square to its own edge, and their ends
    overshoot each other: both end at one point where their images cross, on the first one's
    line (so neither image tilts, and the SVG output's polylines still join there); along a
    smooth rim, where the two nearly continue each other, at the mean of their two ends.
    `clip`: object space -> clip space (4 x 4)."""
    if not len(e1):
        return

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


def _corner_arcs(extract, pairs, rec, e1, e2, matrix, camera):
    """Where two moved segments meet at a vertex with a corner patch, the fillets' outline there
    is the patch ball's circle (docs/lines.md, "Corners"): each segment ends where its fillet
    meets the ball, at B + rb P (B the ball's centre, rb its radius, P the segment's outline
    direction, seen from B), and an arc of the circle joins the two. None where no pair is
    rounded; else (per pair: rounded; for the rounded ones, object space: the two ends T1, T2,
    the arc's points (rounded, ARC_MAX_PIECES + 1, 3), its pieces)."""
    cverts, crecs = corner_records(extract)
    m = np.asarray(matrix, np.float64)
    lin = m[:3, :3]
    if not len(cverts) or not len(e1) or not abs(np.linalg.det(lin)) > 1e-30:
        return None
    vert = pairs.reshape(-1)[e1]
    at = np.minimum(np.searchsorted(cverts, vert), len(cverts) - 1)
    idx = np.flatnonzero(cverts[at] == vert)
    # The circle's image at most: the ball's radius under the transform's largest stretch, seen
    # at its centre's distance. Only pairs whose circle may reach a pixel go on.
    world_clip = np.asarray(camera.projection, np.float64) @ np.asarray(camera.view, np.float64)
    right = _unit(np.asarray(camera.view, np.float64)[None, 0, :3])[0]  # a scaled camera's too
    size = np.array([camera.width, camera.height], np.float64) * 0.5

    def radius_px(centre, r):
        wc = np.c_[centre, np.ones(len(centre))] @ world_clip.T
        wt = np.c_[centre + r[:, None] * right, np.ones(len(centre))] @ world_clip.T
        with np.errstate(divide="ignore", invalid="ignore"):
            px = np.linalg.norm((wt[:, :2] / wt[:, 3:4] - wc[:, :2] / wc[:, 3:4]) * size, axis=1)
        return np.where((wc[:, 3] > 0.0) & (wt[:, 3] > 0.0) & np.isfinite(px), px, 0.0)

    ball = crecs[at[idx]].astype(np.float64)
    centre = ball[:, 0, :3] @ lin.T + m[:3, 3]
    idx, ball, centre = (a[radius_px(centre, ball[:, 0, 3] * np.linalg.norm(lin, 2)) >= ARC_TOLERANCE_PX]
                         for a in (idx, ball, centre))
    if not len(idx):
        return None
    inv = np.linalg.inv(lin)
    rb = ball[:, 0, 3] * ball_scale(m, ball[:, 2, :3], ball[:, 3, :3], ball[:, 4, :3])
    v = np.broadcast_to(-np.asarray(camera.view_dir, np.float64), centre.shape) if camera.orthographic \
        else np.asarray(camera.eye, np.float64) - centre
    v = _unit(v)
    outs = []
    for e in (e1[idx], e2[idx]):
        r = rec[e // 2].astype(np.float64)
        half = np.where(e % 2 == 0, -0.5, 0.5)[:, None]
        ea = _unit((r[:, 0, :3] + half * r[:, 4, :3]) @ inv)
        eb = _unit((r[:, 1, :3] + half * r[:, 5, :3]) @ inv)
        outs.append(fillet_outline(ea, eb, v))
    (q1, _, s1), (q2, _, s2) = outs
    # The outline turns by the arc's angle there; the lines' crossing lies R (1 / cos(angle / 2)
    # - 1) outside a circle of R pixels. An arc where that is past the tolerance, in pieces whose
    # chords stay within it of the circle.
    px = radius_px(centre, rb)
    angle = np.arccos(np.clip(_dot(q1, q2), -1.0, 1.0))
    step = 2.0 * np.arccos(np.clip(1.0 - ARC_TOLERANCE_PX / np.maximum(px, 1e-9), -1.0, 1.0))
    pieces = np.clip(np.ceil(angle / np.maximum(step, 1e-9)), 1, ARC_MAX_PIECES).astype(np.int64)
    overshoot = px * (1.0 / np.maximum(np.cos(0.5 * angle), 1e-9) - 1.0)
    ok = s1 & s2 & (overshoot > ARC_TOLERANCE_PX) & (angle < np.radians(179.0))
    if not ok.any():
        return None
    idx, centre, rb, q1, q2, angle, pieces = (a[ok] for a in (idx, centre, rb, q1, q2, angle, pieces))
    t = np.arange(ARC_MAX_PIECES + 1)[None, :] / pieces[:, None]
    sin_a = np.maximum(np.sin(angle), 1e-9)[:, None]
    w1 = np.where(angle[:, None] > 1e-6, np.sin((1.0 - t) * angle[:, None]) / sin_a, 1.0 - t)
    w2 = np.where(angle[:, None] > 1e-6, np.sin(t * angle[:, None]) / sin_a, t)
    arc = centre[:, None, :] + rb[:, None, None] * (w1[..., None] * q1[:, None, :] + w2[..., None] * q2[:, None, :])
    # Into object space: the ends move there, and the arc's segments are the object's.
    to_obj = lambda x: (x - m[:3, 3]) @ inv.T  # noqa: E731
    rounded = np.zeros(len(e1), bool)
    rounded[idx] = True
    return (rounded, to_obj(centre + rb[:, None] * q1), to_obj(centre + rb[:, None] * q2),
            to_obj(arc.reshape(-1, 3)).reshape(arc.shape), pieces)


def _with_arcs(seg, hit, e1, e2, t1, t2, arc, pieces):
    """`seg` with each rounded corner's two ends (e1, e2 of the moved segments `hit`) at its
    ball's circle (t1, t2, object space) and its arc (`arc`, `pieces` of it) appended, piece by
    piece, in the chain of the segment it continues (chain order is by arc length: the arc
    takes the corner's arc length at both its ends, so it sorts between the two and continues
    both)."""
    p0, p1 = seg.p0, seg.p1
    i1, k1, i2, k2 = hit[e1 // 2], e1 % 2, hit[e2 // 2], e2 % 2
    for i, k, t in ((i1, k1, t1), (i2, k2, t2)):
        for end, out in ((0, p0), (1, p1)):
            sel = k == end
            out[i[sel]] = t[sel].astype(np.float32)
    links = seg.chain_links
    # Which way each arc runs, and in whose chain. Where segment 1's chain arrives at the corner
    # (the corner at its higher arc length), the arc follows it, from T1 to T2; else where
    # segment 2's does, the arc follows that, from T2 to T1; else (both leave the corner) the
    # arc comes before segment 1 in its chain, from T2 to T1.
    if links is not None:
        s_at = lambda i, k: np.where(k == 0, links["s0"][i], links["s1"][i])  # noqa: E731
        s_far = lambda i, k: np.where(k == 0, links["s1"][i], links["s0"][i])  # noqa: E731
        arrives1 = s_far(i1, k1) < s_at(i1, k1)
        arrives2 = s_far(i2, k2) < s_at(i2, k2)
        forward = arrives1
        by_2 = ~arrives1 & arrives2
        owner, owner_k = np.where(by_2, i2, i1), np.where(by_2, k2, k1)
        s_corner = s_at(owner, owner_k)
    else:
        forward = np.ones(len(i1), bool)
        owner, owner_k = i1, k1
    rows = np.repeat(np.arange(len(i1)), pieces)
    q = np.arange(len(rows)) - np.repeat(np.cumsum(pieces) - pieces, pieces)  # piece along its run
    fwd, n = forward[rows], pieces[rows]
    a = arc[rows, np.where(fwd, q, n - q)].astype(np.float32)
    b = arc[rows, np.where(fwd, q + 1, n - q - 1)].astype(np.float32)
    # Each piece sees with the faces of the side it is nearer.
    first, last = np.where(fwd, i1[rows], i2[rows]), np.where(fwd, i2[rows], i1[rows])
    src = np.where(q < (n + 1) // 2, first, last)
    taper_at = np.take_along_axis(seg.taper[owner], owner_k[:, None], 1)[:, 0]
    return _appended(seg, a, b, src, taper_at[rows], owner[rows],
                     s_corner[rows] if links is not None else None)


def _clip(x, m, w=1.0):
    """(x, y, w) of points (w = 1) or directions (w = 0) in clip space."""
    return (np.c_[x, np.full(len(x), w)] @ m.T)[:, [0, 1, 3]]
