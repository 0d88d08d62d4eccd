"""The add-on's pure rules in plain Python (no Blender), on inputs small enough to know the answer:
which edges each material rounds (edge_choice.choose), the taper parameter of a line's
ends (lines.taper_params), the first two faces of each edge (edge_data.first_two_faces), and
the crease rule, which the add-on asks of the library (lines.crease_edges; needs the built
library: EDGELIGHT_LIBRARY, which ctest sets).

    EDGELIGHT_LIBRARY=build/native/libedgelight.so python3 tests/addon/test_pure_rules.py
"""
import math
import os
import types
import unittest
from dataclasses import dataclass

import numpy as np

from addon_modules import addon_module

native = addon_module("bridge.native")
lines = addon_module("linework.lines")
edge_data = addon_module("geometry.edge_data")
edge_choice = addon_module("geometry.edge_choice")
material_defaults = addon_module("extract.material_defaults")
clamp_counts = addon_module("geometry.radius_clamp_notes")

NO = native.NO_EDGE


class FirstTwoFaces(unittest.TestCase):
    def test_first_two_triangles_in_triangle_order(self):
        # Edges: 0 border (triangle 1 only), 1 between triangles 0 and 2, 2 used by three
        # triangles (0, 1, 3: the first two are kept), 3 unused, 4 only on a polygon diagonal.
        tri_edges = np.array([[1, 2, NO],
                              [2, 0, NO],
                              [NO, 1, NO],
                              [NO, NO, 2]], np.uint32)
        first, second = edge_data.first_two_faces(tri_edges, 5)
        self.assertEqual(first.tolist(), [1, 0, 0, -1, -1])
        self.assertEqual(second.tolist(), [-1, 2, 1, -1, -1])

    def test_repeated_side_of_one_triangle_counts_once_per_side(self):
        # A degenerate triangle naming edge 0 twice: its two sides are two uses, in side order.
        first, second = edge_data.first_two_faces(np.array([[0, 0, 1]], np.uint32), 2)
        self.assertEqual((first.tolist(), second.tolist()), ([0, 0], [0, -1]))

    def test_no_triangles(self):
        first, second = edge_data.first_two_faces(np.zeros((0, 3), np.uint32), 3)
        self.assertEqual((first.tolist(), second.tolist()), ([-1] * 3, [-1] * 3))


def chains(*rows):
    return np.array(list(rows), native.CHAIN)


def links(*rows):
    return np.array(list(rows), native.CHAIN_LINK)


class TaperParams(unittest.TestCase):
    def test_distance_to_the_nearest_free_end_over_the_chain_length(self):
        free = native.CHAIN_START_FREE | native.CHAIN_END_FREE
        c = chains((3, 4.0, free), (2, 2.0, native.CHAIN_START_FREE), (2, 2.0, native.CHAIN_END_FREE))
        got = lines.taper_params(links((0, 0.0, 1.0), (0, 1.0, 3.0), (0, 3.0, 4.0),
                                       (1, 0.0, 1.0), (2, 1.0, 2.0)), c)
        np.testing.assert_allclose(got, [[0.0, 0.25], [0.25, 0.25], [0.25, 0.0],
                                         [0.0, 0.5], [0.5, 0.0]])

    def test_an_end_without_a_free_end_on_its_chain_does_not_taper(self):
        got = lines.taper_params(links((0, 0.5, 1.5), (1, 0.0, 1.0)),
                                 chains((4, 2.0, native.CHAIN_CLOSED), (1, 1.0, 0)))
        self.assertTrue(np.all(got == lines.NO_TAPER))

    def test_no_links(self):
        self.assertEqual(lines.taper_params(links(), chains()).shape, (0, 2))


@dataclass(frozen=True)
class Shading:
    """The fields of materials.Shading that the edge choice reads (materials imports bpy)."""
    enabled: bool = material_defaults.ROUNDED
    K: float = material_defaults.HIGHLIGHT_STRENGTH
    radius: float = material_defaults.RADIUS
    rules: frozenset = material_defaults.EDGES
    angle_deg: float = material_defaults.ANGLE_DEG
    material: str = ""


MANIFOLD = native.EDGE_MANIFOLD


