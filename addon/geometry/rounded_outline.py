"""Where a rounded silhouette pulls the part's outline in (docs/highlight_math.md, "The fillet's
outline"): what the surface pass needs to leave out the strip between a sharp silhouette edge and
its fillet's outline (shaders/rounded_outline.glsl). The mesh's convex rounded edges, and per
surface triangle up to EDGES_PER_TRIANGLE of them whose strip may cross it: its own sides', then
the nearest of those whose strip reaches into its patch (a quad's other half at the edge's end,
the thin facets of a triangulated face along it). No bpy: plain-Python tests import it."""
import numpy as np

from ..bridge import native, shader_specs

# The texture layout: shaders/outline_layout.json (the surface program's EL_OUTLINE_* defines; the
# edge and corner records are also what the library's el_outline_lines reads).
_LAYOUT = shader_specs.load("outline_layout.json")["defines"]
# Per edge: (N1, radius), (N2, 0), (p0, cut at p0), (p1, cut at p1), (turn of N1, concave edge
# at p0), (turn of N2, concave edge at p1), object space, the normals as the edge pass shades
# with (edge_choice.EdgeSet: at t along the edge a side's normal is normalize(N + (t - 1/2)
# turn)); a cut is the fraction of the edge from that end along which a concave fillet meeting it
# there fills the corner, signed by the face its end arc lies in (_concave_cuts); 1 where a
# concave edge meets that end, else 0 (_concave_ends).
EDGE_TEXELS = _LAYOUT["EL_OUTLINE_EDGE_TEXELS"]
EDGES_PER_ROW = _LAYOUT["EL_OUTLINE_EDGES_PER_ROW"]
# Per corner patch (three convex rounded edges meeting): (ball centre, radius), (vertex, 0), and
# its three sectors' normals (AB, BC, CA; corner_patches.Corners).
CORNER_TEXELS = _LAYOUT["EL_OUTLINE_CORNER_TEXELS"]
CORNERS_PER_ROW = _LAYOUT["EL_OUTLINE_CORNERS_PER_ROW"]
# Per triangle: the numbers of up to EDGES_PER_TRIANGLE edges, four to a texel, then of up to
# CORNERS_PER_TRIANGLE corners, each plus one (0: none). A sliver of an n-gon's triangulation (a
# cylinder's 32-sided cap) lies in the reach of five to eight rims' strips; a quad's half lies in
# the zones of all four of its corners. The first VERTEX_EDGES are judged in the vertex shader
# (varyings), the rest per pixel (EL_OUTLINE_MORE).
EDGES_PER_TRIANGLE = _LAYOUT["EL_OUTLINE_EDGES_PER_TRIANGLE"]
VERTEX_EDGES = _LAYOUT["EL_OUTLINE_VERTEX_EDGES"]
CORNERS_PER_TRIANGLE = _LAYOUT["EL_OUTLINE_CORNERS_PER_TRIANGLE"]
TRIANGLE_TEXELS = _LAYOUT["EL_OUTLINE_TRIANGLE_TEXELS"]
TRIANGLES_PER_ROW = _LAYOUT["EL_OUTLINE_TRIANGLES_PER_ROW"]
# A concave edge folded by more than this (degrees) at a strip's end: the silhouette may run on
# into it (_concave_ends); a triangulated surface's flatter folds are its curvature's noise.
CONCAVE_END_DEG = 1.0


def from_edges(extract, name, compute):
    """compute(extract), kept in the extraction's `derived` (scene_sync.MeshExtract) for as long
    as its chosen edges are these; computed each time for an extraction without one."""
    derived = getattr(extract, "derived", None)
    if derived is None:
        return compute(extract)
    memo = derived.get(name)
    if memo is None or memo[0] is not extract.edges:
        memo = derived[name] = (extract.edges, compute(extract))
    return memo[1]


def edge_records(extract):
    """_edges(extract), made once per extraction's chosen edges (the surface pass's textures and
    the ink's el_outline read the same records)."""
    return from_edges(extract, "outline edges", _edges)


