"""Silhouette lines on the rounded outline (docs/lines.md, "Silhouettes of rounded edges"). Where
the edge pass rounds a convex edge, the surface pass pulls the part's outline in to the fillet's
(rounded_outline.glsl), and the ink of a silhouette along that edge follows it there instead of
tracing the sharp edge past the part. Each end of such a segment moves to its fillet's outline
point: r from the fillet's axis along P = (Na x Nb) x V / |...|, turned towards the sharp edge,
which lies r C from the axis. That is a move of -r (C - P) in world space, judged with the
normals and the radius the strip is (zero where the end is no silhouette, as the strip's width
is), so the stroke's centre lies on the strip's inner side. The library does the per-view work
(native/src/outline_lines.cpp; lines.silhouettes asks it for all instances of a mesh at once,
el_view_lines); this module hands it the mesh's records once per extraction. No bpy: plain-Python tests import it."""
import numpy as np

from ..bridge import native
from . import rounded_outline


def outline_of(extract):
    """The mesh's convex rounded edges and corner patches as a native.Outline (the strip's own
    records: rounded_outline._edges and _corners), made once per extraction's chosen edges."""
    def compute(extract):
        recs, _, verts = rounded_outline.edge_records(extract)
        known = np.all(verts >= 0, axis=1)
        crecs, cverts = rounded_outline.corner_records(extract)
        return native.Outline(recs[known].reshape(-1, 4 * native.OUTLINE_EDGE_TEXELS), verts[known],
                              crecs.reshape(-1, 4 * native.OUTLINE_CORNER_TEXELS), cverts)
    return rounded_outline.from_edges(extract, "outline lines", compute)

