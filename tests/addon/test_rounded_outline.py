"""Which rounded edges each surface triangle lists for the strip a rounded silhouette leaves out
(addon/geometry/rounded_outline.py), on meshes small enough to know the answer: a box (each half of a
face lists its own sides first, then its quad's other two, which touch its corners), a box whose
faces are grids of quads (the strip's triangles reach across the facets along an edge, as far as
the fillet's setback, and no farther), a cylinder whose cap's long triangles cut across its rims'
reach, an L-shaped prism (its concave edge is listed nowhere: a concave fillet moves no
outline in), and a box with unrounded edges (nothing to list)."""
import types
import unittest

import numpy as np

import rounded_outline_reference as reference
from addon_modules import addon_module
from small_meshes import box, edge_frame, mesh

rounded_outline = addon_module("geometry.rounded_outline")
edge_choice = addon_module("geometry.edge_choice")
corner_patches = addon_module("geometry.corner_patches")
native = addon_module("bridge.native")


def extract_of(positions, edges, polys, tris, rounded, radius=0.1, corners=False):
    """The parts of a MeshExtract that rounded_outline reads: one slot, the triangles in order
    (surface id = triangle + 1), the rounded edges' EdgeSet (with its corner patches)."""
    normals, faces = edge_frame(positions, edges, polys, tris)
    sel = np.flatnonzero(rounded)
    e = edge_choice.EdgeSet(positions[edges[sel, 0]], positions[edges[sel, 1]], normals[sel, :3], normals[sel, 3:],
                            np.full(len(sel), radius, np.float32), faces=(faces[sel] + 1).astype(np.float32),
                            verts=edges[sel])
    if corners:
        e.corners = corner_patches.find(edges, positions, normals, np.ones(len(edges), bool), np.asarray(rounded, bool),
                                        np.full(len(edges), radius, np.float32))
    # The library's classes: convex where N1 x N2 runs along the edge (N1's face runs p0 -> p1).
    n1, n2 = normals[:, :3].astype(float), normals[:, 3:].astype(float)
    along = np.einsum("ij,ij->i", np.cross(n1, n2), positions[edges[:, 1]] - positions[edges[:, 0]])
    flags = np.where(along >= 0.0, native.EDGE_CONVEX, native.EDGE_CONCAVE)
    angles = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", n1, n2), -1.0, 1.0)))
    data = types.SimpleNamespace(polygons=polys, tri_verts=tris, flags=flags, angles=angles, edges=edges)
    return types.SimpleNamespace(
        slot_triangles={0: np.arange(len(tris))}, corner_pos=positions[tris.reshape(-1)],
        edges={0: e} if len(sel) else {}, edge_data=data), sel


def grid_box(n):
    """A unit box whose faces are n x n grids of quads."""
    index, verts, polys_list = {}, [], []

    def vert(p):
        key = tuple(round(c, 6) for c in p)
        if key not in index:
            index[key] = len(verts)
            verts.append(key)
        return index[key]
    for axis in range(3):
        for side in (0.0, 1.0):
            u, v = [a for a in range(3) if a != axis]
            for i in range(n):
                for j in range(n):
                    quad = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0.0, 0.0, 0.0]
                        p[axis], p[u], p[v] = side, (i + di) / n, (j + dj) / n
                        quad.append(vert(p))
                    polys_list.append(quad if (side == 1.0) == (axis != 1) else quad[::-1])
    return mesh(verts, polys_list)


def cylinder(n=32):
    """A cylinder of radius 0.5 and height 1 with n sides, its top cap triangulated as a zigzag
    (as Blender's polyfill does, with chords spanning several rim segments) and the rest as fans;
    and the top cap's triangles."""
    ring = [(0.5 * np.cos(2 * np.pi * k / n), 0.5 * np.sin(2 * np.pi * k / n)) for k in range(n)]
    verts = [(x, y, 0.0) for x, y in ring] + [(x, y, 1.0) for x, y in ring]
    top = list(range(n, 2 * n))
    polys_list = [top, list(range(n))[::-1]] + [[k, (k + 1) % n, n + (k + 1) % n, n + k] for k in range(n)]
    positions, edges, polys, tris = mesh(verts, polys_list)
    zigzag, lo, hi = [], 0, n - 1
    while hi - lo > 1:
        if len(zigzag) % 2 == 0:
            zigzag.append((top[lo], top[lo + 1], top[hi]))
            lo += 1
        else:
            zigzag.append((top[lo], top[hi - 1], top[hi]))
            hi -= 1
    tris[:n - 2] = zigzag
    return positions, edges, polys, tris, np.arange(n - 2)


