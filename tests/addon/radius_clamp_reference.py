"""The numpy copy of the radius clamp's first look (radius_clamp.width_bounds) that the add-on
ran until the library took it over (native/src/radius_clamp.cpp, el_width_bounds): the reference
test_radius_clamp.py holds the library to. Not loaded by the add-on."""
import numpy as np


def width_bounds(polys, positions, edges, edge_polys):
    """(N, 2) a lower bound of widths() for edges (N, 2) whose polygons are edge_polys (N, 2)
    (-1: none, bound 0): the farthest from the edge's line of three of the polygon's corners
    (the first, and a third and two thirds of the way round), found without expanding every
    corner. An edge whose fillets need no more than this is not clamped."""
    out = np.zeros(edge_polys.shape)
    a = positions[edges[:, 0]].astype(np.float64)
    d = positions[edges[:, 1]].astype(np.float64) - a
    length = np.maximum(np.linalg.norm(d, axis=1), 1e-30)
    for side in range(2):
        has = np.flatnonzero(edge_polys[:, side] >= 0)
        p = edge_polys[has, side]
        for k in range(3):
            corner = polys.start[p] + (k * polys.total[p]) // 3
            v = positions[polys.loop_vert[corner]].astype(np.float64) - a[has]
            out[has, side] = np.maximum(out[has, side], np.linalg.norm(np.cross(d[has], v), axis=1) / length[has])
    return out
