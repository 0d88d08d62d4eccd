"""What a new artist's first F12 shows: the defaults make rounded edges visible on Blender's
default scene (docs/addon.md, "Defaults"), and files made with the older defaults keep their look."""
import os
import tempfile
import unittest

import addon_utils
import bpy
import numpy as np

import helpers

# The default cube's edge nearest the default camera.
FRONT_EDGE = ((1.0, -1.0, -1.0), (1.0, -1.0, 1.0))


def default_scene():
    """Blender's startup scene (cube, camera, light at 1920 x 1080), drawn by EdgeLight."""
    bpy.ops.wm.read_factory_settings(use_empty=False)
    addon_utils.enable(helpers.MODULE, default_set=True)  # a factory reset disables add-ons
    bpy.context.scene.render.engine = "EDGELIGHT"
    return bpy.context.scene


def band_pixels(rec):
    """Median over the front edge's middle of how many pixels across it the highlight changes
    by more than 2 % (the band an artist sees)."""
    change = helpers.highlight_change(rec)[..., None]
    profile = helpers.edge_profile(rec, change, *FRONT_EDGE, np.linspace(0.3, 0.7, 9), np.arange(-30, 31))
    return float(np.median((profile[..., 0] > 0.02).sum(axis=1)))


class DefaultCube(unittest.TestCase):
    def test_first_render_shows_rounded_edges(self):
        scene = default_scene()
        self.assertEqual((scene.render.resolution_x, scene.render.resolution_y), (1920, 1080))
        material = bpy.data.materials["Material"]
        self.assertEqual(len(material.edgelight.keys()), 0, "the artist has set nothing")
        width = band_pixels(helpers.render())
        # 5 cm on the 2 m cube at 1080p changes 20 pixels across the edge; the old 1 cm changed 5
        # (2 of them clearly, docs/addon.md, "Defaults").
        self.assertGreaterEqual(width, 12, "the default radius makes a band an artist can see")

    def test_default_is_the_bevel_nodes(self):
        # Cycles' Bevel node, the render EdgeLight previews, starts at the same radius.
        scene = default_scene()
        del scene
        node = bpy.data.materials.new("Probe")
        node.use_nodes = True
        bevel = node.node_tree.nodes.new("ShaderNodeBevel")
        self.assertAlmostEqual(bpy.data.materials["Material"].edgelight.radius, bevel.inputs["Radius"].default_value, 6)


class OldFilesKeepTheirLook(unittest.TestCase):
    def test_stored_settings_without_radius_keep_one_cm(self):
        # Layout 2's toon materials store their ramps but no radius: they drew at 1 cm.
        bpy.ops.wm.open_mainfile(filepath=os.path.join(helpers.ROOT, "tests", "data", "settings_layout2.blend"))
        for name in ("Stepped", "Smooth", "NoStops"):
            group = bpy.data.materials[name].edgelight
            self.assertAlmostEqual(group.radius, 0.01, 6, name)
            self.assertEqual(group.get("settings_version"), helpers.addon().host.properties.SETTINGS_VERSION)
        self.assertAlmostEqual(bpy.data.materials["Cube"].edgelight.radius, 0.02, 6, "a stored radius stays")

    def saved_untouched(self, stamped):
        """A saved file drawn by EdgeLight with a material that stores nothing; without the
        scene's stamp it reads as one saved before layout 5."""
        scene = default_scene()
        scene.edgelight.samples = 2  # stored: the scene group has keys
        path = os.path.join(tempfile.mkdtemp(), "untouched.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        if not stamped:
            del scene.edgelight["settings_version"]
            self.save_without_stamps(path)
        self.assertEqual(len(bpy.data.materials["Material"].edgelight.keys()), 0)
        bpy.ops.wm.open_mainfile(filepath=path)
        return bpy.data.materials["Material"].edgelight

    def save_without_stamps(self, path):
        """Saves as an older add-on (or an autosave, which runs no save handler) would."""
        versioning = helpers.addon().host.versioning
        bpy.app.handlers.save_pre.remove(versioning._save_pre)
        try:
            bpy.ops.wm.save_as_mainfile(filepath=path)
        finally:
            bpy.app.handlers.save_pre.append(versioning._save_pre)

    def test_old_materials_say_so_when_the_scene_does_not(self):
        # Saved with layout 4 by a scene since switched to another engine, storing nothing of
        # EdgeLight's: a material's stamp 4 says the file is older.
        default_scene().render.engine = helpers.addon().compat.eevee_engine_id()
        old = bpy.data.materials.new("Stamped")
        old.use_fake_user = True
        old.edgelight["K"], old.edgelight["settings_version"] = 0.5, 4
        path = os.path.join(tempfile.mkdtemp(), "layout4.blend")
        self.save_without_stamps(path)
        bpy.ops.wm.open_mainfile(filepath=path)
        self.assertAlmostEqual(bpy.data.materials["Material"].edgelight.radius, 0.01, 6)
        self.assertAlmostEqual(bpy.data.materials["Stamped"].edgelight.radius, 0.01, 6)

    def test_a_scene_added_since_the_save_is_no_old_file(self):
        # A current file, then a scene added and saved by an autosave (no save handler): the
        # stamped scene says the file is current.
        scene = default_scene()
        scene.edgelight.samples = 2
        path = os.path.join(tempfile.mkdtemp(), "current.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        extra = bpy.data.scenes.new("Added")
        extra.render.engine = 'EDGELIGHT'
        self.save_without_stamps(path)
        bpy.ops.wm.open_mainfile(filepath=path)
        group = bpy.data.materials["Material"].edgelight
        self.assertAlmostEqual(group.radius, 0.05, 6)
        self.assertEqual(len(group.keys()), 0)

    def test_an_older_material_pasted_in_is_upgraded_on_save(self):
        # A layout-4 material appended into a current file keeps its 1 cm when saved, instead
        # of being stamped current with nothing stored.
        default_scene().edgelight.samples = 2
        pasted = bpy.data.materials.new("Pasted")
        pasted.use_fake_user = True
        pasted.edgelight["K"], pasted.edgelight["settings_version"] = 0.5, 4
        path = os.path.join(tempfile.mkdtemp(), "pasted.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        self.assertAlmostEqual(bpy.data.materials["Pasted"].edgelight.radius, 0.01, 6)
        self.assertAlmostEqual(bpy.data.materials["Material"].edgelight.radius, 0.05, 6)

    def test_a_scene_of_another_engine_gets_no_edgelight_data(self):
        default_scene().render.engine = helpers.addon().compat.eevee_engine_id()
        path = os.path.join(tempfile.mkdtemp(), "eevee.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        self.assertEqual(len(bpy.context.scene.edgelight.keys()), 0)

    def test_unstamped_file_keeps_old_default(self):
        self.assertAlmostEqual(self.saved_untouched(stamped=False).radius, 0.01, 6)

    def test_current_file_takes_new_default_and_stores_nothing(self):
        group = self.saved_untouched(stamped=True)
        self.assertAlmostEqual(group.radius, 0.05, 6)
        self.assertEqual(len(group.keys()), 0, "defaults add no data")


if __name__ == "__main__":
    unittest.main()
