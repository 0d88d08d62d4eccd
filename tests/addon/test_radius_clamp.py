"""The radius clamp's widths (addon/geometry/radius_clamp.py) on patches small enough to know the answer:
a flat face triangulated into many small triangles is as wide to a fillet as the whole face, a
faceted curved patch as its surface is long, and a walk across either stops at the first edge
that ends the patch."""
import math
import unittest

import numpy as np

from addon_modules import addon_module
from small_meshes import mesh

radius_clamp = addon_module("geometry.radius_clamp")


def edge_polygons(edges, polys):
    """(E, 2) each edge's first two polygons (-1: none)."""
    out = np.full((len(edges), 2), -1)
    poly_of_loop = np.repeat(np.arange(len(polys.start)), polys.total)
    for loop, e in enumerate(polys.loop_edge):
        out[e, 0 if out[e, 0] < 0 else 1] = poly_of_loop[loop]
    return out


def edge_index(edges, a, b):
    return [tuple(x) for x in edges.tolist()].index((min(a, b), max(a, b)))


def triangulated_plate(nx=10, ny=4):
    """A flat nx by ny plate of unit cells, each cut into two triangles (polygons of their own)."""
    verts = [(x, y, 0.0) for y in range(ny + 1) for x in range(nx + 1)]
    at = lambda x, y: y * (nx + 1) + x  # noqa: E731
    polys = []
    for y in range(ny):
        for x in range(nx):
            polys += [[at(x, y), at(x + 1, y), at(x + 1, y + 1)], [at(x, y), at(x + 1, y + 1), at(x, y + 1)]]
    return mesh(verts, polys), at


def folded_strip(facets, fold_deg):
    """Unit-wide quads along y, each folded `fold_deg` from the last about the x axis, 3 long in x."""
    verts, y, z, turn = [], 0.0, 0.0, 0.0
    for k in range(facets + 1):
        verts += [(0.0, y, z), (3.0, y, z)]
        y, z = y + math.cos(turn), z + math.sin(turn)
        turn += math.radians(fold_deg)
    polys = [[2 * k, 2 * k + 1, 2 * k + 3, 2 * k + 2] for k in range(facets)]
    return mesh(verts, polys)


def walk(m, edge, stop, cap):
    positions, edges, polys, _ = m
    ep = edge_polygons(edges, polys)
    sel = np.array([edge])
    return radius_clamp.patch_walks(polys, positions, edges, ep, stop, sel, ep[sel, 0], np.array([cap]))[0]


