"""Corner patches: where three rounded convex edges meet at a vertex, their fillets end on a piece
of the sphere of radius r that touches the three faces (the rolling ball's corner, as the Bevel
modifier's vertex patch; docs/highlight_math.md, "Corner patches"). The bands stop at mitres
there; the patch is drawn over them (shaders/edge_corner.*).

A vertex is a corner where exactly three rounded edges meet, all convex, and the fan round it
falls into three sectors, one between each two of those edges: the sides of the two edges
facing each other there turn by less than SECTOR_TURN_DEG (one face, or facets of one smooth
patch). Each sector's normal is the mean of those two sides'. No bpy: plain-Python tests import
it.
"""
from dataclasses import dataclass

import numpy as np

# Two sides of one sector (edges meeting at the corner, the faces between them) turn by at most
# this: more and a fold between them (a sharp edge left unrounded) makes the fan no corner of
# three faces.
SECTOR_TURN_DEG = 40.0
# |det| of the three unit sector normals below this: faces too near one plane (a shallow
# corner), whose ball sits far from the vertex; its bands' mitres stand.
MIN_DET = 0.05
# The ball's centre further than this many radii from the vertex (a needle-sharp corner): the
# patch would lie far from where its fillets end.
MAX_REACH = 4.0

# Which side of each of the corner's edges A, B, C faces which sector, for each of the eight
# choices (sA, sB, sC): sector AB is A[sA] and B[1 - sB], BC is B[sB] and C[1 - sC], CA is
# C[sC] and A[1 - sA].
_CHOICES = np.array([[a, b, c] for a in (0, 1) for b in (0, 1) for c in (0, 1)])


@dataclass
class Corners:
    """Corner patches of one mesh, object space."""
    vertex: np.ndarray   # (K,) vertex index
    position: np.ndarray  # (K, 3) the vertex's position
    edges: np.ndarray    # (K, 3) its three rounded edges
    normals: np.ndarray  # (K, 3, 3) unit normals of its three sectors (AB, BC, CA)
    radius: np.ndarray   # (K,) the ball's radius: the smallest of its edges' radii
    centre: np.ndarray   # (K, 3) the ball's centre, r under all three faces
    faces: np.ndarray = None  # (K, 6) float32 surface ids of its edges' faces (visibility)

    def __len__(self):
        return len(self.vertex)

    def subset(self, rows):
        return Corners(*(None if a is None else a[rows] for a in (self.vertex, self.position, self.edges, self.normals,
                                                                   self.radius, self.centre, self.faces)))


def find(edges, positions, normals, convex, chosen, radius):
    """Corner patches of a mesh. edges (E, 2) vertex indices; normals (E, 6) each edge's two
    faces' unit normals (N1, N2, oriented alike); convex, chosen (E,) booleans; radius (E,) the
    chosen edges' radii."""
    nv = len(positions)
    sel = np.flatnonzero(chosen)
    conv = sel[convex[sel]]
    count_all = np.bincount(edges[sel].reshape(-1), minlength=nv)
    count_conv = np.bincount(edges[conv].reshape(-1), minlength=nv)
    at = (count_all == 3) & (count_conv == 3)
    inc_v = edges[conv].reshape(-1).astype(np.int64)
    inc_e = np.repeat(conv, 2)
    keep = at[inc_v]
    inc_v, inc_e = inc_v[keep], inc_e[keep]
    order = np.argsort(inc_v, kind="stable")
    verts, trio = inc_v[order][::3], inc_e[order].reshape(-1, 3)
    n = normals[trio].astype(np.float64).reshape(-1, 3, 2, 3)  # (K, edge, side, xyz)
    k = np.arange(len(trio))

    def sector_pairs(ch):
        sa, sb, sc = ch
        return ((0, sa, 1, 1 - sb), (1, sb, 2, 1 - sc), (2, sc, 0, 1 - sa))

    best_cos = np.full(len(trio), -2.0)
    best = np.zeros(len(trio), np.int64)
    for i, ch in enumerate(_CHOICES):
        cos = np.min([np.einsum("kx,kx->k", n[:, e0, s0], n[:, e1, s1]) for e0, s0, e1, s1 in sector_pairs(ch)], axis=0)
        better = cos > best_cos
        best_cos[better], best[better] = cos[better], i
    sides = np.zeros((len(trio), 3, 2, 2), np.int64)
    for i, ch in enumerate(_CHOICES):
        rows = best == i
        for s, (e0, s0, e1, s1) in enumerate(sector_pairs(ch)):
            sides[rows, s] = [[e0, s0], [e1, s1]]
    sector = n[k[:, None], sides[:, :, 0, 0], sides[:, :, 0, 1]] + n[k[:, None], sides[:, :, 1, 0], sides[:, :, 1, 1]]
    sector /= np.maximum(np.linalg.norm(sector, axis=2, keepdims=True), 1e-30)
    det = np.linalg.det(sector) if len(trio) else np.zeros(0)
    r = radius[trio].astype(np.float64).min(axis=1)
    ok = (best_cos >= np.cos(np.radians(SECTOR_TURN_DEG))) & (np.abs(det) > MIN_DET) & (r > 0.0)
    # The ball touches each sector's plane from inside: N (c - v) = -r (1, 1, 1).
    offset = np.zeros((len(trio), 3))
    if np.any(ok):
        offset[ok] = np.linalg.solve(sector[ok], -r[ok, None] * np.ones((1, 3)))
    ok &= np.linalg.norm(offset, axis=1) <= MAX_REACH * r
    return Corners(verts[ok], positions[verts[ok]].astype(np.float32), trio[ok], sector[ok].astype(np.float32), r[ok].astype(np.float32),
                   (positions[verts[ok]].astype(np.float64) + offset[ok]).astype(np.float32))
