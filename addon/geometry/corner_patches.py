"""Corner patches: where three rounded convex edges meet at a vertex, their fillets end on a piece
of the sphere of radius r that touches the three faces (the rolling ball's corner, as the Bevel
modifier's vertex patch; docs/highlight_math.md, "Corner patches"); where three concave ones
meet (an inside corner, a pocket's floor), on the far side of the ball rolling in the air. The
bands stop at mitres there; the patch is drawn over them (shaders/edge_corner.*).

A vertex is a corner where exactly three rounded edges meet, all convex or all concave, no other
edge there ends a smooth patch (sharp, open, or folded past radius_clamp.SMOOTH_FOLD_DEG), and
the fan round it falls into three sectors, one between each two of those edges: the sides of
the two edges facing each other there turn by less than 40 degrees (the sum of a patch's folds
across a sector). Each sector's normal is the mean of those two sides'. The library finds them
(native/src/corner_patches.cpp, el_corner_patches); this module keeps what the add-on holds of
them. No bpy: plain-Python tests import it.
"""
from dataclasses import dataclass

import numpy as np

from ..bridge import native


@dataclass
class Corners:
    """Corner patches of one mesh, object space."""
    vertex: np.ndarray   # (K,) vertex index
    position: np.ndarray  # (K, 3) the vertex's position
    edges: np.ndarray    # (K, 3) its three rounded edges
    normals: np.ndarray  # (K, 3, 3) unit normals of its three sectors (AB, BC, CA)
    radius: np.ndarray   # (K,) the ball's radius: the smallest of its edges' radii
    centre: np.ndarray   # (K, 3) the ball's centre, r under all three faces (convex) or over them
    fold: np.ndarray     # (K,) +1: three convex edges, -1: three concave ones
    faces: np.ndarray = None  # (K, 6) float32 surface ids of its edges' faces (visibility)

    def __len__(self):
        return len(self.vertex)

    def subset(self, rows):
        return Corners(*(None if a is None else a[rows] for a in (self.vertex, self.position, self.edges, self.normals,
                                                                   self.radius, self.centre, self.fold, self.faces)))


def find(edges, positions, normals, convex, chosen, radius, stop=None):
    """Corner patches of a mesh (the library's el_corner_patches). edges (E, 2) vertex indices;
    normals (E, 6) each edge's two faces' unit normals (N1, N2, oriented alike); convex, chosen
    (E,) booleans; radius (E,) the chosen edges' radii; stop (E,) the edges a face's smooth patch
    ends at (the rounded ones, sharp, open or folded past radius_clamp.SMOOTH_FOLD_DEG:
    edge_choice), default the chosen."""
    c = native.corner_patches(positions, edges, normals, convex, chosen, radius, stop)
    verts = c["vertex"].astype(np.int64)
    return Corners(verts, np.asarray(positions, np.float32)[verts].reshape(-1, 3), c["edges"].astype(np.int64),
                   c["normals"], c["radius"], c["centre"], c["fold"])