def corner_records(extract):
    """_corners(extract), made once per extraction's chosen edges."""
    return from_edges(extract, "outline corners", _corners)


def layout_defines():
    """The texture layout (shaders/outline_layout.json), as the surface program's defines
    (shaders/rounded_outline.glsl)."""
    return dict(_LAYOUT)


def convex(e):
    """(N,) bool: the edges of EdgeSet `e` that are convex (the edge pass's edge_fold > 0: N1's
    face runs p0 -> p1, so the surface turns away from its outside where N1 x N2 points along it)."""
    return np.einsum("ij,ij->i", np.cross(e.n1, e.n2), e.p1 - e.p0) >= 0.0


def _edges(extract):
    """(M, 4, 4) float32 records of the convex rounded edges, (M, 2) their faces' batch
    positions (surface id - 1) and (M, 2) their vertices (-1: not known)."""
    recs, faces, verts = [], [], []
    for e in extract.edges.values():
        keep = np.flatnonzero(convex(e) & (e.radius > 0.0)) if e.faces is not None else []
        if not len(keep):
            continue
        r = np.zeros((len(keep), EDGE_TEXELS, 4), np.float32)
        r[:, 0, :3], r[:, 0, 3] = e.n1[keep], e.radius[keep]
        r[:, 1, :3], r[:, 2, :3], r[:, 3, :3] = e.n2[keep], e.p0[keep], e.p1[keep]
        if e.turn is not None:
            r[:, 4, :3], r[:, 5, :3] = e.turn[keep, :3], e.turn[keep, 3:]
        recs.append(r)
        faces.append(np.asarray(e.faces[keep], np.int64) - 1)
        verts.append(np.asarray(e.verts, np.int64)[keep] if e.verts is not None else np.full((len(keep), 2), -1))
    if not recs:
        return np.zeros((0, EDGE_TEXELS, 4), np.float32), np.zeros((0, 2), np.int64), np.zeros((0, 2), np.int64)
    recs, verts = np.concatenate(recs), np.concatenate(verts)
    recs[:, 2, 3], recs[:, 3, 3] = _concave_cuts(extract, recs, verts).T
    recs[:, 4, 3], recs[:, 5, 3] = _concave_ends(extract, verts).T
    return recs, np.concatenate(faces), verts


def _concave_ends(extract, verts):
    """(M, 2) float32: 1 at the ends (`verts`) where a concave edge of the mesh meets, folded by
    more than CONCAVE_END_DEG, rounded or not (a bore's wall); else 0. The silhouette may run on
    there into the concave edge's, behind the face, and the strip's end takes no half disc of its
    own (rounded_outline.glsl's el_strip_part)."""
    from ..bridge import native
    d = extract.edge_data
    out = np.zeros(verts.shape, np.float32)
    if d is None or d.flags is None or not np.all(verts >= 0):
        return out
    concave = ((np.asarray(d.flags) & native.EDGE_CONCAVE) != 0) & (np.asarray(d.angles) > CONCAVE_END_DEG)
    at = np.unique(np.asarray(d.edges, np.int64)[concave].reshape(-1))
    out[np.isin(verts, at)] = 1.0
    return out


