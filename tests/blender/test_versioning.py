"""A .blend saved with an older settings layout opens with its settings intact.

tests/data/settings_layout1.blend was saved by Blender 3.4 with the layout-1 add-on
(tests/data/make_settings_layout1.py), where the material toggle was called `enabled`.
"""
import math
import os
import tempfile
import unittest

import bpy

import helpers

LAYOUT1 = os.path.join(helpers.ROOT, "tests", "data", "settings_layout1.blend")


def current_layout():
    return helpers.addon().host.properties.SETTINGS_VERSION


class SampleIsLayout1(unittest.TestCase):
    def test_linked_material_keeps_the_old_layout(self):
        # Linked data is not upgraded (it belongs to its file): it shows what the file stores.
        helpers.open_sample("cube")
        with bpy.data.libraries.load(LAYOUT1, link=True) as (src, dst):
            dst.materials = ["Cube"]
        group = dst.materials[0].edgelight
        self.assertIn("enabled", group.keys())
        self.assertEqual(group["enabled"], False)
        self.assertNotIn("use_rounding", group.keys())
        self.assertIsNone(group.get("settings_version"), "layout 1 files carry no stamp")


class OpensUpgraded(unittest.TestCase):
    def check_values(self):
        cube = bpy.data.materials["Cube"].edgelight
        self.assertFalse(cube.use_rounding, "enabled=False became use_rounding=False")
        # K = 2.5 is past layout 4's cap: K 1 and the radius times 2.5 (versioning._material_3_to_4).
        self.assertAlmostEqual(cube.K, 1.0, places=6)
        self.assertAlmostEqual(cube.radius, 0.033 * 2.5, places=6)
        self.assertEqual(tuple(round(c, 6) for c in cube.tint), (0.2, 0.4, 0.6))
        self.assertEqual(set(cube.selection), {'SHARP', 'ANGLE'})
        self.assertAlmostEqual(cube.angle, math.radians(40.0), places=6)
        self.assertTrue(cube.use_custom_shininess)
        self.assertEqual(cube.shininess, 123.0)
        spare = bpy.data.materials["Spare"].edgelight
        self.assertTrue(spare.use_rounding)
        self.assertAlmostEqual(spare.radius, 0.05, places=6)
        scene = bpy.context.scene.edgelight
        self.assertEqual((scene.samples, scene.viewport_samples, scene.highlights), (5, 3, True))
        for group in (cube, spare, scene):
            self.assertEqual(group.get("settings_version"), current_layout())
            self.assertNotIn("enabled", group.keys(), "the old key is gone once moved")

    def test_values_intact_after_open(self):
        bpy.ops.wm.open_mainfile(filepath=LAYOUT1)
        self.check_values()

    def test_values_intact_after_save_and_reopen(self):
        bpy.ops.wm.open_mainfile(filepath=LAYOUT1)
        path = os.path.join(tempfile.mkdtemp(), "upgraded.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        self.check_values()

    def test_upgraded_setting_drives_the_render(self):
        bpy.ops.wm.open_mainfile(filepath=LAYOUT1)
        bpy.context.scene.edgelight.samples = 1
        off = helpers.render(resolution=(160, 120))
        self.assertEqual(off["stats"].edges_drawn, 0, "rounding was off in the old file")
        bpy.data.materials["Cube"].edgelight.use_rounding = True
        on = helpers.render(resolution=(160, 120))
        self.assertGreater(on["stats"].edges_drawn, 0)


LAYOUT2 = os.path.join(helpers.ROOT, "tests", "data", "settings_layout2.blend")
# What the layout-2 file's toon materials rendered with (tests/data/make_settings_layout2.py).
STEPPED = ((0.0, (0.05, 0.07, 0.12)), (0.3, (0.22, 0.3, 0.45)), (0.75, (0.55, 0.68, 0.85)))
SMOOTH = ((0.1, (1.0, 0.0, 0.0)), (0.9, (0.0, 0.0, 1.0)))


class RampStopsBecomeAColourRamp(unittest.TestCase):
    def check(self):
        el = helpers.addon()
        for name, stops, interpolation in (("Stepped", STEPPED, 'CONSTANT'), ("Smooth", SMOOTH, 'LINEAR')):
            s = bpy.data.materials[name].edgelight
            ramp = el.extract.color_ramp.ramp_of(s)
            self.assertIsNotNone(ramp, name)
            self.assertEqual(ramp.interpolation, interpolation, name)
            toon = el.extract.materials.toon_of(s, (0.5, 0.5, 0.5))
            self.assertEqual(toon.smooth, interpolation == 'LINEAR')
            self.assertEqual(len(toon.ramp), len(stops))
            for (p, c), (want_p, want_c) in zip(toon.ramp, stops):
                self.assertAlmostEqual(p, want_p, places=6)
                self.assertEqual(tuple(round(v, 6) for v in c), want_c)
            for key in ("ramp", "ramp_interpolation", "ramp_index"):
                self.assertNotIn(key, s.keys())
            self.assertEqual(s.get("settings_version"), current_layout())
        none = bpy.data.materials["NoStops"]
        self.assertIsNone(none.edgelight.shade_ramp, "an empty list stays the default two bands")
        base = el.extract.materials.base_color_of(none)
        self.assertEqual(el.extract.materials.toon_of(none.edgelight, base).ramp, el.extract.materials.default_ramp(base))
        self.assertIsNone(bpy.data.materials["Cube"].edgelight.shade_ramp)

    def test_upgraded_on_open(self):
        bpy.ops.wm.open_mainfile(filepath=LAYOUT2)
        self.check()

    def test_ramp_survives_save_and_reopen(self):
        bpy.ops.wm.open_mainfile(filepath=LAYOUT2)
        path = os.path.join(tempfile.mkdtemp(), "ramps.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        self.check()
        groups = [g for g in bpy.data.node_groups if g.name.startswith(".EdgeLight")]
        self.assertEqual(len(groups), 2, "one ramp per toon material, nothing else added")


class ShadowsAreNewInLayout6(unittest.TestCase):
    def test_a_scene_of_layout_5_keeps_drawing_no_shadows_and_a_new_one_draws_them(self):
        """Layout 6 added cast shadows, on by default (versioning._scene_5_to_6): a scene saved
        with layout 5 drew none and opens with Shadows off; a scene made now has them on."""
        scene = helpers.empty_scene(64, 64)
        self.assertTrue(scene.edgelight.use_shadows, "on for a scene made now")
        scene.edgelight.samples = 2
        path = os.path.join(tempfile.mkdtemp(), "layout5.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        self.assertTrue(bpy.context.scene.edgelight.use_shadows, "a current file keeps its Shadows")
        bpy.context.scene.edgelight["settings_version"] = 5  # as the layout-5 add-on stamped it
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        group = bpy.context.scene.edgelight
        self.assertFalse(group.use_shadows)
        self.assertEqual(group.samples, 2)
        self.assertEqual(group.get("settings_version"), current_layout())
        for sample in (LAYOUT1, os.path.join(helpers.SAMPLES, "cube.blend")):  # older layouts: none either
            bpy.ops.wm.open_mainfile(filepath=sample)
            self.assertFalse(bpy.context.scene.edgelight.use_shadows, sample)


class CurrentFilesAreStamped(unittest.TestCase):
    def test_save_stamps_groups_that_store_settings(self):
        helpers.open_sample("cube")
        bpy.data.materials["Cube"].edgelight.use_rounding = False
        untouched = bpy.data.materials.new("Untouched")
        untouched.use_fake_user = True
        path = os.path.join(tempfile.mkdtemp(), "current.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        cube = bpy.data.materials["Cube"].edgelight
        self.assertEqual(cube.get("settings_version"), current_layout())
        self.assertFalse(cube.use_rounding)
        self.assertEqual(len(bpy.data.materials["Untouched"].edgelight.keys()), 0, "defaults add no data")


if __name__ == "__main__":
    unittest.main()
