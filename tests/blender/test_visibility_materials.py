"""The edge pass's depth test, and the rule for edges between two materials."""
import unittest

import bpy
import numpy as np

import helpers

A, B = np.array((-1.0, -1.0, 1.0)), np.array((1.0, -1.0, 1.0))  # the cube sample's glinting edge


class DepthTest(unittest.TestCase):
    def test_no_leak_through_a_nearer_object_and_no_z_fighting(self):
        helpers.open_sample("cube")
        cam = bpy.context.scene.camera
        # A small card between the camera and the middle of the glinting edge.
        mid = 0.5 * (A + B)
        eye = np.array(cam.matrix_world.translation)
        centre = mid + 0.3 * (eye - mid)
        me = bpy.data.meshes.new("Card")
        s = 0.12
        me.from_pydata([tuple(centre + d) for d in ((-s, -s, -s), (s, -s, -s), (s, s, s), (-s, s, s))], [], [(0, 1, 2, 3)])
        card = bpy.data.objects.new("Card", me)
        bpy.context.scene.collection.objects.link(card)
        rec = helpers.render(resolution=(640, 480))
        hl = rec["highlight"][..., 3]
        ts = np.linspace(0.0, 1.0, 201)
        xy = helpers.project(rec, A[None] + ts[:, None] * (B - A)[None])
        card_xy = helpers.project(rec, [centre])[0]
        near_card = np.linalg.norm(xy - card_xy, axis=1) < 3.0
        far = np.linalg.norm(xy - card_xy, axis=1) > 40.0
        on_line = helpers.sample(hl[..., None], xy)[:, 0]
        self.assertGreater(near_card.sum(), 2)
        self.assertTrue((on_line[near_card] == 0.0).all(), "the card hides the edge: no highlight leaks through")
        self.assertTrue((on_line[far & (ts > 0.05) & (ts < 0.95)] > 0.0).all(), "elsewhere the edge is not z-fighting")


class TwoMaterials(unittest.TestCase):
    def render_with_top(self, enabled, radius=None):
        helpers.open_sample("cube")
        ob = bpy.data.objects["Cube"]
        top = bpy.data.materials["Cube"].copy()
        top.name = "Top"
        top.edgelight.use_rounding = enabled
        if radius is not None:
            top.edgelight.radius = radius
        ob.data.materials.append(top)
        for p in ob.data.polygons:
            if p.normal.z > 0.9:
                p.material_index = 1
        return helpers.render(resolution=(320, 240))

    def test_both_materials_must_enable_rounding(self):
        self.assertEqual(self.render_with_top(True)["stats"].edges_drawn, 12)
        self.assertEqual(self.render_with_top(False)["stats"].edges_drawn, 8, "the top face's 4 edges are not rounded")

    def test_shared_edges_take_the_smaller_radius(self):
        rec = self.render_with_top(True, radius=0.005)
        ex = rec["scene"].instances[0].mesh
        radii = np.concatenate([e.radius for e in ex.edges.values()])
        self.assertEqual(int((radii == np.float32(0.005)).sum()), 4)
        self.assertEqual(int((radii == np.float32(0.02)).sum()), 8)


if __name__ == "__main__":
    unittest.main()
