"""Large settings degrade gracefully: Highlight Strength cannot pass 1 (older
files move the excess into the radius), and the material panel says when the radius is clamped
to what an edge's faces allow."""
import gc
import math
import unittest

import bpy

import helpers
import scene_zoo as zoo


def material_settings():
    return bpy.types.Material.bl_rna.properties["edgelight"].fixed_type.properties


class HighlightStrength(unittest.TestCase):
    def test_at_most_one(self):
        k = material_settings()["K"]
        self.assertEqual((k.hard_min, k.hard_max, k.soft_max), (0.0, 1.0, 1.0))
        mat = bpy.data.materials.new("Strong")
        mat.edgelight.K = 3.0
        self.assertEqual(mat.edgelight.K, 1.0, "Blender clamps a set value to the maximum")
        mat.edgelight.K = 0.4
        self.assertAlmostEqual(mat.edgelight.K, 0.4, places=6)

    def test_a_stored_value_past_the_cap_draws_as_the_cap(self):
        # Blender does not clamp a stored value on read (a linked file of an older layout).
        mat = bpy.data.materials.new("Linked")
        mat.edgelight["K"] = 2.5
        self.assertAlmostEqual(mat.edgelight.K, 2.5, places=6)
        self.assertEqual(helpers.addon().extract.materials.shading_of(mat).K, 1.0)

    def layout3_group(self, k, radius=None):
        mat = bpy.data.materials.new("Old")
        group = mat.edgelight
        group["K"] = k
        if radius is not None:
            group["radius"] = radius
        group["settings_version"] = 3
        return group

    def test_layout_3_strength_moves_into_the_radius(self):
        versioning = helpers.addon().host.versioning
        group = self.layout3_group(2.5, 0.02)
        self.assertEqual(versioning.upgrade(group, "material"), 3)
        self.assertAlmostEqual(group.K, 1.0, places=6)
        self.assertAlmostEqual(group.radius, 0.05, places=6)
        self.assertEqual(group.get("settings_version"), helpers.addon().host.properties.SETTINGS_VERSION)
        # The default radius (not stored) is the one multiplied.
        group = self.layout3_group(3.0)
        versioning.upgrade(group, "material")
        self.assertAlmostEqual(group.radius, 0.03, places=6)
        # In range: untouched.
        group = self.layout3_group(0.7, 0.02)
        versioning.upgrade(group, "material")
        self.assertAlmostEqual(group.K, 0.7, places=6)
        self.assertAlmostEqual(group.radius, 0.02, places=6)


def cube_scene(radius, size=2.0):
    """A `size` m cube (90 degree edges: its faces allow radius size / 2) rounded at `radius`."""
    helpers.empty_scene(200, 150)
    helpers.add_camera((4.5, -5.5, 4.0))
    helpers.add_sun()
    cube = zoo.box("Cube", size)
    mat = zoo.material("Steel", (0.5, 0.5, 0.55))
    mat.edgelight.radius = radius
    cube.data.materials.append(mat)
    return mat


def extract():
    """What a render extracts (scene_sync.collect): no GPU needed."""
    el = helpers.addon()
    lib, error = el.host.engine.load_library()
    if lib is None:
        raise AssertionError(f"native library: {error}")
    return el.extract.scene_sync.collect(bpy.context.evaluated_depsgraph_get(), lib=lib)


def notes():
    """What the material panel's note reads (host/clamp_notes.py)."""
    return helpers.addon().host.clamp_notes.NOTES


def rendered(layer="ViewLayer"):
    """A render's extraction, handed to the notes as the engine hands it (for view layer `layer`)."""
    data = extract()
    notes().rendered(layer, (inst.mesh for inst in data.instances))
    return data


