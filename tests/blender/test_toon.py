"""Toon shading in final renders: the shade ramp and X-Toon."""
import os
import tempfile
import unittest

import bpy
import numpy as np

import helpers

DARK, LIGHT = (0.1, 0.05, 0.2), (0.9, 0.6, 0.3)


def toon_sphere(location=(0.0, 0.0, 0.0), name="Toon"):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=64, ring_count=32, radius=1.0, location=location)
    bpy.ops.object.shade_smooth()
    ob = bpy.context.object
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.edgelight.use_rounding = False  # a sphere has no edges to round; keep the surface pure
    ob.data.materials.append(mat)
    return ob, mat


def set_ramp(mat, stops, smooth=False):
    s = mat.edgelight
    s.shading = 'RAMP'
    s.shade_ramp = helpers.addon().extract.color_ramp.new_ramp(stops, 'LINEAR' if smooth else 'CONSTANT')


def surface_colours(rec):
    surf = rec["surface"]
    rgb = surf[surf[..., 3] == 1.0][:, :3]
    colours, counts = np.unique(rgb, axis=0, return_counts=True)
    return colours, counts, len(rgb)


class Ramp(unittest.TestCase):
    def render_sphere(self, stops, smooth=False, lights=1):
        helpers.empty_scene(300, 300, highlights=False)
        _, mat = toon_sphere()
        set_ramp(mat, stops, smooth)
        helpers.add_camera((0.0, -6.0, 0.0))
        helpers.add_sun((1.0, -1.0, 0.5), strength=3.0)
        if lights > 1:
            helpers.add_sun((-1.0, -0.5, -0.3), strength=1.0, name="Fill")
        return helpers.render()

    def test_two_band_ramp_gives_exactly_two_surface_colours(self):
        for lights in (1, 2):
            rec = self.render_sphere([(0.0, DARK), (0.5, LIGHT)], lights=lights)
            colours, counts, total = surface_colours(rec)
            print(f"{lights} light(s): colours {colours.round(3).tolist()} counts {counts.tolist()}")
            self.assertEqual(len(colours), 2)
            np.testing.assert_allclose(sorted(map(tuple, colours)), sorted([DARK, LIGHT]), atol=1e-6)
            self.assertTrue((counts > 0.1 * total).all())
            # The whole image, lines and composite included, has the same two colours on the sphere.
            px = rec["pixels"][rec["surface"][..., 3] == 1.0][:, :3]
            self.assertEqual(len(np.unique(px, axis=0)), 2)

    def test_band_boundary_is_where_n_dot_l_crosses_the_stop(self):
        rec = self.render_sphere([(0.0, DARK), (0.5, LIGHT)])
        # Points on the sphere where N.L is just above / below 0.5 fall in the light / dark band.
        L = np.array((1.0, -1.0, 0.5)) / np.linalg.norm((1.0, -1.0, 0.5))
        V = np.array((0.0, -1.0, 0.0))  # towards the camera
        side = np.cross(L, V)
        side /= np.linalg.norm(side)
        perp = np.cross(side, L)  # unit, with L and side an orthonormal frame
        for nl, expected in ((0.56, LIGHT), (0.44, DARK), (0.9, LIGHT), (0.1, DARK)):
            n = nl * L + np.sqrt(1 - nl * nl) * perp  # a normal facing the camera with this N.L
            if np.dot(n, V) < 0:  # keep the point on the hemisphere facing the camera
                n = nl * L - np.sqrt(1 - nl * nl) * perp
            xy = helpers.project(rec, [n])[0]
            np.testing.assert_allclose(helpers.sample(rec["surface"], xy)[:3], expected, atol=1e-6, err_msg=f"N.L {nl}")

    def test_smooth_ramp_blends_between_stops(self):
        rec = self.render_sphere([(0.0, DARK), (1.0, LIGHT)], smooth=True)
        colours, _, _ = surface_colours(rec)
        self.assertGreater(len(colours), 50)
        lo, hi = np.minimum(DARK, LIGHT), np.maximum(DARK, LIGHT)
        self.assertTrue(((colours >= lo - 1e-6) & (colours <= hi + 1e-6)).all())


