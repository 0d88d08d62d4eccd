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
            self.assertEqual(group.get("settings_version"), helpers.addon().properties.SETTINGS_VERSION)
        self.assertAlmostEqual(bpy.data.materials["Cube"].edgelight.radius, 0.02, 6, "a stored radius stays")

    def saved_untouched(self, stamped):
        """A saved file drawn by EdgeLight with a material that stores nothing; without the
        scene's stamp it reads as one saved before layout 5."""
        scene = default_scene()
        scene.edgelight.samples = 2  # stored: the scene group has keys
        path = os.path.join(tempfile.mkdtemp(), "untouched.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        if not stamped:
            bpy.app.handlers.save_pre.remove(helpers.addon().versioning._save_pre)
            try:
                del scene.edgelight["settings_version"]
                bpy.ops.wm.save_as_mainfile(filepath=path)
            finally:
                bpy.app.handlers.save_pre.append(helpers.addon().versioning._save_pre)
        self.assertEqual(len(bpy.data.materials["Material"].edgelight.keys()), 0)
        bpy.ops.wm.open_mainfile(filepath=path)
        return bpy.data.materials["Material"].edgelight

    def test_unstamped_file_keeps_old_default(self):
        self.assertAlmostEqual(self.saved_untouched(stamped=False).radius, 0.01, 6)

    def test_current_file_takes_new_default_and_stores_nothing(self):
        group = self.saved_untouched(stamped=True)
        self.assertAlmostEqual(group.radius, 0.05, 6)
        self.assertEqual(len(group.keys()), 0, "defaults add no data")


if __name__ == "__main__":
    unittest.main()