def _concave_cuts(extract, recs, verts):
    """(M, 2) float32: per convex rounded edge (records `recs`, vertices `verts`) and end, the
    fraction of the edge from that end along which a concave fillet meeting it there fills the
    corner (docs/highlight_math.md, "The fillet's outline"). A concave rounded edge c at the
    end's vertex that shares a face with the edge (one normal within SMOOTH_FOLD_DEG of one of
    the edge's) has its fillet on that face up to its setback s = r tan(a/2) from c; the convex
    fillet along the edge runs into it s / sin(theta) from the vertex, theta the angle between
    the two edges. Up to there the concave fillet fills the corner, and its end arc lies in the
    edge's other face, out over the line: the strip narrows by that much (rounded_outline.glsl's
    el_strip_part), and the fillets' outline runs from the convex fillet's round the concave
    one's end (the inside corner of a step's L-shaped end face). Signed by the face the arc
    lies in: + N2's (the concave fillet on N1's face), - N1's. 0 where none meets; 1 at most."""
    from .radius_clamp import SMOOTH_FOLD_DEG
    cuts = np.zeros((len(recs), 2), np.float32)
    cv, cp, cn, cs = [], [], [], []
    for e in extract.edges.values():
        if e.verts is None:
            continue
        keep = np.flatnonzero(~convex(e) & (e.radius > 0.0))
        if not len(keep):
            continue
        n1, n2 = e.n1[keep].astype(np.float64), e.n2[keep].astype(np.float64)
        cos_fold = np.einsum("ij,ij->i", n1, n2) / np.maximum(np.linalg.norm(n1, axis=1) * np.linalg.norm(n2, axis=1), 1e-30)
        cos_half = np.sqrt(np.clip(0.5 * (1.0 + cos_fold), 1e-6, 1.0))
        cv.append(np.asarray(e.verts, np.int64)[keep])
        cp.append(np.stack([e.p0[keep], e.p1[keep]], axis=1).astype(np.float64))
        cn.append(np.stack([n1, n2], axis=1))
        cs.append(e.radius[keep] * np.sqrt(1.0 - cos_half * cos_half) / cos_half)
    if not cv or not np.all(verts >= 0):
        return cuts
    cv, cp, cn, cs = np.concatenate(cv), np.concatenate(cp), np.concatenate(cn), np.concatenate(cs)
    # The concave edges' ends by vertex: (vertex, concave edge, which end).
    ends_v = cv.reshape(-1)
    by_v = np.argsort(ends_v, kind="stable")
    sorted_v = ends_v[by_v]
    ev = verts.reshape(-1)  # the convex edges' ends, (M * 2,)
    lo, hi = np.searchsorted(sorted_v, ev, "left"), np.searchsorted(sorted_v, ev, "right")
    count = hi - lo
    if not count.any():
        return cuts
    at = np.repeat(np.arange(len(ev)), count)                       # convex end
    k = by_v[np.repeat(lo, count) + (np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count))]
    j, jend = k // 2, k % 2                                         # concave edge, its end at the vertex
    i, iend = at // 2, at % 2
    p = recs[:, 2:4, :3].astype(np.float64)
    here, there = p[i, iend], p[i, 1 - iend]
    u = there - here
    w = cp[j, 1 - jend] - cp[j, jend]
    length = np.linalg.norm(u, axis=1)
    sin_t = np.linalg.norm(np.cross(u, w), axis=1) / np.maximum(length * np.linalg.norm(w, axis=1), 1e-30)
    en = recs[i, 0:2, :3].astype(np.float64)
    unit = lambda n: n / np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-30)  # noqa: E731
    same = (np.einsum("nak,nbk->nab", unit(en), unit(cn[j])) > np.cos(np.radians(SMOOTH_FOLD_DEG))).any(axis=2)
    cut = np.where(same.any(axis=1), np.minimum(cs[j] / np.maximum(sin_t, 1e-6) / np.maximum(length, 1e-30), 1.0), 0.0)
    # The longest cut at each end, signed by the face its arc lies in (+: N2's, the fillet on N1's).
    best = np.full(len(ev), -1.0)
    np.maximum.at(best, at, cut)
    top = (cut == best[at]) & (cut > 0.0)
    cuts.reshape(-1)[at[top]] = np.where(same[top, 0], cut[top], -cut[top]).astype(np.float32)
    return cuts


def _segment_distance(points, p0, p1):
    """(N, K) distance of points (N, K, 3) from the segments p0 -> p1 (N, 3)."""
    u = p1 - p0
    uu = np.einsum("nj,nj->n", u, u)
    # A corner's segment is a point: t is 0 there (the floor is the dtype's, 1e-300 is 0 in float32).
    t = np.einsum("nkj,nj->nk", points - p0[:, None, :], u) / np.maximum(uu, np.finfo(uu.dtype).tiny)[:, None]
    foot = p0[:, None, :] + np.clip(t, 0.0, 1.0)[..., None] * u[:, None, :]
    return np.linalg.norm(points - foot, axis=-1)


