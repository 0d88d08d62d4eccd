"""The numpy copy of where rounded edges' bands end (band_ends.end_angles) that the add-on ran
until the library took it over (native/src/band_ends.cpp, el_band_ends): the reference
test_band_ends.py holds the library to. Not loaded by the add-on."""
import numpy as np

SQUARE = np.float32(np.pi / 2)
_MIN = 0.02  # rad: a cut along the edge itself would remove the whole band
_MAX_MITRE = np.float32(0.75 * np.pi)  # a mitre leans past its vertex by at most the band's width
_MAX_FAN = 32  # facets round one vertex a cut looks across at most


def _next_loop(polys, loop, poly):
    """The loop after `loop` in polygon `poly` (cyclic), and the one before."""
    start, total = polys.start[poly], polys.total[poly]
    rel = loop - start
    return start + (rel + 1) % total, start + (rel - 1) % total


def _loop_lookup(polys):
    """Sorted keys (edge * polygon count + polygon) of every loop, and the loops in that order:
    which loop of a polygon runs along an edge."""
    count = len(polys.start)
    keys = polys.loop_edge.astype(np.int64) * count + np.repeat(np.arange(count, dtype=np.int64), polys.total)
    order = np.argsort(keys, kind="stable")
    return keys[order], order


def _side_at(polys, loop, poly, vert):
    """The other side at vertex `vert` of polygon `poly`, whose loop `loop` has `vert` at one end:
    (its edge, its far vertex)."""
    nxt, prv = _next_loop(polys, loop, poly)
    nxt2, _ = _next_loop(polys, nxt, poly)
    at_start = polys.loop_vert[loop] == vert
    return (np.where(at_start, polys.loop_edge[prv], polys.loop_edge[nxt]),
            np.where(at_start, polys.loop_vert[prv], polys.loop_vert[nxt2]))


def _loop_of(polys, edge, poly):
    """Loop of polygon `poly` along `edge` (-1 where it has none)."""
    keys, order = _loop_lookup(polys)
    want = edge.astype(np.int64) * len(polys.start) + poly
    at = np.minimum(np.searchsorted(keys, want), len(keys) - 1)
    return np.where(keys[at] == want, order[at], -1)


def _round_the_fan(polys, edge_polys, smooth, own_edge, vert, poly, side, far):
    """From a face's side at a vertex, on around the vertex across every side in `smooth` (a
    smooth patch's facets: the face a fillet lies on goes on there) to the patch's own side:
    (its edge, its far vertex), or own_edge where the fan comes back round to the band's edge."""
    live = np.flatnonzero(smooth[side] & (side != own_edge))
    for _ in range(_MAX_FAN):
        if not len(live):
            break
        g, p = side[live], poly[live]
        q = np.where(edge_polys[g, 0] == p, edge_polys[g, 1], edge_polys[g, 0])
        go = (q >= 0) & (q != p)
        live, g, q = live[go], g[go], q[go]
        loop = _loop_of(polys, g, q)
        go = loop >= 0
        live, q, loop = live[go], q[go], loop[go]
        side[live], far[live] = _side_at(polys, loop, q, vert[live])
        poly[live] = q
        live = live[smooth[side[live]] & (side[live] != own_edge[live])]
    return side, far


def end_angles(polys, positions, normals, edges, sel, faces, rounded, smooth=None, edge_polys=None):
    """(N, 4) float32 cut angles of edges `sel`: (p0 on N1's face, p0 on N2's face, p1 on N1's
    face, p1 on N2's face). faces (N, 2): each edge's two loop triangles; rounded: per mesh edge,
    whether it is rounded (the mitre needs both sides rounded). N1's face runs p0 -> p1 (the
    library's convention), so its inside is N1 x (p1 - p0), and N2's is (p1 - p0) x N2. smooth
    (per mesh edge) and edge_polys ((E, 2) each edge's first two polygons): where given, a face
    is its smooth patch, whose side at the vertex is the first one round the fan not in smooth."""
    out = np.full((len(sel), 4), SQUARE, np.float32)
    if polys is None or polys.loop_edge is None or polys.normal is None or not len(sel):
        return out
    p0 = positions[edges[sel, 0]].astype(np.float64)
    p1 = positions[edges[sel, 1]].astype(np.float64)
    e = p1 - p0
    e /= np.maximum(np.linalg.norm(e, axis=1, keepdims=True), 1e-30)
    if not len(_loop_lookup(polys)[0]):
        return out
    inside = (np.cross(normals[sel, :3].astype(np.float64), e), np.cross(e, normals[sel, 3:].astype(np.float64)))
    joint = np.bincount(edges[rounded].ravel(), minlength=len(positions)) == 2  # a chain's joint
    for side in range(2):
        has = np.flatnonzero(faces[:, side] >= 0)
        poly = polys.tri_poly[faces[has, side]]
        # The polygon's loop along this edge, looked up by (edge, polygon).
        loop = _loop_of(polys, sel[has], poly)
        ok = loop >= 0
        has, poly, loop = has[ok], poly[ok], loop[ok]
        # N1's face or N2's: by normal, not by winding (the library orients faces the file may
        # have flipped; the polygons keep the file's winding).
        n_poly = polys.normal[poly]
        col = np.where(np.abs(np.einsum("ij,ij->i", n_poly, normals[sel[has], :3]))
                       >= np.abs(np.einsum("ij,ij->i", n_poly, normals[sel[has], 3:])), 0, 1)
        for end in range(2):
            v = edges[sel[has], end].astype(np.int64)
            other_edge, other_vert = _side_at(polys, loop, poly, v)
            closed = np.zeros(len(has), bool)
            if smooth is not None and edge_polys is not None:
                own = sel[has].astype(np.int64)
                other_edge, other_vert = _round_the_fan(polys, edge_polys, smooth, own, v, poly.copy(),
                                                        other_edge, other_vert)
                closed = other_edge == own  # the band's edge ends inside a smooth patch
            vert = np.where(end == 0, p0[has], p1[has])
            u = e[has] if end == 0 else -e[has]
            g = positions[other_vert].astype(np.float64) - vert
            n_in = np.where((col == 0)[:, None], inside[0][has], inside[1][has])
            n_in /= np.maximum(np.linalg.norm(n_in, axis=1, keepdims=True), 1e-30)
            # The face's corner angle at this end, from the edge towards its inside.
            theta = np.arctan2(np.einsum("ij,ij->i", g, n_in), np.einsum("ij,ij->i", g, u)) % (2.0 * np.pi)
            mitre = rounded[other_edge]
            # A mitre on the outer side of a turn leans past the vertex, over its own face, where
            # the vertex is a joint of one chain of rounded edges: the turning fillets' bands
            # meet on the bisector there too, with no notch. Where a third rounded edge meets
            # them (the concave edge into a reflex corner) their fillets turn round its own.
            lean = np.where(joint[v], _MAX_MITRE, SQUARE)
            phi = np.where(mitre, np.minimum(0.5 * theta, lean), np.minimum(theta, SQUARE))
            phi = np.where(closed, SQUARE, np.maximum(phi, _MIN))
            out[has, 2 * end + col] = phi.astype(np.float32)
    return out