def edges_of(angles, sharp=None, bevel=None, flags=None, slots=(0, 0)):
    """EdgeData of len(angles) separate edges, edge i between triangles 2i and 2i + 1 (slots:
    the two triangles' material slots, or one pair per edge)."""
    n = len(angles)
    slots = np.array(slots if np.ndim(slots) == 2 else [slots] * n)
    positions = np.array([(i, j, 0.0) for i in range(n) for j in (0.0, 1.0)], np.float32)
    return edge_data.EdgeData(
        flags=np.array(flags if flags is not None else [MANIFOLD] * n, np.uint32),
        angles=np.array(angles, np.float32),
        normals=np.tile(np.array([0, 0, 1, 0, 1, 0], np.float32), (n, 1)),
        edges=np.arange(2 * n, dtype=np.uint32).reshape(n, 2),
        positions=positions,
        face_a=np.arange(n, dtype=np.int64) * 2,
        face_b=np.arange(n, dtype=np.int64) * 2 + 1,
        tri_slot=slots.reshape(-1),
        sharp=np.array(sharp if sharp is not None else [False] * n),
        bevel=np.array(bevel if bevel is not None else [0.0] * n, np.float32),
        surface_id=np.arange(1, 2 * n + 1, dtype=np.uint32))


def choose_edges(d, shading):
    """The edges edge_choice.choose picks, by slot."""
    return edge_choice.choose(d, shading).edges


def chosen(result):
    """{slot: (edge indices by their p0's x, radii)} of a choose_edges result."""
    return {slot: (e.p0[:, 0].astype(int).tolist(), e.radius.tolist()) for slot, e in result.items()}


class ShadingNormals(unittest.TestCase):
    """The normals a band's arc runs between are the ones the surface is shaded with next to it
    (edge_data.shading_normals): one edge along x between a floor (z up, N1) and a wall (-y,
    N2), a 90 degree convex fold."""

    def edge(self, floor_corners, wall_corners, flip_wall=False):
        n1, n2 = np.array([0.0, 0.0, 1.0]), np.array([0.0, -1.0, 0.0])
        lib = np.r_[n1, -n2 if flip_wall else n2].astype(np.float32)[None]
        d = edge_data.EdgeData(
            flags=np.array([MANIFOLD], np.uint32), angles=np.array([90.0], np.float32), normals=lib,
            edges=np.array([[0, 1]], np.uint32),
            positions=np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1)], np.float32),
            face_a=np.array([0]), face_b=np.array([1]), tri_slot=np.zeros(2, np.int64),
            sharp=np.zeros(1, bool), bevel=np.zeros(1, np.float32),
            tri_verts=np.array([[0, 1, 2], [1, 0, 3]]),
            corner_nor=np.array([floor_corners, wall_corners], np.float32))
        return edge_data.shading_normals(d, np.array([0]), lib)[0]  # (end, 6)

    def test_flat_faces_keep_their_normals(self):
        got = self.edge([[0, 0, 1]] * 3, [[0, -1, 0]] * 3)
        np.testing.assert_allclose(got, [[0, 0, 1, 0, -1, 0]] * 2, atol=1e-6)

    def test_smooth_sides_take_their_corner_normal_at_each_end(self):
        tilt = np.array([0.0, -np.sin(0.2), np.cos(0.2)])
        other = np.array([0.0, np.sin(0.4), np.cos(0.4)])
        # The floor's corners at the edge's ends (vertices 0 and 1) lean towards the wall; its
        # third corner (off the edge) is not counted.
        got = self.edge([tilt, tilt, other], [[0, -1, 0]] * 3)
        np.testing.assert_allclose(got[:, :3], [tilt, tilt], atol=1e-6)
        np.testing.assert_allclose(got[:, 3:], [[0, -1, 0]] * 2, atol=1e-6)

    def test_a_normal_turning_along_the_edge_and_its_mean_and_turn(self):
        """A smooth wall whose normal turns about z along the edge (a cylinder's rim): each end
        takes its own corner normal, and normalize(mean + (t - 1/2) turn) gives them back at
        t = 0 and 1 (el_edge_frame)."""
        at0 = np.array([-np.sin(0.15), -np.cos(0.15), 0.0])
        at1 = np.array([np.sin(0.15), -np.cos(0.15), 0.0])
        # The wall's triangle runs 1, 0, 3: its first corner is at vertex 1 (the edge's p1).
        got = self.edge([[0, 0, 1]] * 3, [at1, at0, [0, -1, 0]])
        np.testing.assert_allclose(got[0, 3:], at0, atol=1e-6)
        np.testing.assert_allclose(got[1, 3:], at1, atol=1e-6)
        mean, turn = edge_data.mean_and_turn(got[None])
        np.testing.assert_allclose(mean[0], [0, 0, 1, 0, -1, 0], atol=1e-6)
        for t, want in ((0.0, at0), (1.0, at1)):
            n = mean[0, 3:] + (t - 0.5) * turn[0, 3:]
            np.testing.assert_allclose(n / np.linalg.norm(n), want, atol=1e-6)
        np.testing.assert_allclose(turn[0, :3], 0.0, atol=1e-7)

    def test_a_reoriented_face_keeps_the_librarys_sign(self):
        got = self.edge([[0, 0, 1]] * 3, [[0, -1, 0]] * 3, flip_wall=True)
        np.testing.assert_allclose(got[:, 3:], [[0, 1, 0]] * 2, atol=1e-6)

    def test_corners_turned_too_far_are_not_taken(self):
        far = np.array([0.0, -np.sin(1.0), np.cos(1.0)])  # 57 degrees from the floor's normal
        got = self.edge([far, far, far], [[0, -1, 0]] * 3)
        np.testing.assert_allclose(got[:, :3], [[0, 0, 1]] * 2, atol=1e-6)

    def test_one_end_turned_too_far_keeps_the_faces_normals_at_both(self):
        """Taking the corner normal at one end alone would turn the arc along the edge where
        Blender shades the face with neither flat normal."""
        near = np.array([0.0, -np.sin(0.2), np.cos(0.2)])
        far = np.array([0.0, -np.sin(0.5), np.cos(0.5)])  # 28.6 degrees: past the limit
        got = self.edge([near, far, [0, 0, 1]], [[0, -1, 0]] * 3)
        np.testing.assert_allclose(got[:, :3], [[0, 0, 1]] * 2, atol=1e-6)


