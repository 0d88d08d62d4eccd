"""A radius larger than an edge's faces allow is clamped (the Bevel modifier's Clamp Overlap):
the band stays on its faces instead of spreading past the object as a starburst."""
import unittest

import bmesh
import numpy as np

import helpers
import scene_zoo as zoo


def cube_with_radius(radius, scale=1.0, cuts=0):
    helpers.empty_scene(400, 300)
    cam = helpers.add_camera((4.5 * scale, -5.5 * scale, 4.0 * scale))
    cam.data.clip_start, cam.data.clip_end = 0.1 * scale, 100.0 * scale
    helpers.add_sun((0.3, -0.6, 0.8), 4.0)
    cube = zoo.box("Cube", 2.0)
    cube.scale = (scale, scale, scale)
    if cuts:  # each face a grid of cuts + 1 squared cells, each cut into triangles: coplanar facets
        bm = bmesh.new()
        bm.from_mesh(cube.data)
        bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=cuts, use_grid_fill=True)
        bmesh.ops.triangulate(bm, faces=bm.faces[:])
        bm.to_mesh(cube.data)
        bm.free()
    mat = zoo.material("Steel", (0.5, 0.5, 0.55))
    mat.edgelight.radius = radius
    cube.data.materials.append(mat)
    return helpers.render()


def band_outside(rec):
    """Highlight pixels where no surface is: a band past its object."""
    band = helpers.highlight_change(rec) > 1.0 / 255.0
    empty = np.asarray(rec["surface"])[..., 3] == 0.0
    return int((band & empty).sum())


class RadiusClamp(unittest.TestCase):
    def test_over_large_radius_stays_on_the_object(self):
        helpers.needs_gpu()
        fitting = cube_with_radius(1.0)      # the largest the cube's 2 m faces allow at 90 degrees
        too_large = cube_with_radius(5.0)
        diff = np.abs(np.asarray(too_large["highlight"]) - np.asarray(fitting["highlight"])).max()
        self.assertLess(diff, 1e-4, "a radius past the limit renders as the limit")
        self.assertEqual(band_outside(too_large), band_outside(fitting))

    def test_triangulated_faces_allow_what_the_face_allows(self):
        """A fillet runs on across coplanar facets: a box whose faces are cut into triangles a
        quarter of their width renders as the box, at a radius 2.4 times what a triangle allows."""
        helpers.needs_gpu()
        plain = cube_with_radius(0.6)
        cut = cube_with_radius(0.6, cuts=3)
        a, b = np.asarray(plain["highlight"]), np.asarray(cut["highlight"])
        self.assertGreater((a[..., 3] > 0.05).sum(), 2000, "wide bands on the plain box")
        self.assertLess(np.abs(a - b).max(axis=-1).mean(), 2e-3)
        self.assertLess(np.percentile(np.abs(a - b).max(axis=-1), 99.5), 0.05)

    def test_scale_and_radius_agree(self):
        """The radius is in object space (scaled with the object, like the Bevel modifier's
        Amount): the same part at 1e-3 and 1e3 renders the same image."""
        helpers.needs_gpu()
        small = cube_with_radius(0.2, scale=1e-3)
        large = cube_with_radius(0.2, scale=1e3)
        self.assertGreater((np.asarray(small["highlight"])[..., 3] > 0.05).sum(), 200)
        diff = np.abs(np.asarray(small["pixels"]) - np.asarray(large["pixels"]))
        self.assertLess(np.percentile(diff, 99.5), 2e-3)