R_CAP = 0.06


def box_edges(positions, edges):
    """(E,) bool: the edges lying on the box's 12 edges."""
    return np.array([sum(positions[a][k] == positions[b][k] and positions[a][k] in (0.0, 1.0) for k in range(3)) == 2
                     for a, b in edges])


def listed(lists):
    """Per triangle, the set of listed edges' numbers."""
    return [set(int(x) - 1 for x in row[:rounded_outline.EDGES_PER_TRIANGLE] if x > 0) for row in lists]


def l_prism():
    """An L-shaped prism, its outline's corner (1, 1) reflex: (positions, edges, polys, tris) and
    the outline's vertex count n (the reflex edge runs from vertex 3 to 3 + n)."""
    outline = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    n = len(outline)
    verts = [(x, y, 0.0) for x, y in outline] + [(x, y, 1.0) for x, y in outline]
    polys_list = [list(range(n))[::-1], [i + n for i in range(n)]]
    polys_list += [[i, (i + 1) % n, (i + 1) % n + n, i + n] for i in range(n)]
    return (*mesh(verts, polys_list), n)


class RoundedOutline(unittest.TestCase):
    def test_box_halves_list_their_quad(self):
        positions, edges, polys, tris = box()
        ex, sel = extract_of(positions, edges, polys, tris, np.ones(len(edges), bool))
        recs, _, lists = rounded_outline.records(ex)
        self.assertEqual(len(recs), 12)
        np.testing.assert_allclose(recs[:, 0, 3], 0.1)
        rows = lists[0]
        for t, row in enumerate(rows):
            quad = polys.tri_poly[t]
            sides = set(polys.loop_edge[polys.start[quad]:polys.start[quad] + 4])
            self.assertEqual(set(sel[list(listed([row])[0])]), sides, f"triangle {t}")
            # The first two are its own sides: both their ends are its corners.
            for k in range(2):
                ends = positions[edges[sel[int(row[k]) - 1]]]
                corners = positions[tris[t]]
                self.assertTrue(all(np.any(np.all(corners == p, axis=1)) for p in ends), f"triangle {t} slot {k}")

    def test_strip_reaches_across_facets(self):
        """A unit box whose faces are 8 x 8 grids (cells 0.125 wide), only its 12 box edges
        rounded, r = 0.3: a face may show in the strip out to the fillet's setback, r tan 45° =
        0.3 (the strip itself is at most r (sqrt 2 - 1) = 0.124 wide, but a face seen at a
        grazing angle folds its image over it from farther), so the bottom face's triangles
        list the edge along y = 0 out to the row of cells at 0.25-0.375 (its near corners within
        reach) and not the row beyond."""
        n = 8
        positions, edges, polys, tris = grid_box(n)
        on_box_edge = box_edges(positions, edges)
        ex, sel = extract_of(positions, edges, polys, tris, on_box_edge, radius=0.3)
        recs, _, lists = rounded_outline.records(ex)
        self.assertEqual(len(recs), n * 12)
        # The bottom face (z = 0): its triangles' centres, and whether they list an edge piece
        # on y = 0, z = 0.
        along = [k for k in range(len(recs)) if np.all(recs[k, 2:4, 1:3] == 0.0)]
        self.assertEqual(len(along), n)
        # Away from the corners, where the pieces of the edges along x = 0 and x = 1 are nearer.
        bottom = [t for t in range(len(tris)) if np.all(positions[tris[t], 2] == 0.0)
                  and 0.375 <= positions[tris[t], 0].min() and positions[tris[t], 0].max() <= 0.625]
        for t in bottom:
            y = positions[tris[t], 1].min()
            lists_it = bool(listed([lists[0][t]])[0] & set(along))
            if y >= 0.375:
                self.assertFalse(lists_it, f"triangle {t} at y >= {y}")
            else:
                self.assertTrue(lists_it, f"triangle {t} at y >= {y}")

    def test_a_cap_lists_every_rim_whose_reach_its_triangles_cross(self):
        """A 32-sided cylinder's rims rounded at r = 0.06 (its setback r at 90 degrees, under
        the rim's segment length, 0.098): a cap triangle lists a rim edge exactly where it comes
        within r of it (measured on points 1/400 of a side apart; up to eight rims). Its long triangles' chords
        cut across the reach of rim edges none of whose vertices they touch; walked only
        through corners within reach, those were missed, and the cap's silhouette kept sharp
        pieces of its outline."""
        positions, edges, polys, tris, cap = cylinder()
        rim = np.array([positions[a, 2] == positions[b, 2] for a, b in edges])
        ex, sel = extract_of(positions, edges, polys, tris, rim, radius=R_CAP)
        recs, _, lists = rounded_outline.records(ex)
        t = np.linspace(0.0, 1.0, 401)[:, None]
        u = np.linspace(0.0, 1.0, 101)[:, None]  # a rim edge is a tenth of a cap's side long
        along = (recs[:, None, 2, :3] + u[None] * (recs[:, None, 3, :3] - recs[:, None, 2, :3])).reshape(-1, 3)
        misses = extras = 0
        for c in cap:
            corners = positions[tris[c]]
            sides = np.concatenate([a + t * (b - a) for a, b in zip(corners, np.roll(corners, -1, axis=0))])
            # Each rim edge's distance from the triangle's sides (both lie in the cap's plane).
            d = np.sqrt(((sides[:, None, :2] - along[None, :, :2]) ** 2).sum(axis=2)).min(axis=0).reshape(len(recs), -1)
            d = d.min(axis=1) + np.abs(recs[:, 2, 2] - 1.0)  # the bottom rim lies 1 below
            got = listed([lists[0][c]])[0]
            self.assertLessEqual(int(np.sum(d < R_CAP + 0.003)), rounded_outline.EDGES_PER_TRIANGLE, f"triangle {c}")
            misses += sum(1 for k in np.flatnonzero(d < R_CAP - 0.003) if k not in got)
            extras += sum(1 for k in np.flatnonzero(d > R_CAP + 0.003) if k in got)
        self.assertEqual((misses, extras), (0, 0))

    def test_corner_zone_reaches_across_facets(self):
        """The grid box (cells 0.25), its box edges rounded at r = 0.3: each corner's zone reaches
        r sqrt 3 = 0.52 from its vertex, so on the bottom face the cell at 0.25-0.5 on both sides
        of the corner at the origin lists it (past the vertex's own fan), and every triangle
        listing a corner has a vertex within that reach of it."""
        positions, edges, polys, tris = grid_box(4)
        ex, _ = extract_of(positions, edges, polys, tris, box_edges(positions, edges), radius=0.3, corners=True)
        _, corners, lists = rounded_outline.records(ex)
        self.assertEqual(len(corners), 8)
        origin = [k for k in range(8) if np.allclose(corners[k, 1, :3], 0.0)]
        self.assertEqual(len(origin), 1)
        per = rounded_outline.EDGES_PER_TRIANGLE
        # The cell's half with a corner at (0.25, 0.25), 0.35 from the vertex (the other half's
        # nearest point is 0.53 away).
        cell = [t for t in range(len(tris)) if np.all(positions[tris[t], 2] == 0.0)
                and positions[tris[t], :2].min() >= 0.25 and positions[tris[t], :2].max() <= 0.5
                and np.any(np.all(positions[tris[t], :2] == 0.25, axis=1))]
        self.assertEqual(len(cell), 1)
        for t in cell:
            self.assertIn(origin[0] + 1, lists[0][t, per:].tolist(), f"triangle {t}")
        for t, row in enumerate(lists[0]):
            for k in (int(x) - 1 for x in row[per:] if x > 0):
                near = np.linalg.norm(positions[tris[t]] - corners[k, 1, :3], axis=1).min()
                self.assertLess(near, 0.3 * np.sqrt(3.0) + 1e-6, f"triangle {t} corner {k}")

    def test_fans_and_walk_agree(self):
        """Faces wider than the strips take the fans of the edges' ends alone, unsorted; the
        walk across patches, forced, lists the same edges per triangle (a box and a prism with a
        reflex corner)."""
        positions, edges, polys, tris = box()
        ex, _ = extract_of(positions, edges, polys, tris, np.ones(len(edges), bool))
        fast = rounded_outline.records(ex)[2][0]
        thinnest = rounded_outline._thinnest
        rounded_outline._thinnest = lambda *args: 0.0
        try:
            walked = rounded_outline.records(ex)[2][0]
        finally:
            rounded_outline._thinnest = thinnest
        self.assertEqual(listed(fast), listed(walked))
        self.assertTrue(all(len(x) == 4 for x in listed(fast)))

    def test_the_librarys_fans_are_the_references(self):
        """el_outline_fans against the numpy it replaced (rounded_outline_reference.fans): grid
        boxes of 1 to 4 quads a side, the triangles in shuffled batch orders, random subsets of
        the edges (their faces' normals, some turned off the faces) and of the vertices as
        corners, lists of 2 to 8: the same lists, slot for slot."""
        rng = np.random.default_rng(9)
        radius_clamp = addon_module("geometry.radius_clamp")
        listed_any = 0
        for n in (1, 2, 3, 4):
            positions, edges, polys, tris = grid_box(n)
            normals, _ = edge_frame(positions, edges, polys, tris)
            tri_normal = np.asarray(polys.normal, np.float32)[np.asarray(polys.tri_poly)]
            for _ in range(6):
                order = rng.permutation(len(tris))
                pick = rng.random(len(edges)) < 0.4
                verts = edges[pick]
                item_normals = normals[pick].reshape(-1, 2, 3).astype(np.float32)
                turn = rng.random(len(verts)) < 0.3
                item_normals[turn] = rng.normal(size=(int(turn.sum()), 2, 3)).astype(np.float32)
                item_normals /= np.linalg.norm(item_normals, axis=2, keepdims=True)
                per = int(rng.integers(2, 9))
                got = rounded_outline._fans(tris, tri_normal, order, verts, item_normals, per, verts)
                want = reference.fans(tris, tri_normal, order, verts, item_normals, per, verts,
                                      radius_clamp.SMOOTH_FOLD_DEG)
                np.testing.assert_array_equal(got, want, f"grid {n}, per {per}")
                corners = rng.choice(len(positions), size=len(positions) // 3, replace=False)
                sectors = rng.normal(size=(len(corners), 3, 3)).astype(np.float32)
                sectors[::2, 0] = tri_normal[rng.integers(0, len(tris), len(sectors[::2]))]
                sectors /= np.linalg.norm(sectors, axis=2, keepdims=True)
                got = rounded_outline._fans(tris, tri_normal, order, corners[:, None], sectors, per)
                want = reference.fans(tris, tri_normal, order, corners[:, None], sectors, per, None,
                                      radius_clamp.SMOOTH_FOLD_DEG)
                np.testing.assert_array_equal(got, want, f"grid {n} corners, per {per}")
                listed_any += int((got > 0).sum())
        self.assertGreater(listed_any, 100)

    def test_concave_edge_is_not_listed(self):
        positions, edges, polys, tris, n = l_prism()
        ex, sel = extract_of(positions, edges, polys, tris, np.ones(len(edges), bool))
        recs, _, lists = rounded_outline.records(ex)
        reflex = [i for i, (a, b) in enumerate(edges[sel]) if {a, b} == {3, 3 + n}]
        self.assertEqual(len(reflex), 1)
        self.assertEqual(len(recs), len(sel) - 1)
        # The records hold the convex edges' ends; none is the reflex edge's.
        ends = {tuple(sorted(map(tuple, r[2:4, :3].tolist()))) for r in recs}
        self.assertNotIn(tuple(sorted([tuple(positions[3]), tuple(positions[3 + n])])), ends)

    def test_convex_ends_at_a_concave_edge(self):
        """The L-shaped prism rounded at 0.1: the four convex edges that meet the reflex edge's
        ends (along the L's floor and riser, top and bottom) share a wall with it, square to it.
        Its fillet fills the corner 0.1 along each (its setback, r tan 45 deg), a tenth of their
        unit length, and its end arc lies in their other face (the cap): that cut, signed by
        the face, and the end's mark (a concave edge meets it) are in their records; every other
        end has neither."""
        positions, edges, polys, tris, n = l_prism()
        ex, sel = extract_of(positions, edges, polys, tris, np.ones(len(edges), bool))
        self.assertEqual([set(e) for e in edges[ex.edge_data.flags == native.EDGE_CONCAVE]], [{3, 3 + n}])
        recs, _, verts_of = rounded_outline._edges(ex)
        cuts, marks = recs[:, 2:4, 3], recs[:, 4:6, 3]
        at_reflex = np.isin(verts_of, (3, 3 + n))
        self.assertEqual(int(at_reflex.sum()), 4)
        np.testing.assert_allclose(np.abs(cuts[at_reflex]), 0.1, rtol=1e-5)
        np.testing.assert_array_equal(cuts[~at_reflex], 0.0)
        np.testing.assert_array_equal(marks, at_reflex.astype(np.float32))
        # The arc's face: the cap, the edge's face that is not the wall it shares.
        cap = np.abs(recs[:, 0:2, 2]) > 0.5  # N1, N2 along z
        for i, k in zip(*np.nonzero(at_reflex)):
            self.assertEqual(cuts[i, k] > 0.0, bool(cap[i, 1]), f"edge {i} end {k}")

    def test_nothing_rounded_lists_nothing(self):
        positions, edges, polys, tris = box()
        ex, _ = extract_of(positions, edges, polys, tris, np.zeros(len(edges), bool))
        self.assertIsNone(rounded_outline.records(ex))


if __name__ == "__main__":
    unittest.main()