class ShadingNormalsAgainstTheReference(unittest.TestCase):
    def test_the_library_gives_the_references_normals(self):
        """el_shading_normals against the numpy it replaced (edge_data_reference.py) on grid
        boxes whose triangles' corner normals are their faces' turned by noise (a few degrees to
        far past the limit), some faces' normals flipped as the library re-orients, some
        corners' normals zero: the same normals (within 1e-6) at every edge's ends, and both
        kinds of edge (taking the corners, keeping the faces') met many times."""
        import edge_data_reference as reference
        from small_meshes import edge_frame
        from small_meshes import mesh as small_mesh
        from test_rounded_outline import grid_box
        rng = np.random.default_rng(12)
        taken = kept = 0
        for n, jitter in ((1, 0.0), (2, 0.0), (3, 0.0), (4, 0.0), (5, 0.0), (3, 0.01), (5, 0.01)):
            positions, edges, polys, tris = grid_box(n)
            if jitter:  # the grid's facets folded a little, either way: the fold's sign decides
                loops = [polys.loop_vert[a:a + k].tolist() for a, k in zip(polys.start, polys.total)]
                positions, edges, polys, tris = small_mesh(positions + rng.normal(scale=jitter, size=positions.shape),
                                                           loops)
            normals, faces = edge_frame(positions, edges, polys, tris)
            flip = rng.random(len(edges)) < 0.2
            normals[flip, 3:] *= -1.0
            tri_n = np.asarray(polys.normal)[np.asarray(polys.tri_poly)]
            scale = rng.choice([0.03, 0.06, 0.6], size=(len(tris), 1, 1))
            corner = tri_n[:, None, :] + scale * rng.normal(size=(len(tris), 3, 3))
            corner[rng.random((len(tris), 3)) < 0.05] = 0.0
            corner = (corner / np.maximum(np.linalg.norm(corner, axis=2, keepdims=True), 1e-30)).astype(np.float32)
            d = types.SimpleNamespace(positions=positions.astype(np.float32), edges=edges, face_a=faces[:, 0],
                                      face_b=faces[:, 1], tri_verts=tris, corner_nor=corner)
            sel = np.flatnonzero((faces >= 0).all(axis=1))
            got = edge_data.shading_normals(d, sel, normals)
            want = reference.shading_normals(d, sel, normals)
            np.testing.assert_allclose(got, want, atol=1e-6, err_msg=f"grid {n}")
            same = np.all(np.abs(got[:, 0] - normals[sel]) < 1e-6, axis=1)
            kept += int(same.sum())
            taken += int((~same).sum())
        self.assertGreater(taken, 40)
        self.assertGreater(kept, 50)


