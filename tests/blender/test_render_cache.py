"""Extractions kept between final renders (addon/extract/render_cache.py): within a render job (an
animation) and, with the scene's Persistent Data on, from one job to the next. A render of
unchanged meshes reuses the last render's classification and draws the same image; an edited
mesh, a changed material or line settings are read afresh, and the image is the one a render
from nothing draws; what a frame no longer draws is dropped after one more frame; without
Persistent Data nothing is kept once a job ends."""
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo


def cache():
    return helpers.addon().extract.render_cache.EXTRACTS


def scene_with_box(persistent=True):
    scene = helpers.empty_scene(160, 120, use_lines=True)
    scene.render.use_persistent_data = persistent  # kept from one still render to the next
    helpers.add_camera((4.0, -5.0, 3.5))
    helpers.add_sun()
    box = zoo.box("Box", 2.0)
    mat = zoo.material("Grey", (0.6, 0.6, 0.6))
    mat.edgelight.radius = 0.05
    box.data.materials.append(mat)
    return box


def render():
    rec = helpers.render()
    return rec, np.asarray(rec["pixels"]).copy()


def native_of(rec, name):
    return next(inst.mesh.native for inst in rec["scene"].instances if inst.mesh.name == name)


def from_nothing():
    """The current scene rendered with nothing kept from earlier renders."""
    cache().clear()
    return render()[1]


class RenderCache(unittest.TestCase):
    def test_unchanged_meshes_are_reused(self):
        scene_with_box()
        first, image = render()
        second, again = render()
        self.assertIs(native_of(second, "Box"), native_of(first, "Box"))
        np.testing.assert_array_equal(again, image)

    def test_outline_records_are_kept_with_the_edges(self):
        """The fillets' outline records (rounded_outline.records, for the surface pass) follow
        from the chosen edges: a reused extraction does not compute them again, a radius change
        (edges chosen again) does, and the image is the one a render from nothing draws."""
        box = scene_with_box()
        outline = helpers.addon().geometry.rounded_outline
        calls, records = [], outline.records

        def counted(extract):
            calls.append(extract.name)
            return records(extract)
        outline.records = counted
        try:
            render()
            render()
            self.assertEqual(calls, ["Box"], "computed once for two renders")
            box.data.materials[0].edgelight.radius = 0.15
            _, image = render()
            self.assertEqual(calls, ["Box", "Box"], "the edges were chosen again")
        finally:
            outline.records = records
        np.testing.assert_array_equal(image, from_nothing())

    def test_a_copy_under_another_name_reuses_the_mesh(self):
        """Kept by content, not by object: with the object that was extracted gone, its copy
        (another object with a copy of the mesh, Shift+D) reuses what was kept."""
        box = scene_with_box()
        copy = bpy.data.objects.new("Copy", box.data.copy())
        copy.location = (0.0, 3.0, 0.0)
        bpy.context.scene.collection.objects.link(copy)
        first, _ = render()
        natives = {inst.mesh.native for inst in first["scene"].instances}
        self.assertEqual(len(natives), 1, "one extraction for both")
        extracted = first["scene"].instances[0].mesh.name  # the one the extraction was made from
        bpy.data.objects.remove(bpy.data.objects[extracted])
        second, image = render()
        self.assertIs(second["scene"].instances[0].mesh.native, natives.pop())
        np.testing.assert_array_equal(image, from_nothing())

    def test_edited_mesh_is_read_again(self):
        box = scene_with_box()
        first, image = render()
        box.data.vertices[0].co.z += 0.4
        box.data.update()
        second, edited = render()
        self.assertIsNot(native_of(second, "Box"), native_of(first, "Box"))
        self.assertGreater(float(np.abs(edited - image).max()), 0.05, "the edit shows")
        np.testing.assert_array_equal(edited, from_nothing())

    def test_material_and_line_changes_apply(self):
        box = scene_with_box()
        render()
        box.data.materials[0].edgelight.radius = 0.15
        bpy.context.scene.edgelight.line_crease.width = 3.0
        second, changed = render()
        np.testing.assert_array_equal(changed, from_nothing())

    def test_nothing_kept_after_a_job_without_persistent_data(self):
        scene_with_box(persistent=False)
        render()
        self.assertEqual(len(cache()), 0)

    def test_another_material_reuses_the_mesh(self):
        """The materials are applied afresh, so assigning another one reads nothing again."""
        box = scene_with_box()
        first, _ = render()
        other = zoo.material("Red", (0.8, 0.1, 0.1))
        other.edgelight.radius = 0.1
        box.data.materials[0] = other
        second, image = render()
        self.assertIs(native_of(second, "Box"), native_of(first, "Box"))
        np.testing.assert_array_equal(image, from_nothing())

    def test_only_the_last_render_is_kept(self):
        """Kept past a job: what its last frame used, nothing more (re-rendering the same frame
        after each edit does not pile up extractions)."""
        box = scene_with_box()
        other = zoo.box("Other", 1.0, (0.0, 0.0, 2.0))
        other.data.materials.append(box.data.materials[0])
        render()
        self.assertEqual(len(cache()), 2)
        for step in range(3):
            box.data.vertices[0].co.z += 0.1
            box.data.update()
            render()
            self.assertEqual(len(cache()), 2, f"edit {step}")
        other.hide_render = True
        bpy.context.scene.frame_set(2)
        render()
        self.assertEqual(len(cache()), 1)


if __name__ == "__main__":
    unittest.main()
