"""Extractions kept between final renders (addon/extract/render_cache.py): within a render job (an
animation) and, with the scene's Persistent Data on, from one job to the next. A render of
unchanged meshes reuses the last render's classification and draws the same image; an edited
mesh, a changed material or line settings are read afresh, and the image is the one a render
from nothing draws; what a frame no longer draws is dropped after one more frame; without
Persistent Data nothing is kept once a job ends. Within a job the engine also keeps the GPU
batches of what it drew (passes/batches.GpuCache): a frame of unchanged meshes builds none."""
import os
import tempfile
import unittest

import bpy
import numpy as np
from mathutils import Vector

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

    def frames(self, **render_args):
        """Renders with render_args (bpy.ops.render.render's); per frame drawn: (meshes whose
        GPU batches it built, its image). self.reads: per frame, the objects whose meshes were
        read."""
        helpers.needs_gpu()
        frame, sync = helpers.addon().passes.frame, helpers.addon().extract.scene_sync
        drawn, real, real_read, reads = [], frame.render, sync.read_object, []

        def spy(*args, **kwargs):
            out = real(*args, **kwargs)
            drawn.append((out.stats.meshes_built, out.pixels.copy()))
            self.reads.append(reads[:])
            reads.clear()
            return out

        def read(ob, *args, **kwargs):
            reads.append(ob.name)
            return real_read(ob, *args, **kwargs)
        frame.render, sync.read_object, self.reads = spy, read, []
        try:
            bpy.ops.render.render(**render_args)
        finally:
            frame.render, sync.read_object = real, real_read
        return drawn

    def animation(self, frames=3):
        """The box scene animated over `frames` frames: the camera moves, the meshes do not."""
        box = scene_with_box(persistent=False)
        scene = bpy.context.scene
        scene.frame_start, scene.frame_end = 1, frames
        scene.render.filepath = os.path.join(tempfile.mkdtemp(prefix="edgelight_anim_"), "frame_")
        cam = scene.camera
        for f, x in ((1, 4.0), (frames, 2.5)):
            cam.location.x = x
            cam.keyframe_insert("location", frame=f)
        return box

    def test_frames_of_a_job_keep_their_gpu_batches(self):
        """Blender keeps the engine and its GPU context for every frame of a render job: a
        frame whose meshes did not change builds no batch, and draws what a render of that
        frame alone draws."""
        self.animation()
        drawn = self.frames(animation=True)
        self.assertEqual([built for built, _ in drawn], [1, 0, 0])
        self.assertEqual(self.reads, [["Box"], [], []], "only the camera moved: no mesh read again")
        self.assertGreater(float(np.abs(drawn[2][1] - drawn[0][1]).max()), 0.05, "the camera moved")
        bpy.context.scene.frame_set(3)
        (built, alone), = self.frames()  # a still: a job of its own
        self.assertEqual(built, 1)
        np.testing.assert_array_equal(drawn[2][1], alone)

    def test_a_changed_mesh_builds_its_batches_again(self):
        box = self.animation(2)
        box.scale = (1.0, 1.0, 1.0)
        shape = box.modifiers.new("Bend", 'SIMPLE_DEFORM')  # the mesh itself changes on frame 2
        shape.deform_method = 'TWIST'
        for f, angle in ((1, 0.0), (2, 0.6)):
            shape.angle = angle
            shape.keyframe_insert("angle", frame=f)
        self.assertEqual([built for built, _ in self.frames(animation=True)], [1, 1])
        self.assertEqual(self.reads, [["Box"], ["Box"]])

    def test_an_animated_material_applies_on_its_frame(self):
        """Only moves let a frame draw the last one's extractions: a keyframed colour is a
        material's update, and the frame draws it as a render of that frame alone does."""
        box = self.animation(2)
        self._keyframe_colour(box.data.materials[0])
        drawn = self.frames(animation=True)
        self.assertEqual(self.reads, [["Box"], ["Box"]], "read again (the render cache keeps its classification)")
        bpy.context.scene.frame_set(2)
        (_, alone), = self.frames()
        np.testing.assert_array_equal(drawn[1][1], alone)
        x, y = helpers.project(helpers.render(), [(0.0, 0.0, 1.0)])[0]
        r, g, b = drawn[1][1][int(y), int(x), :3]
        self.assertGreater(g, 2.0 * r, "frame 2 is green")

    def test_two_view_layers_see_each_others_updates(self):
        """The view layers of a job share one depsgraph whose updates each layer's render clears:
        what one layer saw must reach the other (engine: anything more than a move, seen by
        any layer, drops what every layer kept; Blender also lists the scene as updated at each
        change of layer, so both read afresh). Both draw frame 2's keyed colour."""
        box = self.animation(2)
        bpy.context.scene.camera.animation_data_clear()
        bpy.context.scene.view_layers.new("Second")
        self._keyframe_colour(box.data.materials[0])
        drawn = self.frames(animation=True)
        self.assertEqual(len(drawn), 4, "two layers, two frames")
        self.assertEqual(self.reads, [["Box"]] * 4)
        x, y = helpers.project(helpers.render(), [(0.0, 0.0, 1.0)])[0]
        for k, (_, image) in enumerate(drawn):
            r, g, b = image[int(y), int(x), :3]
            self.assertEqual(g > 2.0 * r, k >= 2, f"render {k} (layer {k % 2}, frame {k // 2 + 1}): {r:.3f} {g:.3f}")

    def _keyframe_colour(self, mat):
        """Grey on frame 1, green on frame 2."""
        bsdf = next((n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED'), None) \
            if mat.node_tree is not None and mat.use_nodes else None  # as scene_zoo.material made it
        for f, rgb in ((1, (0.6, 0.6, 0.6, 1.0)), (2, (0.1, 0.6, 0.1, 1.0))):
            if bsdf is not None:
                bsdf.inputs["Base Color"].default_value = rgb
                bsdf.inputs["Base Color"].keyframe_insert("default_value", frame=f)
            else:
                mat.diffuse_color = rgb
                mat.keyframe_insert("diffuse_color", frame=f)

    def test_kept_batches_draw_each_object_with_its_own_materials(self):
        """Two objects of one content (a mesh copy, another material): one extraction, one set of
        batches, each drawn with its own material, in the next frame too."""
        box = self.animation(2)
        bpy.context.scene.camera.animation_data_clear()  # both frames from where both objects show
        bpy.context.scene.camera.location.x = 4.0
        red = zoo.material("Red", (0.8, 0.05, 0.05))
        red.edgelight.radius = 0.05
        copy = bpy.data.objects.new("Copy", box.data.copy())
        copy.data.materials[0] = red
        copy.location = (0.0, 3.0, 0.0)
        bpy.context.scene.collection.objects.link(copy)
        drawn = self.frames(animation=True)
        self.assertEqual([built for built, _ in drawn], [1, 0], "one set of batches for both")
        bpy.context.scene.frame_set(2)
        rec = helpers.render()
        np.testing.assert_array_equal(drawn[1][1], rec["pixels"])
        self.assertEqual(len({id(inst.mesh.native) for inst in rec["scene"].instances}), 1, "one extraction")
        # The middle of each object's top face: the box grey, its copy red.
        for ob, want_red in ((box, False), (copy, True)):
            x, y = helpers.project(rec, [tuple(ob.location + Vector((0.0, 0.0, 1.0)))])[0]
            r, g, b = drawn[1][1][int(y), int(x), :3]
            self.assertEqual(r > 2.0 * g, want_red, f"{ob.name}: {r:.3f} {g:.3f} {b:.3f}")

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
