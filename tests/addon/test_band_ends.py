"""Where bands end (addon/band_ends.py), on meshes small enough to know the answer: a box's
corners (every edge rounded: mitres at 45 degrees), a box edge cut by a collinear vertex (square
ends where the pieces meet), a box with unrounded sides (square ends, the corner being a right
angle), and a wedge whose acute face corner cuts the band along its side."""
import math
import unittest

import numpy as np

from addon_modules import addon_module
from small_meshes import box, edge_frame, mesh

band_ends = addon_module("band_ends")
radius_clamp = addon_module("radius_clamp")


def angles(positions, edges, polys, tris, rounded):
    normals, faces = edge_frame(positions, edges, polys, tris)
    sel = np.arange(len(edges))
    return band_ends.end_angles(polys, positions, normals, edges, sel, faces, rounded)


class BandEnds(unittest.TestCase):
    def test_box_corners_mitre(self):
        positions, edges, polys, tris = box()
        out = angles(positions, edges, polys, tris, np.ones(len(edges), bool))
        np.testing.assert_allclose(out, math.pi / 4, atol=1e-6)

    def test_unrounded_sides_end_square(self):
        positions, edges, polys, tris = box()
        out = angles(positions, edges, polys, tris, np.zeros(len(edges), bool))
        np.testing.assert_allclose(out, math.pi / 2, atol=1e-6)

    def test_collinear_pieces_meet_square(self):
        positions, edges, polys, tris = box(cut=True)
        rounded = np.ones(len(edges), bool)
        out = angles(positions, edges, polys, tris, rounded)
        for piece in ((1, 8), (5, 8)):
            e = [tuple(sorted(x)) for x in edges.tolist()].index(tuple(sorted(piece)))
            end = 0 if edges[e, 0] == 8 else 1  # the end at the cut vertex: both faces square
            np.testing.assert_allclose(out[e, 2 * end:2 * end + 2], math.pi / 2, atol=1e-6)
            np.testing.assert_allclose(out[e, 2 * (1 - end):2 * (1 - end) + 2], math.pi / 4, atol=1e-6)

    def test_a_face_wound_the_other_way_changes_nothing(self):
        """The library orients faces a file has flipped, and gives N1 / N2 as oriented; the
        polygons keep the file's winding. Which face is which comes from the normals."""
        positions, edges, polys, tris = box()
        normals, faces = edge_frame(positions, edges, polys, tris)
        rounded = np.arange(len(edges)) % 3 != 0  # some mitres, some square ends: sides differ
        sel = np.arange(len(edges))
        good = band_ends.end_angles(polys, positions, normals, edges, sel, faces, rounded)
        flipped = radius_clamp.Polygons(polys.start, polys.total, polys.loop_vert.copy(), polys.tri_poly,
                                        polys.loop_edge.copy(), polys.normal.copy())
        p = 1  # the top: its loops reversed, as the file would store them
        a, n = polys.start[p], polys.total[p]
        verts = polys.loop_vert[a:a + n][::-1]
        flipped.loop_vert[a:a + n] = verts
        key = {tuple(sorted(e)): i for i, e in enumerate(edges.tolist())}
        flipped.loop_edge[a:a + n] = [key[tuple(sorted((verts[i], verts[(i + 1) % n])))] for i in range(n)]
        flipped.normal[p] = -polys.normal[p]
        bad = band_ends.end_angles(flipped, positions, normals, edges, sel, faces, rounded)
        np.testing.assert_allclose(bad, good, atol=1e-6)

    def test_acute_corner_cuts_along_its_side(self):
        # A wedge: a triangular prism whose end faces have a 30-degree corner at the ridge's foot.
        a = math.radians(30.0)
        verts = [(0, 0, 0), (1, 0, 0), (math.cos(a), 0, math.sin(a)),
                 (0, 1, 0), (1, 1, 0), (math.cos(a), 1, math.sin(a))]
        polys = [[0, 2, 1], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [0, 3, 5, 2]]
        positions, edges, polys_, tris = mesh(verts, polys)
        rounded = np.zeros(len(edges), bool)
        e = [tuple(x) for x in edges.tolist()].index((0, 3))  # the edge along y at the acute corner
        rounded[e] = True
        out = angles(positions, edges, polys_, tris, rounded)
        # On both faces at both ends the next side is the end face's, 90 degrees away: square.
        np.testing.assert_allclose(out[e], math.pi / 2, atol=1e-6)
        # The end faces' own edges see the acute corner: the bottom edge (0, 1) on the end face
        # meets the slanted side at 30 degrees, so that band is cut along the side.
        rounded[:] = True
        out = angles(positions, edges, polys_, tris, rounded)
        f = [tuple(x) for x in edges.tolist()].index((0, 1))
        self.assertTrue(np.any(np.isclose(out[f], a / 2, atol=1e-6)), out[f])


if __name__ == "__main__":
    unittest.main()