class EdgeRulesAgainstTheReference(unittest.TestCase):
    def test_the_library_applies_the_references_rule(self):
        """el_edge_rules against the numpy it replaced (edge_choice_reference.py): 3000 edges of
        random flags, angles (half exactly at a slot's angle), faces (some missing), sharp marks
        and bevel weights over four slots of different rules, radii and angles (one disabled,
        one at strength 0): every output the same (radii exactly)."""
        import edge_choice_reference as reference
        rng = np.random.default_rng(51)
        n, tris = 3000, 500
        flags = rng.choice([MANIFOLD, MANIFOLD | native.EDGE_DEGENERATE, native.EDGE_BORDER, MANIFOLD | native.EDGE_CONVEX],
                           n).astype(np.uint32)
        # Half the angles exactly at a slot's angle (not past it), half anywhere.
        angles = np.where(rng.random(n) < 0.5, rng.choice([10.0, 30.0, 45.0, 60.0], n),
                          rng.uniform(0.0, 180.0, n)).astype(np.float32)
        face_a = rng.integers(-1, tris, n)
        face_b = np.where(rng.random(n) < 0.1, -1, rng.integers(0, tris, n))
        tri_slot = rng.integers(0, 4, tris)
        # Slot 2 at strength 0 and slot 3 disabled round nothing, even where their rules pick.
        shading = [Shading(enabled=True, radius=0.05, K=1.0, rules=frozenset({'ANGLE'}), angle_deg=30.0),
                   Shading(enabled=True, radius=0.12, K=1.0, rules=frozenset({'SHARP', 'BEVEL'}), angle_deg=45.0),
                   Shading(enabled=True, radius=0.08, K=0.0, rules=frozenset({'ANGLE', 'SHARP', 'BEVEL'}), angle_deg=10.0),
                   Shading(enabled=False, radius=0.2, K=1.0, rules=frozenset({'ANGLE'}), angle_deg=60.0)]
        d = types.SimpleNamespace(flags=flags, angles=angles, face_a=face_a, face_b=face_b, tri_slot=tri_slot,
                                  sharp=rng.random(n) < 0.2, bevel=np.where(rng.random(n) < 0.3, rng.random(n), 0.0).astype(np.float32))
        bits = {'ANGLE': native.RULE_ANGLE, 'SHARP': native.RULE_SHARP, 'BEVEL': native.RULE_BEVEL}
        got = native.edge_rules(d.flags, d.angles, d.face_a, d.face_b, d.sharp, d.bevel, d.tri_slot,
                                [(s.enabled, s.radius, s.K, sum(bits[b] for b in s.rules), s.angle_deg) for s in shading])
        want = reference.rules(d, shading)
        for name, w in zip(("chosen", "radius", "slot_a", "slot_b", "pick_a", "pick_b", "rad_a", "rad_b"), want):
            np.testing.assert_array_equal(got[name], w, err_msg=name)
        self.assertGreater(int(got["chosen"].sum()), 150)
        self.assertGreater(int((~got["chosen"] & (got["pick_a"] | got["pick_b"])).sum()), 100)


