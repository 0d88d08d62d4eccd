"""Where a rounded edge's band ends, on each of its two faces (docs/highlight_math.md, "Band
ends").

A fillet runs the length of its edge and stops where its face does: at each end, the band on a
face is cut by a line through the end vertex in that face's plane. Where the face's next side
there is rounded too, the two fillets meet on the bisector of the corner (a mitre: the picture
frame of a box's top, the seamless turn of a rim made of short edges); where it is not rounded,
the band stops at that side if the corner is sharper than a right angle, and square to its edge
otherwise. The cut is given as the angle phi of its line from the edge, towards the face's inside:
pi / 2 is square, smaller leans over the edge, larger leans past the vertex. Only a mitre at a
joint of one chain of rounded edges leans past: on the outer side of a turn (a reflex corner)
the fillets' axes meet on the bisector beyond the vertex, and square ends there left a notch at
every vertex of a rim (the shoulder round a boss, the plate round a hole). A band that leans past
a corner on the outline shows in the outline's own pixels at most (the outline's fringe,
edge_highlight.frag). The library decides them (native/src/band_ends.cpp, el_band_ends).
"""
import numpy as np

from ..bridge import native

SQUARE = np.float32(np.pi / 2)


def end_angles(polys, positions, normals, edges, sel, faces, rounded, smooth=None, edge_polys=None):
    """(N, 4) float32 cut angles of edges `sel`: (p0 on N1's face, p0 on N2's face, p1 on N1's
    face, p1 on N2's face). faces (N, 2): each edge's two loop triangles; rounded: per mesh edge,
    whether it is rounded (the mitre needs both sides rounded). N1's face runs p0 -> p1 (the
    library's convention), so its inside is N1 x (p1 - p0), and N2's is (p1 - p0) x N2. smooth
    (per mesh edge) and edge_polys ((E, 2) each edge's first two polygons): where given, a face
    is its smooth patch, whose side at the vertex is the first one round the fan not in smooth.
    The library's el_band_ends."""
    if polys is None or polys.loop_edge is None or polys.normal is None or not len(sel):
        return np.full((len(sel), 4), SQUARE, np.float32)
    return native.band_ends(polys, positions, edges, normals, rounded, sel, faces, smooth, edge_polys)
