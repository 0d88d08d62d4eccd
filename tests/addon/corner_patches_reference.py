"""The numpy copy of corner patches (corner_patches.find) that the add-on ran until the library
took it over (native/src/corner_patches.cpp, el_corner_patches): the reference
test_corner_patches.py holds the library to. Not loaded by the add-on."""
import numpy as np

from addon_modules import addon_module

Corners = addon_module("geometry.corner_patches").Corners

# Two sides of one sector (edges meeting at the corner, the faces between them) turn by at most
# this: the facets of one smooth patch, each fold under 30 degrees, may add up to more than one
# fold, but a sector curving further is no face a ball can touch.
SECTOR_TURN_DEG = 40.0
# |det| of the three unit sector normals below this: faces too near one plane (a shallow
# corner), whose ball sits far from the vertex; its bands' mitres stand.
MIN_DET = 0.05
# The ball's centre further than this many radii from the vertex (a needle-sharp corner): the
# patch would lie far from where its fillets end.
MAX_REACH = 4.0

# Which side of each of the corner's edges A, B, C faces the next edge round (A: towards B, B:
# towards C, C: towards A), for each of the eight choices (sA, sB, sC).
_CHOICES = np.array([[a, b, c] for a in (0, 1) for b in (0, 1) for c in (0, 1)])


def _cross(u, v):
    """Row-wise cross products (np.cross is several times slower on (K, 3) arrays)."""
    return np.stack([u[:, 1] * v[:, 2] - u[:, 2] * v[:, 1], u[:, 2] * v[:, 0] - u[:, 0] * v[:, 2],
                     u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]], axis=1)


def find(edges, positions, normals, convex, chosen, radius, stop=None):
    """Corner patches of a mesh. edges (E, 2) vertex indices; normals (E, 6) each edge's two
    faces' unit normals (N1, N2, oriented alike); convex, chosen (E,) booleans; radius (E,) the
    chosen edges' radii; stop (E,) the edges a face's smooth patch ends at (the rounded ones,
    sharp, open or folded past radius_clamp.SMOOTH_FOLD_DEG: edge_choice), default the chosen."""
    nv = len(positions)
    sel = np.flatnonzero(chosen)
    conv = sel[convex[sel]]
    count_all = np.bincount(edges[sel].reshape(-1), minlength=nv)
    count_conv = np.bincount(edges[conv].reshape(-1), minlength=nv)
    # Three convex edges (the ball inside the solid) or three concave ones (the ball in the air,
    # the patch filling the inside corner); a mix meets on a saddle, not a ball.
    # No other patch boundary round the vertex: an unrounded fold or a sharp mark inside a
    # sector would make it two faces, and the ball would not meet the bands' arcs.
    count_stop = np.bincount(edges[np.flatnonzero(chosen if stop is None else stop)].reshape(-1), minlength=nv)
    at = (count_all == 3) & ((count_conv == 3) | (count_conv == 0)) & (count_stop == 3)
    inc_v = edges[sel].reshape(-1).astype(np.int64)
    inc_e = np.repeat(sel, 2)
    keep = at[inc_v]
    inc_v, inc_e = inc_v[keep], inc_e[keep]
    order = np.argsort(inc_v, kind="stable")
    verts, trio = inc_v[order][::3], inc_e[order].reshape(-1, 3)
    n = normals[trio].reshape(-1, 3, 2, 3)  # (K, edge, side, xyz)
    k = np.arange(len(trio))
    # cos[:, j, p, q]: side p of edge j against side q of the next edge round (A-B, B-C, C-A).
    nxt = n[:, [1, 2, 0]]
    cos = (n[:, :, :, None, :] * nxt[:, :, None, :, :]).sum(axis=4)
    sa, sb, sc = _CHOICES.T
    # Each choice's worst sector: AB is A[sA] with B[1 - sB], BC is B[sB] with C[1 - sC], CA is
    # C[sC] with A[1 - sA].
    score = np.minimum(np.minimum(cos[:, 0, sa, 1 - sb], cos[:, 1, sb, 1 - sc]), cos[:, 2, sc, 1 - sa])
    best = np.argmax(score, axis=1)
    best_cos = score[k, best]
    s_own = _CHOICES[best]                                   # (K, 3): edge j's side toward edge j + 1
    s_next = 1 - s_own[:, [1, 2, 0]]                         # edge j + 1's side toward edge j
    pick = lambda a, side: np.take_along_axis(a, side[:, :, None, None], axis=2)[:, :, 0]  # noqa: E731
    sector = pick(n, s_own) + pick(nxt, s_next)
    sector /= np.maximum(np.sqrt((sector * sector).sum(axis=2, keepdims=True)), 1e-30)
    a, b, c = sector[:, 0], sector[:, 1], sector[:, 2]
    bc, ca, ab = _cross(b, c), _cross(c, a), _cross(a, b)
    det = (a * bc).sum(axis=1)
    r = radius[trio].min(axis=1)
    ok = (best_cos >= np.cos(np.radians(SECTOR_TURN_DEG))) & (np.abs(det) > MIN_DET) & (r > 0.0)
    # The ball touches each sector's plane from inside: N (c - v) = -r (1, 1, 1), by Cramer's rule
    # (the rows' cross products are the inverse's columns times det).
    fold = np.where(convex[trio[:, 0]], 1.0, -1.0)
    offset = -(fold * r)[:, None] * (bc + ca + ab) / np.where(ok, det, 1.0)[:, None]
    ok &= (offset * offset).sum(axis=1) <= (MAX_REACH * r) ** 2
    return Corners(verts[ok], positions[verts[ok]].astype(np.float32), trio[ok], sector[ok].astype(np.float32), r[ok].astype(np.float32),
                   (positions[verts[ok]].astype(np.float64) + offset[ok]).astype(np.float32), fold[ok].astype(np.float32))