class ChooseEdges(unittest.TestCase):
    def test_angle_rule_rounds_edges_past_the_angle(self):
        got = choose_edges(edges_of([10.0, 30.0, 31.0, 90.0]), [Shading()])
        self.assertEqual(chosen(got), {0: ([2, 3], [np.float32(material_defaults.RADIUS)] * 2)})

    def test_sharp_and_bevel_rules_and_the_bevel_weight_scaling_the_radius(self):
        d = edges_of([5.0, 5.0, 5.0, 60.0], sharp=[True, False, False, False], bevel=[0.0, 0.5, 0.0, 0.5])
        got = chosen(choose_edges(d, [Shading(radius=0.02)]))
        # Edge 1 is picked by its bevel weight alone (radius x weight); edge 3 by its angle too
        # (the full radius); edge 2 by nothing.
        self.assertEqual(got[0][0], [0, 1, 3])
        np.testing.assert_allclose(got[0][1], [0.02, 0.01, 0.02])
        none = chosen(choose_edges(d, [Shading(rules=frozenset({'SHARP'}))]))
        self.assertEqual(none[0][0], [0])

    def test_only_usable_manifold_edges_with_two_faces(self):
        flags = [MANIFOLD, MANIFOLD | native.EDGE_DEGENERATE, native.EDGE_NON_MANIFOLD, native.EDGE_BORDER]
        d = edges_of([60.0] * 4, flags=flags)
        d.face_b[3] = -1  # the border edge's one face
        self.assertEqual(chosen(choose_edges(d, [Shading()]))[0][0], [0])

    def test_between_two_materials(self):
        # Edge 0: both round, only the second's angle picks it, smaller radius wins; edge 1: the
        # second material does not round at all; edge 2: K = 0 turns rounding off; edge 3: both
        # pick it, and its first face's material (slot 1) shades it.
        d = edges_of([40.0, 60.0, 60.0, 60.0], slots=[(0, 1), (0, 2), (0, 3), (1, 0)])
        shading = [Shading(radius=0.03, angle_deg=50.0), Shading(radius=0.02),
                   Shading(enabled=False), Shading(K=0.0)]
        self.assertEqual(chosen(choose_edges(d, shading)),
                         {0: ([0], [np.float32(0.02)]), 1: ([3], [np.float32(0.02)])})

    def test_bands_carry_their_faces_surface_ids(self):
        got = choose_edges(edges_of([60.0, 60.0]), [Shading()])
        self.assertEqual(got[0].faces.tolist(), [[1.0, 2.0], [3.0, 4.0]])

    def test_same_edges(self):
        a = choose_edges(edges_of([60.0, 60.0]), [Shading()])
        self.assertTrue(edge_choice.same_edges(a, choose_edges(edges_of([60.0, 60.0]), [Shading()])))
        self.assertFalse(edge_choice.same_edges(a, choose_edges(edges_of([60.0, 60.0]), [Shading(radius=0.02)])))
        self.assertFalse(edge_choice.same_edges(a, choose_edges(edges_of([60.0, 10.0]), [Shading()])))


class RadiusClampCounts(unittest.TestCase):
    """What the material panel's note counts (radius_clamp_notes.count): three rounded edges
    between materials A (slot 0, radius 0.5) and B (slot 1, radius 0.1), their faces allowing
    0.2, 0.05 and 1.0. Edge 0 (A | A) is clamped for A; edge 1 (A | B, radius 0.1) for both, each
    having asked more than 0.05; edge 2 (B | B) for neither."""

    def counts(self):
        shading = [Shading(radius=0.5, material="A"), Shading(radius=0.1, material="B"), Shading(material="")]
        sides = ((np.array([0, 0, 1]), np.array([True] * 3), np.array([0.5, 0.5, 0.1])),
                 (np.array([0, 1, 1]), np.array([True] * 3), np.array([0.5, 0.1, 0.1])))
        return clamp_counts.count(shading, sides, np.array([0.2, 0.05, 1.0]))

    def test_each_material_counts_its_rounded_and_clamped_edges(self):
        a, b = self.counts()
        self.assertEqual((a.material, a.radius, a.rounded, a.clamped, a.smallest), ("A", 0.5, 2, 2, 0.05))
        self.assertEqual((b.material, b.radius, b.rounded, b.clamped, b.smallest), ("B", 0.1, 2, 1, 0.05))

    def test_totals_over_geometries_at_the_current_radius(self):
        counts = self.counts() * 2  # two geometries
        self.assertEqual(clamp_counts.total(counts, "A", 0.5), (4, 4, 0.05))
        self.assertIsNone(clamp_counts.total(counts, "A", 0.25), "counted at another radius")
        self.assertIsNone(clamp_counts.total(counts, "C", 0.5))

    def test_the_choice_returns_its_counts(self):
        got = edge_choice.choose(edges_of([60.0, 60.0]), [Shading(material="A")])
        self.assertEqual(len(got.edges[0]), 2)
        self.assertEqual([(c.material, c.rounded, c.clamped) for c in got.clamps], [("A", 2, 0)])


