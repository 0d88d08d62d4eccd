"""Where corner patches go (addon/geometry/corner_patches.py), on meshes small enough to know the answer:
a box with every edge rounded (eight corners, the ball r under each face), a room's corner (three
concave edges: the ball r over each face, in the air), the same box with a
top edge cut by a collinear vertex (two rounded edges there: no corner; the eight stay), a box
whose vertical edges are not rounded (no corner), a box whose top face is a fan of triangles
(still eight corners: the sectors are sides of one face), a top folded along an unrounded
diagonal (no corner at its ends), and a needle-sharp pyramid tip (no corner: the ball would sit
far from the vertex).

    /usr/bin/python3 tests/addon/test_corner_patches.py
"""
import unittest

import numpy as np

from addon_modules import addon_module
from small_meshes import box, edge_frame, mesh

corner_patches = addon_module("geometry.corner_patches")


def corners(positions, edges, polys, tris, rounded, radius=0.1):
    """The corners, with every rounded edge and every unrounded fold past 30 degrees ending a
    face's smooth patch (as edge_choice gives them)."""
    normals, _ = edge_frame(positions, edges, polys, tris)
    e = positions[edges[:, 1]] - positions[edges[:, 0]]
    convex = np.einsum("ek,ek->e", np.cross(normals[:, :3], normals[:, 3:]), e) > 0.0
    fold = np.degrees(np.arccos(np.clip(np.einsum("ek,ek->e", normals[:, :3], normals[:, 3:]), -1.0, 1.0)))
    return corner_patches.find(edges, positions, normals, convex, rounded, np.full(len(edges), radius, np.float32),
                               rounded | (fold > 30.0))


class CornerPatches(unittest.TestCase):
    def test_box_corners(self):
        positions, edges, polys, tris = box()
        c = corners(positions, edges, polys, tris, np.ones(len(edges), bool))
        self.assertEqual(sorted(c.vertex), list(range(8)))
        # The ball's centre is r in from each of the three faces: the vertex moved 0.1 inwards
        # along every axis.
        inward = np.where(positions[c.vertex] > 0.5, -0.1, 0.1)
        np.testing.assert_allclose(c.centre, positions[c.vertex] + inward, atol=1e-6)
        np.testing.assert_allclose(np.abs(np.linalg.det(c.normals)), 1.0, atol=1e-6)
        np.testing.assert_allclose(c.radius, 0.1)
        np.testing.assert_array_equal(c.fold, 1.0)

    def test_inside_corner(self):
        # A room's corner: floor and two walls facing into the room. Three concave edges meet at
        # the origin; the ball rolls in the air, r over each face.
        v = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (0, 1, 1), (1, 0, 1)]
        positions, edges, polys, tris = mesh(v, [[0, 1, 2, 3], [0, 3, 5, 4], [0, 4, 6, 1]])
        at_origin = (edges == 0).any(axis=1)
        c = corners(positions, edges, polys, tris, at_origin)
        self.assertEqual(list(c.vertex), [0])
        self.assertEqual(float(c.fold[0]), -1.0)
        np.testing.assert_allclose(c.centre[0], [0.1, 0.1, 0.1], atol=1e-6)

    def test_smallest_radius(self):
        positions, edges, polys, tris = box()
        normals, _ = edge_frame(positions, edges, polys, tris)
        radius = np.full(len(edges), 0.1, np.float32)
        at_origin = np.flatnonzero((edges == 0).any(axis=1))
        radius[at_origin[0]] = 0.05
        c = corner_patches.find(edges, positions, normals, np.ones(len(edges), bool), np.ones(len(edges), bool), radius)
        k = list(c.vertex).index(0)
        self.assertAlmostEqual(float(c.radius[k]), 0.05)
        np.testing.assert_allclose(c.centre[k], [0.05, 0.05, 0.05], atol=1e-6)

    def test_unrounded_fold_inside_a_sector(self):
        # The top face as two triangles folded 35.3 degrees along their diagonal 1-7, which is
        # not rounded: at its ends the top is two faces, so no ball; the other corners stay.
        v = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
        v[5] = (1.0, 0.0, 0.5)
        polys_ = [[0, 2, 6, 4], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5], [1, 5, 7], [1, 7, 3]]
        positions, edges, polys, tris = mesh(v, polys_)
        diagonal = (edges == 1).any(axis=1) & (edges == 7).any(axis=1)
        c = corners(positions, edges, polys, tris, ~diagonal)
        self.assertEqual(sorted(c.vertex), [0, 2, 3, 4, 5, 6])

    def test_collinear_vertex_is_no_corner(self):
        positions, edges, polys, tris = box(cut=True)
        c = corners(positions, edges, polys, tris, np.ones(len(edges), bool))
        self.assertEqual(sorted(c.vertex), list(range(8)))

    def test_unrounded_sides_leave_no_corner(self):
        positions, edges, polys, tris = box()
        vertical = positions[edges[:, 0], 2] != positions[edges[:, 1], 2]
        c = corners(positions, edges, polys, tris, ~vertical)
        self.assertEqual(len(c), 0)

    def test_triangulated_face(self):
        # The top face (z = 1) as four triangles round a centre vertex: its diagonals are
        # edges now, flat, not rounded; each top corner's sector is two triangles of one plane.
        v = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)] + [(0.5, 0.5, 1.0)]
        ring = [1, 5, 7, 3]
        top = [[ring[i], ring[(i + 1) % 4], 8] for i in range(4)]
        polys_ = [[0, 2, 6, 4], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]] + top
        positions, edges, polys, tris = mesh(v, polys_)
        rounded = ~(edges == 8).any(axis=1)
        c = corners(positions, edges, polys, tris, rounded)
        self.assertEqual(sorted(c.vertex), list(range(8)))

    def test_needle_tip_is_no_corner(self):
        # A three-sided pyramid 20 times taller than wide: its tip's ball would sit ~20 r down.
        v = [(0, 0, 0), (1, 0, 0), (0.5, 0.87, 0), (0.5, 0.29, 20.0)]
        positions, edges, polys, tris = mesh(v, [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]])
        c = corners(positions, edges, polys, tris, np.ones(len(edges), bool))
        self.assertNotIn(3, list(c.vertex))
        self.assertEqual(sorted(c.vertex), [0, 1, 2])