def _segments_distance(a0, a1, b0, b1):
    """Distance between the segments a0 -> a1 and b0 -> b1 (arrays (..., 3), broadcast; either
    may be a point): the closest points' parameters clamped to the segments, as in Ericson's
    Real-Time Collision Detection, 5.1.9."""
    d1, d2, w = a1 - a0, b1 - b0, a0 - b0
    a, e = np.einsum("...j,...j->...", d1, d1), np.einsum("...j,...j->...", d2, d2)
    b, c, f = np.einsum("...j,...j->...", d1, d2), np.einsum("...j,...j->...", d1, w), np.einsum("...j,...j->...", d2, w)
    tiny = np.finfo(np.float32).tiny
    denom = a * e - b * b
    with np.errstate(over="ignore"):  # a point's quotients overflow; np.where below discards them
        s = np.where(denom > 1e-12 * a * e, np.clip((b * f - c * e) / np.maximum(denom, tiny), 0.0, 1.0), 0.0)
        t = (b * s + f) / np.maximum(e, tiny)
        s = np.where(t < 0.0, np.clip(-c / np.maximum(a, tiny), 0.0, 1.0),
                     np.where(t > 1.0, np.clip((b - c) / np.maximum(a, tiny), 0.0, 1.0), s))
    t = np.where(e > tiny, np.clip(t, 0.0, 1.0), 0.0)
    s = np.where(a > tiny, s, 0.0)
    return np.linalg.norm(a0 + d1 * s[..., None] - b0 - d2 * t[..., None], axis=-1)


def _reach(extract, start, rec, normals, p0, p1, reach):
    """(triangle, item) pairs an item's (an edge's or a corner's) strip may cross beyond its own
    faces: the triangles round its vertices `start` (with `rec`, the item), within
    radius_clamp.SMOOTH_FOLD_DEG of one of its faces' normals (`normals`, (items, K, 3): a fillet
    runs on across a patch's facets), and on from their corners within `reach` of the item's
    segment p0 -> p1 (a point for a corner): a quad's other half at an edge's end, the thin
    facets of a triangulated face along it. Walked vertex by vertex, so a mesh whose faces are
    wider than the reach costs one fan per vertex; and within a polygon across each of its
    diagonals that passes within reach: a long triangle of an n-gon (a cylinder's cap) whose
    diagonal cuts across a rim's reach though none of its corners lies within it."""
    d = extract.edge_data
    tri_verts = getattr(d, "tri_verts", None) if d is not None else None
    polys = getattr(d, "polygons", None) if d is not None else None
    ok = start >= 0
    if tri_verts is None or polys is None or polys.normal is None or not ok.any():
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    from .radius_clamp import SMOOTH_FOLD_DEG
    cos_max = np.float32(np.cos(np.radians(SMOOTH_FOLD_DEG)))
    tri_verts = np.asarray(tri_verts, np.int64)
    tri_poly = np.asarray(polys.tri_poly, np.int64)
    tri_normal = np.asarray(polys.normal, np.float32)[tri_poly]
    vert_pos = np.zeros((int(tri_verts.max()) + 1, 3), np.float32)  # by vertex, from the corners
    vert_pos[tri_verts.reshape(-1)] = np.asarray(extract.corner_pos, np.float32).reshape(-1, 3)
    tv = tri_verts.reshape(-1)
    by_vert = np.argsort(tv, kind="stable")
    first = np.searchsorted(tv[by_vert], np.arange(tv.max() + 2))
    unit = (normals / np.maximum(np.linalg.norm(normals, axis=2, keepdims=True), 1e-30)).astype(np.float32)
    p0, p1, reach = p0.astype(np.float32), p1.astype(np.float32), reach.astype(np.float32)
    m = max(len(p0), 1)
    diagonals = _diagonals(tri_verts, tri_poly)
    front_v, front_r = start[ok], rec[ok]
    seen = np.unique(front_v * m + front_r)
    out_t, out_r = [], []
    for _ in range(8):
        count = first[front_v + 1] - first[front_v]
        src = np.repeat(np.arange(len(front_v)), count)
        offs = np.arange(len(src)) - np.repeat(np.cumsum(count) - count, count)
        t = by_vert[first[front_v][src] + offs] // 3
        r = front_r[src]
        flat = np.abs(np.einsum("nj,nkj->nk", tri_normal[t], unit[r])).max(axis=1) >= cos_max
        t, r = _across_diagonals(t[flat], r[flat], diagonals, vert_pos, p0, p1, reach, m)
        out_t.append(t)
        out_r.append(r)
        # On through the fan's corners within reach, each (corner, item) once.
        key = np.unique(tri_verts[t].reshape(-1) * m + np.repeat(r, 3))
        key = key[~np.isin(key, seen)]
        cv, cr = key // m, key % m
        key = key[_segment_distance(vert_pos[cv][:, None, :], p0[cr], p1[cr])[:, 0] < reach[cr]]
        if not len(key):
            break
        seen = np.union1d(seen, key)
        front_v, front_r = key // m, key % m
    return np.concatenate(out_t), np.concatenate(out_r)