class RampData(unittest.TestCase):
    """The ramp lives in a node group of its own: the user's node trees are untouched, and a
    copied material shares the ramp until Make Single User."""

    def test_ramp_leaves_the_material_tree_alone_and_copies_share_it(self):
        helpers.empty_scene()
        color_ramp = helpers.addon().extract.color_ramp
        mat = bpy.data.materials.new("Toon")
        mat.use_nodes = True
        nodes_before = sorted(n.name for n in mat.node_tree.nodes)
        set_ramp(mat, [(0.0, DARK), (0.5, LIGHT)])
        self.assertEqual(sorted(n.name for n in mat.node_tree.nodes), nodes_before)
        self.assertEqual(mat.edgelight.shade_ramp.users, 1)
        copy = mat.copy()
        self.assertEqual(copy.edgelight.shade_ramp, mat.edgelight.shade_ramp)
        self.assertEqual(mat.edgelight.shade_ramp.users, 2)
        with bpy.context.temp_override(material=copy):
            bpy.ops.edgelight.ramp_single_user()
        self.assertNotEqual(copy.edgelight.shade_ramp, mat.edgelight.shade_ramp)
        self.assertEqual((mat.edgelight.shade_ramp.users, copy.edgelight.shade_ramp.users), (1, 1))
        self.assertEqual(color_ramp.stops_of(copy.edgelight), color_ramp.stops_of(mat.edgelight))


