"""Which surfaces are closed (addon/geometry/closed_surfaces.py), and where an instance's back faces
cannot show: on a cube whole, opened, half wound the other way, with a fin, and seen from
outside, from inside and across the near plane."""
import unittest

import numpy as np

from addon_modules import addon_module

closed_surfaces = addon_module("geometry.closed_surfaces")

# A unit cube's twelve triangles, wound outwards.
CUBE = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                 [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
POSITIONS = np.array([[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])


def look_at(eye, target, near=0.1, far=100.0):
    """A perspective camera's projection times view (OpenGL conventions)."""
    eye, target = np.asarray(eye, float), np.asarray(target, float)
    f = target - eye
    f /= np.linalg.norm(f)
    up = np.array([0.0, 0.0, 1.0]) if abs(f[2]) < 0.9 else np.array([0.0, 1.0, 0.0])
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = s, u, -f
    view[:3, 3] = -view[:3, :3] @ eye
    proj = np.zeros((4, 4))
    proj[0, 0] = proj[1, 1] = 2.0
    proj[2, 2], proj[2, 3] = -(far + near) / (far - near), -2.0 * far * near / (far - near)
    proj[3, 2] = -1.0
    return proj @ view


class Closed(unittest.TestCase):
    def test_a_cube_is_closed(self):
        self.assertTrue(closed_surfaces.is_closed(CUBE, np.zeros(12, bool)))

    def test_a_cube_without_a_face_is_open(self):
        self.assertFalse(closed_surfaces.is_closed(CUBE[2:], np.zeros(10, bool)))

    def test_triangles_wound_the_other_way_count_as_the_library_oriented_them(self):
        wound = CUBE.copy()
        wound[::3] = wound[::3, ::-1]
        flips = np.zeros(12, bool)
        self.assertFalse(closed_surfaces.is_closed(wound, flips), "the file's winding is not consistent")
        flips[::3] = True
        self.assertTrue(closed_surfaces.is_closed(wound, flips))
        # Back in the cube's winding, from another corner.
        np.testing.assert_array_equal(np.roll(closed_surfaces.oriented_triangles(wound, flips)[::3], -1, axis=1), CUBE[::3])

    def test_a_fin_on_an_edge_is_not_closed(self):
        """Three faces on one edge: the third's back shows wherever it stands out."""
        fin = np.r_[CUBE, [[0, 1, 8]], [[1, 0, 8]]]
        self.assertFalse(closed_surfaces.is_closed(fin, np.zeros(len(fin), bool)))

    def test_a_sliver_with_a_repeated_vertex_is_not_taken_for_closed(self):
        cube = np.r_[CUBE, [[0, 0, 1]]]
        self.assertFalse(closed_surfaces.is_closed(cube, np.zeros(len(cube), bool)))


class HiddenBackFaces(unittest.TestCase):
    BOX = closed_surfaces.bounds(POSITIONS)

    def test_seen_from_outside(self):
        self.assertTrue(closed_surfaces.hidden_back_faces(self.BOX, np.eye(4), look_at((4.0, -5.0, 3.0), (0.5, 0.5, 0.5))))

    def test_seen_from_inside(self):
        self.assertFalse(closed_surfaces.hidden_back_faces(self.BOX, np.eye(4), look_at((0.5, 0.5, 0.5), (2.0, 0.5, 0.5))))

    def test_cut_by_the_near_plane(self):
        """The eye outside, but the near plane 0.1 in front of it cuts the cube open."""
        self.assertFalse(closed_surfaces.hidden_back_faces(self.BOX, np.eye(4), look_at((-0.05, 0.5, 0.5), (2.0, 0.5, 0.5))))

    def test_the_instance_transform_counts(self):
        moved = np.eye(4)
        moved[:3, 3] = (4.0, -5.0, 3.0)  # the cube moved round the eye
        camera = look_at((4.5, -4.5, 3.5), (10.0, -4.5, 3.5))
        self.assertFalse(closed_surfaces.hidden_back_faces(self.BOX, moved, camera))
        self.assertTrue(closed_surfaces.hidden_back_faces(self.BOX, np.eye(4), look_at((4.0, -5.0, 3.0), (0.5, 0.5, 0.5))))

    def test_many_instances_at_once(self):
        """Stacked boxes and transforms (surface_pass.cull_modes' one call a frame): each the
        answer it gets alone."""
        camera = look_at((4.5, -4.5, 3.5), (10.0, -4.5, 3.5))
        moved = [np.eye(4) for _ in range(4)]
        for m, at in zip(moved, ((4.0, -5.0, 3.0), (8.0, -5.0, 3.0), (0.0, 0.0, 0.0), (20.0, -5.0, 3.0))):
            m[:3, 3] = at
        boxes = np.stack([self.BOX, self.BOX * 2.0, self.BOX, self.BOX])
        together = closed_surfaces.hidden_back_faces(boxes, np.stack(moved), camera)
        alone = [bool(closed_surfaces.hidden_back_faces(b, m, camera)) for b, m in zip(boxes, moved)]
        self.assertEqual(together.tolist(), alone)
        self.assertEqual(alone, [False, True, False, True])


if __name__ == "__main__":
    unittest.main()
