"""A radius larger than an edge's faces allow is clamped (the Bevel modifier's Clamp Overlap):
the band stays on its faces instead of spreading past the object as a starburst."""
import math
import os
import sys
import unittest

import bmesh
import bpy
import numpy as np

import helpers
import scene_zoo as zoo

sys.path.insert(0, os.path.join(helpers.ROOT, "bench"))
import fillets  # noqa: E402
from gt_scenes import display  # noqa: E402

CAMERA = (4.5, -5.5, 4.0)


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


def stretched_box(width_px, scale, mode, samples=8):
    """A 2 m box scaled by `scale` (its z the long axis), lit to glint halfway round its vertical
    edges' fillets, with EdgeLight's bands ("bands"), the Bevel modifier's circular fillets of
    the same object-space radius ("fillets"), or sharp ("sharp")."""
    helpers.empty_scene(400, 300, samples=samples)
    cam = helpers.add_camera(CAMERA)
    cam.data.clip_start, cam.data.clip_end = 0.1, 100.0
    n = np.array([1.0, -1.0, 0.0]) / math.sqrt(2.0)
    v = np.asarray(CAMERA) / np.linalg.norm(CAMERA)
    helpers.add_sun(tuple(2.0 * (n @ v) * n - v), 4.0)
    cube = zoo.box("Cube", 2.0)
    cube.scale = scale
    radius = zoo.radius_at_width(width_px, CAMERA, 400)
    mat = zoo.material("Steel", (0.5, 0.5, 0.55))
    mat.edgelight.radius = radius
    cube.data.materials.append(mat)
    s = bpy.context.scene
    s.view_settings.view_transform = 'Standard'
    if mode == "fillets":
        fillets.add_fillets(s, radius, 32)
    s.edgelight.highlights = mode == "bands"
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

    def test_a_stretched_box_keeps_its_radius_across_its_long_edges(self):
        """Under a non-uniform scale the radius stretches as the object does, across each edge
        (the Bevel modifier's Amount is in object space too): a box stretched along z keeps
        round vertical edges of the radius itself. Across the middle of a vertical edge, against
        the modifier's fillets (RMSE on display values, llvmpipe, Blender 3.4): 0.021-0.061
        with the radius scaled by the transform's effect on the diagonal (1.41 and 1.91 times
        too wide), 0.0005-0.0007 scaled across the edge; sharp 0.071-0.103."""
        helpers.needs_gpu()
        edge = ((1.0, -1.0, -1.0), (1.0, -1.0, 1.0))
        ts, offsets = np.linspace(0.35, 0.65, 7), np.arange(-8.0, 8.5, 0.5)
        for stretch in (2.0, 3.0):
            for width in (2.0, 4.0):
                world_edge = [(x, y, z * stretch) for x, y, z in edge]
                profile = lambda rec: display(helpers.edge_profile(  # noqa: E731
                    rec, np.asarray(rec["pixels"])[..., :3], *world_edge, ts, offsets))
                scale = (1.0, 1.0, stretch)
                exact = profile(stretched_box(width, scale, "fillets", samples=64))
                ours = profile(stretched_box(width, scale, "bands"))
                sharp = profile(stretched_box(width, scale, "sharp"))
                rmse = lambda a: math.sqrt(np.mean((a - exact) ** 2))  # noqa: E731
                print(f"stretched {stretch:g}, {width:g} px: RMSE against the modifier's fillets: EdgeLight "
                      f"{rmse(ours):.4f}, sharp {rmse(sharp):.4f}")
                self.assertGreater(rmse(sharp), 0.02, "the fillet changes the edge's image")
                self.assertLess(rmse(ours), 0.008, f"stretched {stretch}, {width} px")