def _diagonals(tri_verts, tri_poly):
    """(sides (D,), the vertex pairs of all triangle sides (3T, 2), the triangle across each of
    `sides`): the sides that two triangles of one polygon share (side k of triangle i is
    3 i + k), each listed from both of its triangles."""
    ends = np.stack([tri_verts, np.roll(tri_verts, -1, axis=1)], axis=2).reshape(-1, 2)
    pair = np.sort(ends, axis=1)
    poly = np.repeat(tri_poly, 3)
    # By vertex pair and polygon (three keys: one product of them overflows int64 past ~2M).
    order = np.lexsort((poly, pair[:, 1], pair[:, 0]))
    k = np.stack([pair[order, 0], pair[order, 1], poly[order]], axis=1)
    twin = np.flatnonzero(np.all(k[1:] == k[:-1], axis=1))
    a, b = order[twin], order[twin + 1]
    sides = np.r_[a, b]
    across = np.r_[b, a] // 3
    at = np.argsort(sides)
    return sides[at], ends, across[at]


def _across_diagonals(t, r, diagonals, vert_pos, p0, p1, reach, m):
    """The (triangle, item) pairs t, r and those reached from them across polygon diagonals
    within each item's reach, repeatedly (one polygon's triangles all lie in its plane)."""
    sides, ends, across = diagonals
    pairs = np.unique(t * m + r)
    front = pairs
    while len(front) and len(sides):
        ft, fr = front // m, front % m
        cand = (3 * ft[:, None] + np.arange(3)).reshape(-1)
        cr = np.repeat(fr, 3)
        at = np.minimum(np.searchsorted(sides, cand), len(sides) - 1)
        inner = sides[at] == cand
        cand, cr, at = cand[inner], cr[inner], at[inner]
        near = _segments_distance(vert_pos[ends[cand, 0]], vert_pos[ends[cand, 1]], p0[cr], p1[cr]) < reach[cr]
        key = np.unique(across[at[near]] * m + cr[near])
        front = key[~np.isin(key, pairs)]
        pairs = np.union1d(pairs, front)
    return pairs // m, pairs % m


def _lists(count, pos, rec, dist, per):
    """(count, per) float32: per position, up to `per` items + 1 (0: none), nearest first."""
    key = np.lexsort((dist, rec, pos))
    pos, rec, dist = pos[key], rec[key], dist[key]
    first_of = np.r_[True, (pos[1:] != pos[:-1]) | (rec[1:] != rec[:-1])]
    pos, rec, dist = pos[first_of], rec[first_of], dist[first_of]
    key = np.lexsort((rec, dist, pos))
    pos, rec = pos[key], rec[key]
    out = np.zeros((count, per), np.float32)
    if not len(pos):
        return out
    start = np.r_[0, np.flatnonzero(pos[1:] != pos[:-1]) + 1]
    nth = np.arange(len(pos)) - np.repeat(start, np.diff(np.r_[start, len(pos)]))
    keep = nth < per
    out[pos[keep], nth[keep]] = rec[keep] + 1
    return out


