"""Orthographic and perspective cameras, every light type, transparent film, resolution %."""
import math
import unittest

import bpy
import numpy as np

import helpers


class Cameras(unittest.TestCase):
    def test_orthographic_matches_projection(self):
        helpers.open_sample("cube")
        cam = bpy.context.scene.camera.data
        cam.type = 'ORTHO'
        cam.ortho_scale = 6.0
        rec = helpers.render(resolution=(320, 240))
        self.assertTrue(rec["camera"].orthographic)
        hl = rec["highlight"]
        self.assertGreater((hl[..., 3] > 0).sum(), 100, "edges drawn in orthographic views too")
        # The cube's projected corners bound the covered pixels.
        corners = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
        xy = helpers.project(rec, corners)
        covered = np.argwhere(rec["surface"][..., 3] > 0)
        self.assertLessEqual(abs(covered[:, 1].min() - xy[:, 0].min()), 1.5)
        self.assertLessEqual(abs(covered[:, 1].max() + 1 - xy[:, 0].max()), 1.5)

    def test_resolution_percentage(self):
        helpers.open_sample("cube")
        s = bpy.context.scene
        s.render.resolution_x, s.render.resolution_y, s.render.resolution_percentage = 400, 300, 50
        self.assertEqual(helpers.render()["pixels"].shape, (150, 200, 4))


class Film(unittest.TestCase):
    def test_transparent_film_leaves_background_alpha_zero(self):
        helpers.open_sample("cube")
        bpy.context.scene.render.film_transparent = True
        px = helpers.render(resolution=(160, 120))["pixels"]
        self.assertEqual(px[0, 0, 3], 0.0)
        self.assertTrue(np.array_equal(px[0, 0], np.zeros(4, np.float32)))
        self.assertEqual(px[60, 80, 3], 1.0)

    def test_opaque_film_shows_the_world_colour(self):
        helpers.open_sample("cube")
        px = helpers.render(resolution=(160, 120))["pixels"]
        world = np.array(bpy.context.scene.world.color[:3], np.float32)
        self.assertTrue(np.allclose(px[0, 0, :3], world, atol=1e-6))
        self.assertEqual(px[0, 0, 3], 1.0)


class Lights(unittest.TestCase):
    def centre_brightness(self, kind, aim=(90.0, 0.0, 0.0), **props):
        helpers.open_sample("cube")
        for ob in [o for o in bpy.data.objects if o.type == 'LIGHT']:
            bpy.data.objects.remove(ob)
        light = bpy.data.lights.new("L", kind)
        for k, v in props.items():
            setattr(light, k, v)
        ob = bpy.data.objects.new("L", light)
        ob.location = (0.0, -6.0, 0.0)
        ob.rotation_euler = tuple(math.radians(a) for a in aim)  # default: along +y, at the front face
        bpy.context.scene.collection.objects.link(ob)
        helpers.set_world_color(bpy.context.scene, (0.0, 0.0, 0.0))
        rec = helpers.render(resolution=(160, 120))
        xy = helpers.project(rec, [(0.0, -1.0, 0.0)])[0]  # centre of the front face
        return helpers.luminance(helpers.sample(rec["surface"], xy[None])[0, :3])

    def test_point_light_inverse_square(self):
        # Front face centre at distance 5: irradiance P / (4 pi 25), radiance albedo E / pi.
        b = self.centre_brightness('POINT', energy=1000.0, shadow_soft_size=0.0)
        albedo = helpers.luminance(np.array(bpy.data.materials["Cube"].node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value[:3]))
        expected_diffuse = albedo * 1000.0 / (4 * math.pi * 25.0) / math.pi
        self.assertGreater(b, expected_diffuse * 0.99)   # plus a little specular
        self.assertLess(b, expected_diffuse * 1.5)

    def test_spot_light_lights_inside_the_cone_only(self):
        inside = self.centre_brightness('SPOT', energy=1000.0, spot_size=math.radians(40))
        self.assertGreater(inside, 0.05)
        # Turned 45 degrees away, the 40-degree cone misses the face centre.
        outside = self.centre_brightness('SPOT', aim=(90.0, 0.0, 45.0), energy=1000.0, spot_size=math.radians(40))
        self.assertLess(outside, 1e-6)

    def test_sun_and_area_light_the_face(self):
        self.assertGreater(self.centre_brightness('SUN', energy=3.0), 0.1)
        self.assertGreater(self.centre_brightness('AREA', energy=2000.0, size=1.0), 0.05)


if __name__ == "__main__":
    unittest.main()


class TooManyLights(unittest.TestCase):
    def test_lights_past_the_limit_are_reported(self):
        helpers.open_sample("cube")
        for i in range(20):
            light = bpy.data.lights.new(f"P{i}", 'POINT')
            ob = bpy.data.objects.new(f"P{i}", light)
            ob.location = (0.0, -5.0 - i, 2.0)
            bpy.context.scene.collection.objects.link(ob)
        rec = helpers.render(resolution=(64, 48))
        text = " | ".join(m for _, m in rec.get("messages", []))
        self.assertIn("21 lights; the 16 first are used", text)