class AgainstTheReference(unittest.TestCase):
    def test_the_library_finds_the_references_corners(self):
        """el_corner_patches against the numpy it replaced (corner_patches_reference.py): grid
        boxes and the box cut, their vertices jittered (folds of a few degrees either way),
        random subsets of the edges rounded at random radii, some edges flipped to concave,
        some extra stops: the same corners, vertex for vertex, edges, normals, radii and
        centres within float32 rounding."""
        import corner_patches_reference as reference
        from test_rounded_outline import grid_box
        rng = np.random.default_rng(21)
        found = 0
        for build, jitter in ((lambda: box(), 0.0), (lambda: box(cut=True), 0.0), (lambda: grid_box(2), 0.0),
                              (lambda: grid_box(3), 0.004), (lambda: grid_box(1), 0.02)):
            positions, edges, polys, tris = build()
            if jitter:
                loops = [polys.loop_vert[a:a + k].tolist() for a, k in zip(polys.start, polys.total)]
                positions, edges, polys, tris = mesh(positions + rng.normal(scale=jitter, size=positions.shape), loops)
            normals, _ = edge_frame(positions, edges, polys, tris)
            e = positions[edges[:, 1]] - positions[edges[:, 0]]
            convex = np.einsum("ek,ek->e", np.cross(normals[:, :3], normals[:, 3:]), e) > 0.0
            fold = np.degrees(np.arccos(np.clip(np.einsum("ek,ek->e", normals[:, :3], normals[:, 3:]), -1.0, 1.0)))
            for _ in range(8):
                rounded = (fold > 30.0) & (rng.random(len(edges)) < 0.8)
                flip = rng.random(len(edges)) < 0.1
                conv = convex ^ flip
                radius = rng.uniform(0.02, 0.3, len(edges)).astype(np.float32)
                stop = rounded | (fold > 30.0) | (rng.random(len(edges)) < 0.05)
                got = corner_patches.find(edges, positions, normals, conv, rounded, radius, stop)
                want = reference.find(edges, positions, normals, conv, rounded, radius, stop)
                np.testing.assert_array_equal(got.vertex, want.vertex)
                np.testing.assert_array_equal(got.edges, want.edges)
                for name in ("position", "normals", "radius", "centre", "fold"):
                    np.testing.assert_allclose(getattr(got, name), getattr(want, name), atol=2e-6, err_msg=name)
                found += len(got)
        self.assertGreater(found, 100)

if __name__ == "__main__":
    unittest.main()