def _corners(extract):
    """(K, CORNER_TEXELS, 4) float32 records of the convex corner patches, and (K,) their
    vertices."""
    recs, verts = [], []
    for e in extract.edges.values():
        c = e.corners
        if c is None or not len(c):
            continue
        keep = np.flatnonzero((c.fold > 0) & (c.radius > 0.0))
        if not len(keep):
            continue
        r = np.zeros((len(keep), CORNER_TEXELS, 4), np.float32)
        r[:, 0, :3], r[:, 0, 3] = c.centre[keep], c.radius[keep]
        r[:, 1, :3] = c.position[keep]
        r[:, 2:5, :3] = c.normals[keep]
        recs.append(r)
        verts.append(np.asarray(c.vertex, np.int64)[keep])
    if not recs:
        return np.zeros((0, CORNER_TEXELS, 4), np.float32), np.zeros(0, np.int64)
    return np.concatenate(recs), np.concatenate(verts)


def _fans(tri_verts, tri_normal, order, item_verts, item_normals, per, ends=None):
    """(T, per) float32 lists, in batch order, of the items at each triangle's corners, flat
    with one of the item's faces (or the triangle's own side), own sides first: the strips and
    corners of a mesh whose faces are wider than its strips cross no other triangles. The
    library's el_outline_fans. item_verts (N, k): each item's vertices (an edge's two ends, a
    corner's one); `ends`: given, the items are edges, whose own sides are told."""
    return native.outline_fans(np.asarray(tri_verts)[order], np.asarray(tri_normal)[order], item_verts, item_normals,
                               per, np.cos(np.radians(_smooth_fold_deg())), own_sides=ends is not None)


def _smooth_fold_deg():
    from .radius_clamp import SMOOTH_FOLD_DEG
    return SMOOTH_FOLD_DEG


def _thinnest(tri_verts, corners, tris):
    """The least height of the triangles `tris` (mesh indices) over their longest side."""
    if not len(tris):
        return np.inf
    a, b, c = (corners[tris, k] for k in range(3))
    area2 = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    longest = np.max(np.stack([np.linalg.norm(b - a, axis=1), np.linalg.norm(c - b, axis=1),
                               np.linalg.norm(a - c, axis=1)]), axis=0)
    return float(np.min(area2 / np.maximum(longest, 1e-30)))