def library():
    if not os.environ.get("EDGELIGHT_LIBRARY"):
        raise unittest.SkipTest("EDGELIGHT_LIBRARY not set (ctest sets it)")
    return native.load()


def moebius(segments=7):
    """A Moebius strip of `segments` quads: orientable nowhere, so one edge joins faces wound
    against each other whatever the library chooses."""
    verts = []
    for i in range(segments):
        t = 2.0 * math.pi * i / segments
        for s in (-0.3, 0.3):
            r = 1.0 + s * math.cos(t / 2.0)
            verts.append((r * math.cos(t), r * math.sin(t), s * math.sin(t / 2.0)))
    tris = []
    for i in range(segments):
        a, b = 2 * i, 2 * i + 1
        c, d = (2 * (i + 1), 2 * (i + 1) + 1) if i + 1 < segments else (1, 0)  # the half twist
        tris += [(a, c, b), (b, c, d)]
    return np.array(verts, np.float32), np.array(tris, np.uint32)


class CreaseRule(unittest.TestCase):
    def test_crease_edges_follow_the_threshold(self):
        # Two triangles folded 60 degrees about their shared edge, and a flat square.
        c, s = math.cos(math.radians(60.0)), math.sin(math.radians(60.0))
        positions = np.array([(0, 0, 0), (1, 0, 0), (0.5, 1, 0), (0.5, -c, s),
                              (3, 0, 0), (4, 0, 0), (4, 1, 0), (3, 1, 0)], np.float32)
        mesh = native.Mesh(positions, np.array([(0, 1, 2), (1, 0, 3), (4, 5, 6), (4, 6, 7)], np.uint32), lib=library())
        e = mesh.edges()
        fold = [i for i, (a, b) in enumerate(e) if {int(a), int(b)} == {0, 1}]
        for threshold, expect in ((59.0, fold), (61.0, [])):
            self.assertEqual(np.flatnonzero(lines.crease_edges(mesh, threshold)).tolist(), expect, threshold)

    def test_no_crease_between_faces_wound_against_each_other(self):
        mesh = native.Mesh(*moebius(), lib=library())
        flags, angles = mesh.edge_flags(), mesh.edge_angles()
        flipped = (flags & native.EDGE_FLIPPED_WINDING) != 0
        manifold = (flags & native.EDGE_MANIFOLD) != 0
        self.assertGreater(int(flipped.sum()), 0)
        threshold = 1.0
        self.assertTrue(np.any(flipped & manifold & (angles > threshold)), "a flipped edge past the angle")
        crease = lines.crease_edges(mesh, threshold)
        self.assertFalse(np.any(crease & flipped))
        self.assertTrue(np.array_equal(crease, manifold & ~flipped & (angles > threshold)))



class OneCameraBuilder(unittest.TestCase):
    def test_the_eye_and_the_unit_direction_come_from_the_views_inverse(self):
        """passes.camera.from_view, which the render, the viewport and the SVG export share: a
        camera at (1, -4, 2) looking along +y, its world matrix scaled by 3 (a scaled camera
        object): the eye where it stands, the direction unit length."""
        camera = addon_module("passes.camera")
        world = np.eye(4)
        world[:3, :3] = 3.0 * np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])  # -z -> +y
        world[:3, 3] = (1.0, -4.0, 2.0)
        c = camera.from_view(np.linalg.inv(world), np.eye(4), True, 640, 480)
        np.testing.assert_allclose(c.eye, (1.0, -4.0, 2.0), atol=1e-12)
        np.testing.assert_allclose(c.view_dir, (0.0, 1.0, 0.0), atol=1e-12)
        self.assertTrue(c.orthographic)
        self.assertEqual((c.width, c.height), (640, 480))

if __name__ == "__main__":
    unittest.main()
