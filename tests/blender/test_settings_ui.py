"""What the settings tell an artist: tooltips, units, the Freestyle crease convention, and line
widths that keep their size when the unit changes."""
import math
import unittest

import bpy
import numpy as np

import helpers


def groups():
    props = helpers.addon().host.properties
    return (props.EdgeLightMaterialSettings, props.EdgeLightSceneSettings, *props.LINE_STYLES)


class Tooltips(unittest.TestCase):
    def test_every_property_has_a_description(self):
        missing = [f"{g.__name__}.{p.identifier}" for g in groups() for p in g.bl_rna.properties
                   if p.identifier not in ("rna_type", "name") and not p.description.strip()]
        self.assertEqual(missing, [])

    def test_names_artists_read(self):
        rna = bpy.types.Material.bl_rna.properties["edgelight"].fixed_type.properties
        self.assertEqual(rna["K"].name, "Highlight Strength")
        self.assertIn("like the Bevel modifier", rna["radius"].description)


class CreaseConvention(unittest.TestCase):
    def test_freestyle_angle_is_180_minus_ours_both_ways(self):
        s = helpers.empty_scene().edgelight
        s.crease_angle = math.radians(45.0)
        self.assertAlmostEqual(math.degrees(s.crease_angle_faces), 135.0, places=4)
        s.crease_angle_faces = math.radians(134.43)  # Freestyle's default
        self.assertAlmostEqual(math.degrees(s.crease_angle), 180.0 - 134.43, places=4)
        self.assertNotIn("crease_angle_faces", s.keys(), "stores nothing of its own")


class WidthUnits(unittest.TestCase):
    def scene(self):
        scene = helpers.empty_scene(400, 400)
        s = helpers.only_lines(scene, border=4.0)
        bpy.ops.mesh.primitive_plane_add(size=2.0)
        helpers.add_camera((0.0, 0.0, 5.0), lens=50.0)
        helpers.add_sun((0.0, 0.0, 1.0))
        bpy.context.view_layer.update()  # the camera's matrix_world, as the UI has it
        return scene, s.line_border

    def test_switching_unit_converts_the_width(self):
        scene, st = self.scene()
        units = helpers.addon().host.line_units
        ppu = units.pixels_per_unit(scene)
        # 50 mm on a 36 mm sensor, 400 px wide, the plane 5 units away: 400 * 50 / 36 / 5.
        self.assertAlmostEqual(ppu, 400 * 50 / 36 / 5, delta=0.01)
        st.unit = 'SCENE'
        self.assertAlmostEqual(st.width, 4.0 / ppu, places=5)
        self.assertAlmostEqual(st.width_scene, st.width)
        st.unit = 'SCENE'  # no change, no conversion
        self.assertAlmostEqual(st.width, 4.0 / ppu, places=5)
        st.unit = 'PIXELS'
        self.assertAlmostEqual(st.width, 4.0, places=4)
        self.assertAlmostEqual(st.width_px, 4.0, places=4)

    def test_rendered_width_survives_the_switch(self):
        scene, st = self.scene()
        ink = {}
        for unit in ('PIXELS', 'SCENE'):
            st.unit = unit
            rec = helpers.render()
            x = int(helpers.project(rec, [(0.0, -1.0, 0.0)])[0][0])
            ink[unit] = rec["lines"][:200, x, 3].sum()  # across the y = -1 border: its width in pixels
        print("border width in pixels:", {k: round(float(v), 2) for k, v in ink.items()})
        self.assertAlmostEqual(ink['PIXELS'], 4.0, delta=0.5)
        self.assertAlmostEqual(ink['SCENE'], ink['PIXELS'], delta=0.3)


class RadiusIsObjectSpace(unittest.TestCase):
    """The radius scales with the object, like the Bevel modifier's Amount."""

    def band_width(self, object_scale):
        from mathutils import Matrix
        helpers.open_sample("cube")
        cube = bpy.data.objects["Cube"]
        bpy.data.materials["Cube"].edgelight.radius = 0.02
        # The same world geometry at either scale: the mesh shrinks as the object grows.
        cube.data.transform(Matrix.Scale(1.0 / object_scale, 4))
        cube.scale = (object_scale,) * 3
        rec = helpers.render(resolution=(640, 480))
        a, b = (-1.0, -1.0, 1.0), (1.0, -1.0, 1.0)  # the glinting edge (test_cube_pixels.py)
        alpha = rec["highlight"][..., 3:4]
        prof = helpers.edge_profile(rec, alpha, a, b, np.linspace(0.2, 0.8, 13), np.arange(-15.0, 15.25, 0.25))[..., 0]
        return prof.sum(axis=1) * 0.25  # coverage across the edge: the band's width in pixels

    def test_scale_2_draws_bands_twice_as_wide(self):
        one, two = self.band_width(1.0), self.band_width(2.0)
        print(f"band width in px at scale 1: {np.round(one.mean(), 2)}, scale 2: {np.round(two.mean(), 2)}")
        self.assertGreater(one.min(), 1.0)
        np.testing.assert_allclose(two / one, 2.0, rtol=0.1)


if __name__ == "__main__":
    unittest.main()