class RadiusClampNote(unittest.TestCase):
    def setUp(self):
        notes().clear()

    def test_clamped_edges_are_counted_for_the_panel(self):
        el = helpers.addon()
        mat = cube_scene(5.0)
        before = {k: mat.edgelight.get(k) for k in mat.edgelight.keys()}
        data = rendered()
        self.assertEqual(len(data.instances[0].mesh.clamps), 1, "one material's counts")
        clamped, rounded, smallest = notes().radius_clamps(mat)
        self.assertEqual((clamped, rounded), (12, 12), "every edge of the 2 m cube")
        self.assertAlmostEqual(smallest, 1.0, places=5, msg="its faces allow 1 m")
        note = el.host.ui.radius_clamp_note(mat, bpy.context.scene)
        self.assertEqual(len(note), 2)
        self.assertEqual(note[0], "12 of 12 edges clamped")
        self.assertIn("1 m", note[1])
        self.assertEqual({k: mat.edgelight.get(k) for k in mat.edgelight.keys()}, before, "nothing written to the material")
        # Another radius: unknown until the edges are picked again, then counted anew.
        mat.edgelight.radius = 0.5
        self.assertIsNone(notes().radius_clamps(mat))
        self.assertEqual(el.host.ui.radius_clamp_note(mat, bpy.context.scene), ())
        del data
        gc.collect()
        data = rendered()
        self.assertEqual(notes().radius_clamps(mat), (0, 12, math.inf))
        self.assertEqual(el.host.ui.radius_clamp_note(mat, bpy.context.scene), (), "no note when nothing is clamped")
        del data

    def test_extraction_itself_records_nothing(self):
        """The edge choice returns its counts with the extraction; only their owners (the
        engine, the viewport) hand them to the notes."""
        mat = cube_scene(5.0)
        data = extract()
        self.assertIsNone(notes().radius_clamps(mat))
        self.assertEqual((data.instances[0].mesh.clamps[0].clamped, data.instances[0].mesh.clamps[0].rounded), (12, 12))

    def test_each_material_counts_its_own_edges(self):
        """A 2 m cube at radius 5 with its top face of another material at radius 0.5: the top's
        4 edges take the smaller radius (0.5, within the 1 m its faces allow), so only the 8
        others are clamped, and they are the first material's alone."""
        mat = cube_scene(5.0)
        cube = bpy.data.objects["Cube"]
        top = zoo.material("Top", (0.8, 0.3, 0.2))
        top.edgelight.radius = 0.5
        cube.data.materials.append(top)
        cube.data.polygons[5].material_index = 1  # scene_zoo.box: face 5 is +z
        data = rendered()
        self.assertEqual(notes().radius_clamps(mat)[:2], (8, 12))
        self.assertEqual(notes().radius_clamps(top), (0, 4, math.inf))
        del data

    def test_the_last_render_is_kept_and_only_held_geometry_counts(self):
        mat = cube_scene(5.0)
        rendered()  # freed at once, as a final render's extraction: still what the panel shows
        gc.collect()
        self.assertEqual(notes().radius_clamps(mat)[:2], (12, 12))
        # A geometry the viewport holds replaces what the last render counted (a mesh edited
        # in the Rendered viewport is extracted anew: no double counting).
        held = [extract().instances[0].mesh for _ in range(2)]
        notes().hold(held[0])
        notes().hold(held[1])
        self.assertEqual(notes().radius_clamps(mat)[:2], (24, 24), "two held geometries")
        notes().hold(held[0])  # held again (its edges chosen again): counted once
        self.assertEqual(notes().radius_clamps(mat)[:2], (24, 24))
        held.pop()
        gc.collect()
        self.assertEqual(notes().radius_clamps(mat)[:2], (12, 12))
        held.pop()
        gc.collect()
        self.assertEqual(notes().radius_clamps(mat)[:2], (12, 12), "none held: the last render's again")

    def test_every_view_layer_counts_each_geometry_once(self):
        """Two layers that drew the cube: its edges count once. A layer rendered again replaces
        only its own counts: a layer without the cube leaves the other's."""
        mat = cube_scene(5.0)
        meshes = [inst.mesh for inst in extract().instances]  # the layers' renders share the job's extractions
        notes().rendered("A", meshes)
        notes().rendered("B", meshes)
        self.assertEqual(notes().radius_clamps(mat)[:2], (12, 12))
        notes().rendered("B", ())  # B again, without the cube
        self.assertEqual(notes().radius_clamps(mat)[:2], (12, 12), "A's counts stay")
        notes().rendered("A", ())
        self.assertIsNone(notes().radius_clamps(mat))

    def test_a_final_render_counts_for_the_note(self):
        helpers.needs_gpu()
        mat = cube_scene(5.0)
        helpers.render()
        self.assertEqual(notes().radius_clamps(mat)[:2], (12, 12))

    def test_the_note_is_drawn_in_the_material_panel(self):
        mat = cube_scene(5.0)
        data = rendered()
        labels = []

        class Layout:  # records what the panel draws
            def __getattr__(self, name):
                return lambda *args, **kwargs: Layout()

            def label(self, text="", icon='NONE'):
                labels.append(text)

            def column(self, *args, **kwargs):
                return self

        panel = helpers.addon().host.ui.EDGELIGHT_PT_material
        context = type("Context", (), {"material": mat, "scene": bpy.context.scene})()
        fake = type("Panel", (), {"layout": Layout()})()
        panel.draw(fake, context)
        self.assertTrue("12 of 12 edges clamped" in labels, labels)
        del data


if __name__ == "__main__":
    unittest.main()
