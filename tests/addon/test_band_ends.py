"""Where bands end (addon/geometry/band_ends.py), on meshes small enough to know the answer: a box's
corners (every edge rounded: mitres at 45 degrees), a box edge cut by a collinear vertex (square
ends where the pieces meet), a box with unrounded sides (square ends, the corner being a right
angle), and a wedge whose acute face corner cuts the band along its side."""
import math
import unittest

import numpy as np

from addon_modules import addon_module
from small_meshes import box, edge_frame, mesh

band_ends = addon_module("geometry.band_ends")
radius_clamp = addon_module("geometry.radius_clamp")


def angles(positions, edges, polys, tris, rounded):
    normals, faces = edge_frame(positions, edges, polys, tris)
    sel = np.arange(len(edges))
    return band_ends.end_angles(polys, positions, normals, edges, sel, faces, rounded)


def prism(outline):
    """A prism of height 1 over a counter-clockwise outline in the xy plane: the outline's index
    i at z = 0, i + n at z = 1; the top face is polygon 1."""
    n = len(outline)
    verts = [(x, y, 0.0) for x, y in outline] + [(x, y, 1.0) for x, y in outline]
    polys = [list(range(n))[::-1], [i + n for i in range(n)]]
    polys += [[i, (i + 1) % n, (i + 1) % n + n, i + n] for i in range(n)]
    return mesh(verts, polys)


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

    def test_outer_side_of_a_turn_mitres_past_the_vertex(self):
        """A top face with a reflex corner (the outer side of a turn, as a shoulder round a boss's
        rim), its outline rounded: where the vertex joins two rounded edges alone, they meet on
        the corner's bisector, which leans past their vertex (theta / 2 past square, at most
        3 pi / 4); with the concave edge into the corner rounded too, or the neighbouring side
        not rounded, the band ends square."""
        for reflex_deg in (200.0, 270.0, 320.0):
            half = math.radians(reflex_deg - 180.0) / 2.0
            # A rectangle whose top side dips at its middle vertex 3, turning there by twice half.
            outline = [(0.0, 0.0), (2.0, 0.0), (2.0, 4.0), (1.0, 4.0 - math.tan(half)), (0.0, 4.0)]
            positions, edges, polys, tris = prism(outline)
            n = len(outline)
            index = [tuple(x) for x in edges.tolist()]
            top = np.array([max(e) >= n and min(e) >= n for e in index])  # the top face's outline
            sides = [index.index((n + 2, n + 3)), index.index((n + 3, n + 4))]  # its sides at the dip

            def cut_at_dip(out, e):
                end = 0 if edges[e, 0] == n + 3 else 1
                return out[e, 2 * end:2 * end + 2]

            out = angles(positions, edges, polys, tris, top)
            want = min(math.radians(reflex_deg) / 2.0, 0.75 * math.pi)
            for e in sides:
                self.assertTrue(np.any(np.isclose(cut_at_dip(out, e), want, atol=1e-5)), (reflex_deg, out[e]))
            # The concave edge into the corner rounded too: a corner of three fillets.
            concave = top.copy()
            concave[index.index((3, n + 3))] = True
            out = angles(positions, edges, polys, tris, concave)
            for e in sides:
                self.assertTrue(np.any(np.isclose(cut_at_dip(out, e), math.pi / 2, atol=1e-6)), (reflex_deg, out[e]))
            # The neighbouring side not rounded.
            one = top.copy()
            one[sides[0]] = False
            out = angles(positions, edges, polys, tris, one)
            self.assertTrue(np.any(np.isclose(cut_at_dip(out, sides[1]), math.pi / 2, atol=1e-6)), out[sides[1]])


class AgainstTheReference(unittest.TestCase):
    def test_the_library_ends_the_bands_as_the_reference_does(self):
        """el_band_ends against the numpy it replaced (band_ends_reference.py): boxes, cut
        boxes, prisms with acute and reflex corners and grid boxes (some jittered: facets folded
        a few degrees, smooth patches to walk round), random subsets rounded, with and without
        the smooth patches' fans: the same angles (within 1e-6)."""
        import band_ends_reference as reference
        from test_rounded_outline import grid_box
        rng = np.random.default_rng(31)
        meshes = [box(), box(cut=True), prism([(0, 0), (3, 0), (0, 1)]), prism([(0, 0), (2, 0), (2, 2), (1, 0.8), (0, 2)]),
                  grid_box(2), grid_box(3)]
        for n, jitter in ((2, 0.01), (3, 0.005)):
            positions, edges, polys, tris = grid_box(n)
            loops = [polys.loop_vert[a:a + k].tolist() for a, k in zip(polys.start, polys.total)]
            meshes.append(mesh(positions + rng.normal(scale=jitter, size=positions.shape), loops))
        mitred = square = 0
        for positions, edges, polys, tris in meshes:
            normals, faces = edge_frame(positions, edges, polys, tris)
            fold = np.degrees(np.arccos(np.clip(np.einsum("ek,ek->e", normals[:, :3], normals[:, 3:]), -1.0, 1.0)))
            edge_polys = np.where(faces >= 0, np.asarray(polys.tri_poly)[np.maximum(faces, 0)], -1)
            for _ in range(6):
                rounded = (fold > 30.0) & (rng.random(len(edges)) < 0.8)
                sel = np.flatnonzero(rounded | (rng.random(len(edges)) < 0.1))
                smooth = ~rounded & (fold < 30.0) & (faces >= 0).all(axis=1)
                for fans in (False, True):
                    args = (polys, positions, normals, edges, sel, faces[sel], rounded) + \
                        ((smooth, edge_polys) if fans else ())
                    got = band_ends.end_angles(*args)
                    want = reference.end_angles(*args)
                    np.testing.assert_allclose(got, want, atol=1e-6)
                    mitred += int((np.abs(got - np.pi / 2) > 1e-3).sum())
                    square += int((np.abs(got - np.pi / 2) <= 1e-3).sum())
        self.assertGreater(mitred, 200)
        self.assertGreater(square, 200)

if __name__ == "__main__":
    unittest.main()
