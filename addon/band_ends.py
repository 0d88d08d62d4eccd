"""Where a rounded edge's band ends, on each of its two faces (docs/highlight_math.md, "Band
ends").

A fillet runs the length of its edge and stops where its face does: at each end, the band on a
face is cut by a line through the end vertex in that face's plane. Where the face's next side
there is rounded too, the two fillets meet on the bisector of the corner (a mitre: the picture
frame of a box's top, the seamless turn of a rim made of short edges); where it is not rounded,
the band stops at that side if the corner is sharper than a right angle, and square to its edge
otherwise. The cut is given as the angle phi of its line from the edge, towards the face's inside:
pi / 2 is square, smaller leans over the edge. A cut never reaches past its vertex: the outer side
of a turn (a reflex corner, where a mitre would) keeps the notch square ends leave there, since a
band drawn past the vertex ran off the part wherever the corner was on the outline.
"""
import numpy as np

SQUARE = np.float32(np.pi / 2)
_MIN = 0.02  # rad: a cut along the edge itself would remove the whole band


def _next_loop(polys, loop, poly):
    """The loop after `loop` in polygon `poly` (cyclic), and the one before."""
    start, total = polys.start[poly], polys.total[poly]
    rel = loop - start
    return start + (rel + 1) % total, start + (rel - 1) % total


def _loop_lookup(polys):
    """Sorted keys (edge * polygon count + polygon) of every loop, and the loops in that order:
    which loop of a polygon runs along an edge. Built once per mesh (a material change re-chooses
    edges without re-reading the mesh) and kept on the Polygons."""
    if polys.loop_lookup is None:
        count = len(polys.start)
        keys = polys.loop_edge.astype(np.int64) * count + np.repeat(np.arange(count, dtype=np.int64), polys.total)
        order = np.argsort(keys, kind="stable")
        polys.loop_lookup = (keys[order], order)
    return polys.loop_lookup


def end_angles(polys, positions, normals, edges, sel, faces, rounded):
    """(N, 4) float32 cut angles of edges `sel`: (p0 on N1's face, p0 on N2's face, p1 on N1's
    face, p1 on N2's face). faces (N, 2): each edge's two loop triangles; rounded: per mesh edge,
    whether it is rounded (the mitre needs both sides rounded). N1's face runs p0 -> p1 (the
    library's convention), so its inside is N1 x (p1 - p0), and N2's is (p1 - p0) x N2."""
    out = np.full((len(sel), 4), SQUARE, np.float32)
    if polys is None or polys.loop_edge is None or polys.normal is None or not len(sel):
        return out
    p0 = positions[edges[sel, 0]].astype(np.float64)
    p1 = positions[edges[sel, 1]].astype(np.float64)
    e = p1 - p0
    e /= np.maximum(np.linalg.norm(e, axis=1, keepdims=True), 1e-30)
    count = len(polys.start)
    keys, order = _loop_lookup(polys)
    if not len(keys):
        return out
    inside = (np.cross(normals[sel, :3].astype(np.float64), e), np.cross(e, normals[sel, 3:].astype(np.float64)))
    for side in range(2):
        has = np.flatnonzero(faces[:, side] >= 0)
        poly = polys.tri_poly[faces[has, side]]
        # The polygon's loop along this edge, looked up by (edge, polygon).
        want = sel[has].astype(np.int64) * count + poly
        at = np.minimum(np.searchsorted(keys, want), len(keys) - 1)
        ok = keys[at] == want
        has, poly, loop = has[ok], poly[ok], order[at[ok]]
        nxt, prv = _next_loop(polys, loop, poly)
        nxt2, _ = _next_loop(polys, nxt, poly)
        runs_forward = polys.loop_vert[loop] == edges[sel[has], 0]
        # N1's face or N2's: by normal, not by winding (the library orients faces the file may
        # have flipped; the polygons keep the file's winding).
        n_poly = polys.normal[poly]
        col = np.where(np.abs(np.einsum("ij,ij->i", n_poly, normals[sel[has], :3]))
                       >= np.abs(np.einsum("ij,ij->i", n_poly, normals[sel[has], 3:])), 0, 1)
        for end in range(2):
            # At the loop's own vertex the face's other side goes back one loop; at the next
            # vertex it goes on one.
            at_start = runs_forward if end == 0 else ~runs_forward
            other_vert = np.where(at_start, polys.loop_vert[prv], polys.loop_vert[nxt2])
            other_edge = np.where(at_start, polys.loop_edge[prv], polys.loop_edge[nxt])
            vert = np.where(end == 0, p0[has], p1[has])
            u = e[has] if end == 0 else -e[has]
            g = positions[other_vert].astype(np.float64) - vert
            n_in = np.where((col == 0)[:, None], inside[0][has], inside[1][has])
            n_in /= np.maximum(np.linalg.norm(n_in, axis=1, keepdims=True), 1e-30)
            # The face's corner angle at this end, from the edge towards its inside.
            theta = np.arctan2(np.einsum("ij,ij->i", g, n_in), np.einsum("ij,ij->i", g, u)) % (2.0 * np.pi)
            phi = np.where(rounded[other_edge], 0.5 * theta, theta)
            phi = np.clip(phi, _MIN, SQUARE)
            out[has, 2 * end + col] = phi.astype(np.float32)
    return out
