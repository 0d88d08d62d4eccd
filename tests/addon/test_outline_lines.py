"""Silhouette lines on the rounded outline (addon/outline_lines.py): a rounded edge's silhouette
end moves onto its fillet's outline point, in closed form for a 90-degree edge, and two moved
segments that meet at a corner end where their lines cross."""
import types
import unittest

import numpy as np

from addon_modules import addon_module

outline_lines = addon_module("outline_lines")

R = 0.1
NA, NB = np.array([0.0, 0.0, 1.0]), np.array([0.0, -1.0, 0.0])  # top and front faces


def record(p0, p1, na=NA, nb=NB, radius=R):
    """One edge's strip record (rounded_outline.EDGE_TEXELS texels), its normals not turning."""
    r = np.zeros((1, 6, 4), np.float32)
    r[0, 0, :3], r[0, 0, 3], r[0, 1, :3] = na, radius, nb
    r[0, 2, :3], r[0, 3, :3] = p0, p1
    return r


def ortho(to_eye):
    v = np.asarray(to_eye, float)
    return types.SimpleNamespace(orthographic=True, view_dir=tuple(-v / np.linalg.norm(v)), eye=None)


class OutlinePoint(unittest.TestCase):
    def test_a_box_edge_seen_from_above_and_behind(self):
        """The top face towards the eye, the front face away: the fillet's axis lies r inside
        both faces, at (0, r, -r) from the edge, and its outline is the point of the circle
        whose normal is square to the view, on the sharp edge's side: (0, -0.8, 0.6) for a view
        from (0, 0.6, 0.8). The move is from the edge to that point, at both ends."""
        moves = outline_lines.outline_moves(record((0, 0, 0), (1, 0, 0)), np.eye(4), ortho((0.0, 0.6, 0.8)))
        axis = np.array([0.0, R, -R])
        expected = axis + R * np.array([0.0, -0.8, 0.6])
        for end in (0, 1):
            np.testing.assert_allclose(moves[end, 0], expected, atol=1e-6)
        # On the fillet's circle, and its normal there square to the view.
        np.testing.assert_allclose(np.linalg.norm(moves[0, 0] - axis), R, rtol=1e-5)
        self.assertAlmostEqual(float(np.dot(moves[0, 0] - axis, (0.0, 0.6, 0.8))), 0.0, places=6)

    def test_the_faces_either_way_round(self):
        """N1 and N2 swapped (the edge's cross product the other way): the same point."""
        a = outline_lines.outline_moves(record((0, 0, 0), (1, 0, 0)), np.eye(4), ortho((0.0, 0.6, 0.8)))
        b = outline_lines.outline_moves(record((0, 0, 0), (1, 0, 0), NB, NA), np.eye(4), ortho((0.0, 0.6, 0.8)))
        np.testing.assert_allclose(a, b, atol=1e-6)

    def test_no_move_where_both_faces_face_the_eye(self):
        moves = outline_lines.outline_moves(record((0, 0, 0), (1, 0, 0)), np.eye(4), ortho((0.0, -0.6, 0.8)))
        np.testing.assert_array_equal(moves, 0.0)

    def test_in_perspective_each_end_sees_the_eye_from_itself(self):
        """An eye far up the same direction gives the orthographic answer; one that sees the
        front face from one end and not from the other moves that end only."""
        far = types.SimpleNamespace(orthographic=False, view_dir=None, eye=tuple(np.array([0.5, 0.6, 0.8]) * 1e5))
        moves = outline_lines.outline_moves(record((0, 0, 0), (1, 0, 0)), np.eye(4), far)
        np.testing.assert_allclose(moves[0, 0], (0.0, 0.02, -0.04), atol=1e-5)
        # From (0.5, 0.05, 10): behind the front face's plane (y > 0) from both ends, so both move;
        # from (0.5, -0.05, 10) in front of it: a silhouette nowhere.
        for y, moved in ((0.05, True), (-0.05, False)):
            eye = types.SimpleNamespace(orthographic=False, view_dir=None, eye=(0.5, y, 10.0))
            moves = outline_lines.outline_moves(record((0, 0, 0), (1, 0, 0)), np.eye(4), eye)
            self.assertEqual(bool(np.abs(moves).max() > 1e-6), moved, y)

    def test_a_uniform_scale_keeps_the_object_space_move(self):
        """The radius is in object space (the Bevel modifier's Amount): under a uniform scale
        the fillet scales with the object, and its outline point stays where it was on it."""
        rec = record((0, 0, 0), (1, 0, 0))
        scaled = np.diag([3.0, 3.0, 3.0, 1.0])
        np.testing.assert_allclose(outline_lines.outline_moves(rec, scaled, ortho((0.0, 0.6, 0.8))),
                                   outline_lines.outline_moves(rec, np.eye(4), ortho((0.0, 0.6, 0.8))), atol=1e-6)


def join(p0, p1, d):
    """Segments 0 -> 1 and 1 -> 2 (p0, p1, directions d), seen along z: both joined in place."""
    p0, p1 = np.array(p0, np.float32), np.array(p1, np.float32)
    outline_lines._join_corners(np.array([[0, 1], [1, 2]]), np.arange(2), np.array(d, np.float32), p0, p1, np.eye(4))
    return p0, p1


class Corners(unittest.TestCase):
    def test_two_moved_segments_end_where_their_lines_cross(self):
        """Segments 0 -> 1 along x and 1 -> 2 along y meet at vertex 1; moved square to
        themselves by 0.1 (into the corner), each overshoots the other. Both end at (0.9, 0.1),
        seen along z (the clip matrix the identity)."""
        p0, p1 = join([[0.0, 0.1, 0.0], [0.9, 0.0, 0.0]], [[1.0, 0.1, 0.0], [0.9, 1.0, 0.0]], [[1, 0, 0], [0, 1, 0]])
        np.testing.assert_allclose(p1[0], (0.9, 0.1, 0.0), atol=1e-6)
        np.testing.assert_allclose(p0[1], (0.9, 0.1, 0.0), atol=1e-6)
        np.testing.assert_allclose(p0[0], (0.0, 0.1, 0.0))  # free ends stay
        np.testing.assert_allclose(p1[1], (0.9, 1.0, 0.0))

    def test_skew_lines_end_where_their_images_cross(self):
        """The same corner with the second line moved 0.3 towards the eye (z), seen along z:
        both ends at one point on the first line whose image is the crossing, (0.9, 0.1, 0)."""
        p0, p1 = join([[0.0, 0.1, 0.0], [0.9, 0.0, 0.3]], [[1.0, 0.1, 0.0], [0.9, 1.0, 0.3]], [[1, 0, 0], [0, 1, 0]])
        np.testing.assert_allclose(p1[0], (0.9, 0.1, 0.0), atol=1e-6)
        np.testing.assert_array_equal(p0[1], p1[0])

    def test_segments_that_nearly_continue_each_other_meet_halfway(self):
        """Along a smooth rim the two lines cross far off or not at all: the ends meet at their
        mean."""
        p0, p1 = join([[0.0, 0.0, 0.0], [1.0, 0.02, 0.0]], [[1.0, 0.0, 0.0], [2.0, 0.05, 0.0]],
                      [[1.0, 0.0, 0.0], [1.0, 0.03, 0.0]])
        np.testing.assert_allclose(p1[0], (1.0, 0.01, 0.0), atol=1e-6)
        np.testing.assert_allclose(p0[1], (1.0, 0.01, 0.0), atol=1e-6)


if __name__ == "__main__":
    unittest.main()