def records(extract):
    """(edges (M, EDGE_TEXELS, 4), corners (K, CORNER_TEXELS, 4), {slot: (T, EDGES_PER_TRIANGLE
    + CORNERS_PER_TRIANGLE) float32 edge numbers + 1, then corner numbers + 1, for the triangles
    of the slot's surface batch in batch order}), the slots only where a strip or a corner may
    cross one of their triangles; None without convex rounded edges. A triangle lists its own
    sides first, then the nearest."""
    slots = list(extract.slot_triangles.items())
    edges, faces, verts = edge_records(extract)
    if not slots or not len(edges):
        return None
    order = np.concatenate([tris for _, tris in slots])  # batch position -> triangle
    pos_of = np.empty(len(order), np.int64)
    pos_of[order] = np.arange(len(order))
    n1, n2 = edges[:, 0, :3].astype(np.float64), edges[:, 1, :3].astype(np.float64)
    cos_half = np.sqrt(np.clip(0.5 * (1.0 + np.einsum("ij,ij->i", n1, n2) / np.maximum(
        np.linalg.norm(n1, axis=1) * np.linalg.norm(n2, axis=1), 1e-30)), 1e-6, 1.0))
    # How far from the edge a face may show in its strip: up to where its fillet starts, the
    # setback r tan(a/2) (a the fold). The strip itself is narrower, r (1/cos(a/2) - 1), but
    # the face behind a silhouette, seen at a grazing angle, folds its image over the strip from
    # farther than that; past the setback every face lies inside the fillet's outline.
    setback = edges[:, 0, 3] * np.sqrt(1.0 - cos_half * cos_half) / cos_half
    p0, p1 = edges[:, 2, :3].astype(np.float64), edges[:, 3, :3].astype(np.float64)
    corners, cverts = corner_records(extract)
    reach = np.linalg.norm(corners[:, 0, :3] - corners[:, 1, :3], axis=1)
    d = extract.edge_data
    tri_verts = getattr(d, "tri_verts", None) if d is not None else None
    polys = getattr(d, "polygons", None) if d is not None else None
    corners_of = np.asarray(extract.corner_pos, np.float64).reshape(-1, 3, 3)
    if tri_verts is not None and polys is not None and polys.normal is not None and np.all(verts >= 0):
        tri_verts = np.asarray(tri_verts, np.int64)
        tri_normal = np.asarray(polys.normal, np.float32)[np.asarray(polys.tri_poly, np.int64)]
        # Faces wider than every setback and corner zone round them: the fans of the items'
        # vertices hold every triangle they cross (a box, a grid of cubes).
        near = np.isin(tri_verts, np.r_[verts.reshape(-1), cverts]).any(axis=1)
        if max(setback.max(initial=0.0), reach.max(initial=0.0)) < _thinnest(tri_verts, corners_of, np.flatnonzero(near)):
            unit = lambda n: (n / np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-30)).astype(np.float32)  # noqa: E731
            lists = np.concatenate([
                _fans(tri_verts, tri_normal, order, verts, unit(np.stack([n1, n2], axis=1)), EDGES_PER_TRIANGLE, verts),
                _fans(tri_verts, tri_normal, order, cverts[:, None], unit(corners[:, 2:5, :3].astype(np.float64)),
                      CORNERS_PER_TRIANGLE)], axis=1)
            return edges, corners, _by_slot(slots, lists)
    own = np.concatenate([order[faces[:, 0]], order[faces[:, 1]]])
    tri, rec = _reach(extract, verts.reshape(-1), np.repeat(np.arange(len(edges)), 2), np.stack([n1, n2], axis=1),
                      p0, p1, setback)
    # Nearest first, own sides before all.
    dist = _segment_distance(corners_of[tri], p0[rec], p1[rec]).min(axis=1) if len(tri) else np.zeros(0)
    lists = [_lists(len(order), pos_of[np.concatenate([own, tri])], np.concatenate([np.tile(np.arange(len(edges)), 2), rec]),
                    np.r_[np.full(len(own), -1.0), dist], EDGES_PER_TRIANGLE)]
    if len(corners):
        # The corner's zone reaches from its vertex to where the ball touches the faces, under
        # the ball's centre's distance from the vertex.
        v = corners[:, 1, :3].astype(np.float64)
        tri, rec = _reach(extract, cverts, np.arange(len(corners)), corners[:, 2:5, :3].astype(np.float64), v, v, reach)
        dist = np.linalg.norm(corners_of[tri] - v[rec][:, None, :], axis=2).min(axis=1) if len(tri) else np.zeros(0)
        lists.append(_lists(len(order), pos_of[tri], rec, dist, CORNERS_PER_TRIANGLE))
    else:
        lists.append(np.zeros((len(order), CORNERS_PER_TRIANGLE), np.float32))
    return edges, corners, _by_slot(slots, np.concatenate(lists, axis=1))


def _by_slot(slots, lists):
    """{slot: its triangles' rows of `lists`} for the slots with any item listed."""
    out, at = {}, 0
    for slot, tris in slots:
        part = lists[at:at + len(tris)]
        at += len(tris)
        if np.any(part > 0.0):
            out[slot] = part
    return out