class PatchWalks(unittest.TestCase):
    def test_triangulated_plate_is_as_wide_as_the_plate(self):
        (positions, edges, polys, tris), at = triangulated_plate()
        border = edge_polygons(edges, polys)[:, 1] < 0
        e = edge_index(edges, at(4, 0), at(5, 0))
        # Its own triangle is one cell wide; the walk crosses four rows of diagonals and sides.
        w = radius_clamp.widths(polys, positions, edges[[e]], np.array([[tris.tolist().index(
            next(t for t in tris.tolist() if at(4, 0) in t and at(5, 0) in t)), -1]]))[0, 0]
        self.assertAlmostEqual(w, 1.0, places=9)
        self.assertAlmostEqual(walk((positions, edges, polys, tris), e, border, 100.0), 4.0, places=9)
        self.assertAlmostEqual(walk((positions, edges, polys, tris), e, border, 2.5), 2.5, places=9)

    def test_a_stop_edge_ends_the_patch(self):
        (positions, edges, polys, tris), at = triangulated_plate()
        stop = edge_polygons(edges, polys)[:, 1] < 0
        stop[edge_index(edges, at(4, 3), at(5, 3))] = True  # a rounded edge across the walk's path
        e = edge_index(edges, at(4, 0), at(5, 0))
        self.assertAlmostEqual(walk((positions, edges, polys, tris), e, stop, 100.0), 3.0, places=9)

    def test_faceted_curve_is_as_wide_as_its_surface_is_long(self):
        m = folded_strip(6, 10.0)
        positions, edges, polys, _ = m
        stop = edge_polygons(edges, polys)[:, 1] < 0
        first = edge_index(edges, 0, 1)
        self.assertAlmostEqual(walk(m, first, stop, 100.0), 6.0, places=6)
        stop[edge_index(edges, 6, 7)] = True  # the fold after the third facet ends the patch
        self.assertAlmostEqual(walk(m, first, stop, 100.0), 3.0, places=6)

    def test_a_walk_through_a_fans_centre_goes_on(self):
        """A disc cut into a fan of triangles (a cylinder's cap as files store it): the walk from a
        rim side's middle passes through the centre vertex and ends at the opposite rim side,
        2 R cos(pi / n) away, as across the same disc as one polygon."""
        n = 16
        rim = [(math.cos(2 * math.pi * (k + 0.5) / n), math.sin(2 * math.pi * (k + 0.5) / n), 0.0) for k in range(n)]
        fan = mesh(rim + [(0.0, 0.0, 0.0)], [[k, (k + 1) % n, n] for k in range(n)])
        disc = mesh(rim, [list(range(n))])
        want = 2.0 * math.cos(math.pi / n)
        for m in (fan, disc):
            positions, edges, polys, _ = m
            stop = edge_polygons(edges, polys)[:, 1] < 0
            self.assertAlmostEqual(walk(m, edge_index(edges, 0, 1), stop, 100.0), want, places=3)

    def test_across_patches_widens_only_what_is_short(self):
        (positions, edges, polys, tris), at = triangulated_plate()
        ep = edge_polygons(edges, polys)
        stop = ep[:, 1] < 0
        sel = np.array([edge_index(edges, at(4, 0), at(5, 0)), edge_index(edges, at(4, 4), at(5, 4))])
        given = np.array([[1.0, 0.0], [1.0, 0.0]])
        out = radius_clamp.across_patches(polys, positions, edges, ep, stop, sel, given, np.array([3.0, 0.5]))
        np.testing.assert_allclose(out[:, 0], [3.0, 1.0])   # walked up to its need; already wide enough
        # A right-angle fillet of radius r sets back r: two across a 4-wide plate fit up to r = 2.
        wide = radius_clamp.across_patches(polys, positions, edges, ep, stop, sel[:1], given[:1], np.array([100.0]))
        self.assertAlmostEqual(float(radius_clamp.max_radius(wide[:, :1], np.array([90.0]))[0]), 2.0, places=9)


class WidthBounds(unittest.TestCase):
    def test_a_lower_bound_exact_on_rectangles(self):
        """width_bounds never exceeds widths (it looks at three corners of each polygon, 0, 1
        and 2 of a quad); on rectangles it is the width."""
        for m, exact in ((triangulated_plate()[0], False), (folded_strip(6, 10.0), True)):
            positions, edges, polys, tris = m
            positions = positions.astype(np.float32)  # as Blender's (the library reads float32)
            ep = edge_polygons(edges, polys)
            inner = np.flatnonzero(ep[:, 1] >= 0)
            tri_of_poly = {int(p): t for t, p in enumerate(polys.tri_poly)}
            faces = np.vectorize(lambda p: tri_of_poly[int(p)])(ep[inner])
            full = radius_clamp.widths(polys, positions, edges[inner], faces)
            bound = radius_clamp.width_bounds(polys, positions, edges[inner], ep[inner])
            self.assertTrue(np.all(bound <= full + 1e-12))
            if exact:
                np.testing.assert_allclose(bound, full, atol=1e-12)

    def test_the_library_bounds_as_the_reference_does(self):
        """el_width_bounds against the numpy it replaced (radius_clamp_reference.py): grid boxes
        jittered and whole, the plate, the strip, every edge, one side missing on some: the same
        bounds (within 1e-12 of their size)."""
        import radius_clamp_reference as reference
        from test_rounded_outline import grid_box
        rng = np.random.default_rng(41)
        meshes = [triangulated_plate()[0], folded_strip(6, 10.0), grid_box(2), grid_box(4)]
        positions, edges, polys, tris = grid_box(3)
        loops = [polys.loop_vert[a:a + k].tolist() for a, k in zip(polys.start, polys.total)]
        meshes.append(mesh(positions + rng.normal(scale=0.02, size=positions.shape), loops))
        for positions, edges, polys, tris in meshes:
            positions = positions.astype(np.float32)  # as Blender's (the library reads float32)
            ep = edge_polygons(edges, polys)
            ep[rng.random(len(ep)) < 0.1, 1] = -1
            got = radius_clamp.width_bounds(polys, positions, edges, ep)
            want = reference.width_bounds(polys, positions, edges, ep)
            np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)
            self.assertTrue(np.all(got[ep[:, 1] < 0, 1] == 0.0))


if __name__ == "__main__":
    unittest.main()
