"""Per-edge data of one extracted mesh that the edge and line choices read: the library's
classification (numpy copies) and which triangles each edge joins. No bpy: plain-Python tests
import it."""
from dataclasses import dataclass

import numpy as np

from . import native, radius_clamp


@dataclass
class EdgeData:
    """Per-edge classification of one mesh (numpy copies of the native results)."""
    flags: np.ndarray
    angles: np.ndarray
    normals: np.ndarray
    edges: np.ndarray
    positions: np.ndarray
    face_a: np.ndarray
    face_b: np.ndarray
    tri_slot: np.ndarray
    sharp: np.ndarray
    bevel: np.ndarray
    surface_id: np.ndarray = None      # per triangle: 1 + its place in the slot-ordered surface batches
    polygons: object = None            # radius_clamp.Polygons
    face_widths: np.ndarray = None     # (E, 2) width of each edge's faces across it, NaN until needed
    edge_polys: np.ndarray = None      # (E, 2) polygons of each edge's first two faces, once needed

    def widths_of(self, sel):
        """The face widths of edges `sel`, computed once per edge (radius_clamp)."""
        if self.face_widths is None:
            self.face_widths = np.full((len(self.edges), 2), np.nan)
        todo = sel[np.isnan(self.face_widths[sel, 0])]
        if len(todo):
            faces = np.stack([self.face_a[todo], self.face_b[todo]], axis=1)
            self.face_widths[todo] = radius_clamp.widths(self.polygons, self.positions, self.edges[todo], faces)
        return self.face_widths[sel]

    def edge_polygons(self):
        """(E, 2) the polygons of each edge's first two faces (-1: none), for walks across patches; None without polygons."""
        if self.edge_polys is None and self.polygons is not None:
            tri_poly = self.polygons.tri_poly
            self.edge_polys = np.stack([np.where(f >= 0, tri_poly[np.maximum(f, 0)], -1)
                                        for f in (self.face_a, self.face_b)], axis=1)
        return self.edge_polys


def first_two_faces(tri_edges, edge_count):
    """(first, second): for each of `edge_count` edges the first two triangles that use it, in
    triangle order (-1 where none). tri_edges: (T, 3) the edge of each triangle side
    (scene_sync.triangle_edge_map), native.NO_EDGE for a polygon's diagonal."""
    sides = tri_edges.reshape(-1).astype(np.int64)
    faces = np.repeat(np.arange(len(tri_edges)), 3)
    keep = sides != native.NO_EDGE
    sides, faces = sides[keep], faces[keep]
    order = np.argsort(sides, kind="stable")
    sides, faces = sides[order], faces[order]
    first = np.full(edge_count, -1, np.int64)
    second = np.full(edge_count, -1, np.int64)
    starts = np.flatnonzero(np.r_[True, sides[1:] != sides[:-1]]) if len(sides) else np.array([], np.int64)
    first[sides[starts]] = faces[starts]
    nxt = starts + 1
    ok = nxt < len(sides)
    nxt, st = nxt[ok], starts[ok]
    same = sides[nxt] == sides[st]
    second[sides[st[same]]] = faces[nxt[same]]
    return first, second