class XToon(unittest.TestCase):
    def test_colour_follows_distance_through_the_image(self):
        helpers.empty_scene(400, 200, highlights=False)
        near_ob, mat = toon_sphere((-1.6, 0.0, 0.0))
        far_ob, _ = toon_sphere((6.0, 14.0, 0.0))
        far_ob.data.materials[0] = mat
        img = bpy.data.images.new("xtoon", 8, 8, float_buffer=True)
        # Bottom rows red, top rows blue, the same across x: the colour depends on y only.
        rows = np.linspace(0.0, 1.0, 8)
        px = np.zeros((8, 8, 4), np.float32)
        px[..., 0] = (1.0 - rows)[:, None]
        px[..., 2] = rows[:, None]
        px[..., 3] = 1.0
        img.pixels.foreach_set(px.ravel())
        s = mat.edgelight
        s.shading, s.xtoon_image, s.xtoon_axis = 'XTOON', img, 'DEPTH'
        s.xtoon_near, s.xtoon_far = 4.0, 20.0
        cam = helpers.add_camera((0.0, -6.0, 0.0), target=(0.0, 0.0, 0.0), lens=35.0)
        helpers.add_sun((0.3, -1.0, 0.4))
        rec = helpers.render()
        view = np.linalg.inv(np.array(cam.matrix_world))
        for ob in (near_ob, far_ob):
            centre = np.array(ob.location)
            front = centre + (np.array(cam.location) - centre) / np.linalg.norm(np.array(cam.location) - centre)
            depth = -(view @ np.r_[front, 1.0])[2]
            y = np.clip((depth - 4.0) / 16.0, 0, 1)
            got = helpers.sample(rec["surface"], helpers.project(rec, [front])[0])[:3]
            print(f"{ob.name}: depth {depth:.2f} -> y {y:.3f}: colour {np.round(got, 4)}")
            np.testing.assert_allclose(got, (1.0 - y, 0.0, y), atol=0.01)
        near_c = helpers.sample(rec["surface"], helpers.project(rec, [near_ob.location])[0])
        far_c = helpers.sample(rec["surface"], helpers.project(rec, [far_ob.location])[0])
        self.assertGreater(near_c[0] - far_c[0], 0.5, "the near sphere is redder")
        self.assertGreater(far_c[2] - near_c[2], 0.5, "the far sphere is bluer")

    def test_orientation_axis_and_builtin_map(self):
        helpers.empty_scene(300, 300, highlights=False)
        _, mat = toon_sphere()
        mat.edgelight.shading = 'XTOON'
        mat.edgelight.xtoon_axis = 'ORIENTATION'
        helpers.add_camera((0.0, -6.0, 0.0))
        helpers.add_sun((0.0, -1.0, 0.0))  # behind the camera: N.L = N.V, x and y move together
        rec = helpers.render()
        surf = rec["surface"]
        centre = helpers.sample(surf, np.array([150.0, 150.0]))[:3]
        rim = helpers.sample(surf, helpers.project(rec, [(0.97, -0.24, 0.0)])[0])[:3]
        # The built-in map: lit material colour facing the eye, greyer and darker at the outline.
        self.assertGreater(centre.sum(), rim.sum() + 0.3)

    def xtoon_scene(self, make_image):
        """A toon sphere with make_image() as its X-Toon map along depth, the near and far limits
        straddling the sphere's front (y about 0.25); returns (material, image)."""
        helpers.empty_scene(200, 200, highlights=False)
        _, mat = toon_sphere()
        img = make_image()
        s = mat.edgelight
        s.shading, s.xtoon_image, s.xtoon_axis = 'XTOON', img, 'DEPTH'
        s.xtoon_near, s.xtoon_far = 3.0, 11.0
        helpers.add_camera((0.0, -6.0, 0.0), target=(0.0, 0.0, 0.0), lens=35.0)
        helpers.add_sun((0.3, -1.0, 0.4))
        return mat, img

    def test_a_map_past_the_texture_limit_is_reduced(self):
        """20000 x 2 (past every GPU's texture limit: it failed the frame with a raw `unknown
        error`) and 4096 x 4096 render as the same ramp at MAP_MAX x 8 (averaged down to at most
        MAP_MAX texels an axis, a ramp stays a ramp)."""
        toon = helpers.addon().passes.toon
        colours = {}
        def ramp_image(w, h):
            img = bpy.data.images.new(f"xtoon_{w}", w, h, float_buffer=True)
            px = np.zeros((h, w, 4), np.float32)
            px[..., 1] = (np.arange(w) + 0.5) / w  # green rises with lighting (x)
            px[..., 2] = 0.25
            px[..., 3] = 1.0
            img.pixels.foreach_set(px.ravel())
            return img

        for w, h in ((toon.MAP_MAX, 8), (20000, 2), (4096, 4096)):
            _, img = self.xtoon_scene(lambda: ramp_image(w, h))
            rec = helpers.render()
            self.assertFalse([r for r in rec.get("reports", []) if "rror" in str(r)], rec.get("reports"))
            colours[w] = helpers.sample(rec["surface"], np.array([100.0, 100.0]))[:3]
            texels = toon.image_texels(img)
            self.assertLessEqual(max(texels.shape[:2]), toon.MAP_MAX)
            # The reduction keeps the mean of each span: x's ramp stays a ramp.
            np.testing.assert_allclose(texels[0, :, 1], (np.arange(texels.shape[1]) + 0.5) / texels.shape[1], atol=1e-4)
        print(f"X-Toon maps of {toon.MAP_MAX} x 8, 20000 x 2, 4096 x 4096:", {k: np.round(v, 4) for k, v in colours.items()})
        np.testing.assert_allclose(colours[20000], colours[toon.MAP_MAX], atol=0.002)
        np.testing.assert_allclose(colours[4096], colours[toon.MAP_MAX], atol=0.002)

    def test_a_missing_file_is_reported_as_missing(self):
        def missing():
            img = bpy.data.images.new("xtoon_missing", 4, 4)
            img.source = 'FILE'
            img.filepath = os.path.join(tempfile.gettempdir(), "edgelight_no_such_xtoon.png")
            return img

        mat, img = self.xtoon_scene(missing)
        rec = helpers.render()
        reports = " | ".join(str(r) for r in rec.get("reports", []))
        self.assertIn(f"material '{mat.name}': X-Toon image '{img.name}': its file", reports)
        self.assertIn("is not found; the built-in map is used", reports)
        self.assertNotIn("0 x 0", reports)


if __name__ == "__main__":
    unittest.main()
