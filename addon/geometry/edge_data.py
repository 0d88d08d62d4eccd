"""Per-edge data of one extracted mesh that the edge and line choices read: the library's
classification (numpy copies) and which triangles each edge joins. No bpy: plain-Python tests
import it."""
from dataclasses import dataclass

import numpy as np

from ..bridge import native
from . import radius_clamp


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
    tri_verts: np.ndarray = None       # (T, 3) each triangle's vertices
    corner_nor: np.ndarray = None      # (T, 3, 3) Blender's shading normal at each triangle corner

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


# A side's shading normal further than this from its face's own normal is not taken (a custom
# normal pointing elsewhere, a corner fan folded over): the face's normal stands. Smooth shading
# of facets folded by less than the 30-degree sharp-edge angle turns it by under 15 degrees; the
# band's plane (edge_highlight.frag's visibility over other facets) is square to it, so it
# must stay near the face's.
MAX_SHADING_TURN_DEG = 20.0


def shading_normals(d, sel, normals):
    """(N, 2, 6) the two normals a rounded edge's arc runs between at each of its ends (p0, then
    p1), as the library gives them (N1, N2: `normals`, the faces' own), each turned to the
    normal the surface is shaded with on that side there: its triangle's corner normal at that
    end. A smooth-shaded curved face meets a fillet with its interpolated normal, not its flat
    one (the arc from the flat normal left a seam along every rounded edge of a smooth part),
    and that normal changes along the edge (a smooth cylinder's rim: one arc per edge made its
    bands dashes); on flat faces the two are the same. The edge keeps its faces' normals at both
    ends where a corner normal at either end is missing or turned too far, or where taking them
    would turn the arc round. The library's el_shading_normals."""
    if d.corner_nor is None or d.tri_verts is None or not len(sel):
        lib = np.asarray(normals[sel], np.float32).reshape(-1, 1, 6)
        return np.ascontiguousarray(np.repeat(lib, 2, axis=1))
    return native.shading_normals(d.positions, d.edges, normals, np.stack([d.face_a, d.face_b], axis=1),
                                  d.tri_verts, d.corner_nor, sel, MAX_SHADING_TURN_DEG)


def mean_and_turn(at_ends):
    """(normals, turn) of shading_normals' (N, 2, 6): each side's normal halfway along the edge
    (the ends' mean, unit) and how it changes from p0 to p1 over the mean's length, (N, 6) each:
    at t along the edge (0 at p0) the side's normal is normalize(normal + (t - 1/2) turn), the
    normal Blender's interpolation shades the face with there (el_edge_frame)."""
    a = at_ends[:, 0].astype(np.float64).reshape(-1, 2, 3)
    b = at_ends[:, 1].astype(np.float64).reshape(-1, 2, 3)
    mean = 0.5 * (a + b)
    length = np.maximum(np.linalg.norm(mean, axis=2, keepdims=True), 1e-30)
    return ((mean / length).reshape(-1, 6).astype(np.float32),
            ((b - a) / length).reshape(-1, 6).astype(np.float32))


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

def surface_ids(edge_data, faces):
    """Triangle indices (-1: none) -> the ids the surface pass writes for them (0: none), as
    float32 (exact below 2^24 triangles per object)."""
    faces = np.asarray(faces, np.int64)
    ids = np.where(faces >= 0, edge_data.surface_id[np.maximum(faces, 0)], 0)
    return np.ascontiguousarray(ids, np.float32)
