"""Render passes: Depth, Normal and EdgeLight's Highlights, Lines and Surface, registered with
Blender (the compositor's Render Layers node shows them) and recomposing Combined within 1/255,
by the formula of docs/addon.md and by Blender's own compositor."""
import os
import tempfile
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo

OWN = ("use_pass_highlights", "use_pass_lines", "use_pass_surface")


def enable_passes(view_layer, on=True):
    view_layer.use_pass_z = view_layer.use_pass_normal = on
    for prop in OWN:
        setattr(view_layer.edgelight, prop, on)


def lines_scene(samples=4, transparent=False):
    """The cube sample with highlights and ink lines, a few jittered samples."""
    scene = helpers.open_sample("cube", samples=samples)
    lines = helpers.only_lines(scene, silhouette=3.0, crease=2.0)
    # Coloured, half-opaque ink: black or opaque ink would hide a premultiplication mistake.
    lines.line_silhouette.color, lines.line_silhouette.opacity = (0.9, 0.5, 0.1), 0.6
    scene.render.film_transparent = transparent
    helpers.set_world_color(scene, (0.2, 0.3, 0.4))
    enable_passes(scene.view_layers[0])
    return scene


def over(front, back):
    """Premultiplied `front` over `back` (RGBA): the compositor's Alpha Over."""
    return front + (1.0 - front[..., 3:4]) * back


def recompose(passes, world, transparent):
    """Combined from the passes (docs/addon.md, "Render passes")."""
    d = over(passes["Lines"], over(passes["Highlights"], passes["Surface"]))
    behind = np.array([*world, 1.0], np.float32) * (0.0 if transparent else 1.0)
    return over(d, behind)


def alpha_over(tree, background, foreground):
    node = tree.nodes.new("CompositorNodeAlphaOver")
    inputs = [i for i in node.inputs if i.type == 'RGBA']  # (background, foreground) on every version
    tree.links.new(background, inputs[0])
    tree.links.new(foreground, inputs[1])
    return node.outputs[0]


def compositor(scene):
    """The scene's compositor tree, emptied, and the socket whose image is the composited frame
    (5.0: a node group with a Group Output; earlier: scene.node_tree with a Composite node)."""
    if hasattr(scene, "compositing_node_group"):
        tree = bpy.data.node_groups.new("Recompose", "CompositorNodeTree")
        tree.interface.new_socket("Image", in_out='OUTPUT', socket_type='NodeSocketColor')
        scene.compositing_node_group = tree
        return tree, tree.nodes.new("NodeGroupOutput").inputs[0]
    scene.use_nodes = True
    tree = scene.node_tree
    tree.nodes.clear()
    return tree, tree.nodes.new("CompositorNodeComposite").inputs[0]


def composited(scene, color_mode, resolution=None, record=True):
    """Renders once for the engine's record (unless not `record`) and once through the compositor
    into a 32-bit EXR: (record or None, the EXR's pixels (h, w, 4))."""
    scene.render.use_compositing = True
    s = scene.render.image_settings
    s.file_format, s.color_depth, s.color_mode = 'OPEN_EXR', '32', color_mode
    with tempfile.TemporaryDirectory() as tmp:
        scene.render.filepath = os.path.join(tmp, "composited.exr")
        rec = helpers.render(resolution=resolution) if record else None
        bpy.ops.render.render(write_still=True)
        img = bpy.data.images.load(scene.render.filepath)
        w, h = img.size
        px = np.empty(w * h * 4, np.float32)
        img.pixels.foreach_get(px)
        bpy.data.images.remove(img)
    return rec, px.reshape(h, w, 4)


class LinesAsRenderPass(unittest.TestCase):
    def test_the_ink_goes_to_its_own_pass(self):
        """Lines as Render Pass: Combined is the highlighted surface over the world, with no ink
        (as the passes recompose it without Lines), and the Lines pass holds the ink as it does
        with the option off."""
        helpers.needs_gpu()
        scene = lines_scene()
        with_ink = helpers.render()
        scene.view_layers[0].edgelight.lines_as_pass = True
        scene.view_layers[0].edgelight.use_pass_lines = False  # the option alone asks for the pass
        rec = helpers.render()
        passes, world = rec["passes"], (0.2, 0.3, 0.4)
        self.assertIn("Lines", passes)
        np.testing.assert_allclose(passes["Lines"], with_ink["passes"]["Lines"], atol=1e-6)
        self.assertGreater(float(passes["Lines"][..., 3].max()), 0.5, "ink in the Lines pass")
        no_ink = dict(passes, Lines=np.zeros_like(passes["Lines"]))
        np.testing.assert_allclose(rec["pixels"], recompose(no_ink, world, False), atol=1.0 / 255.0)
        ink = passes["Lines"][..., 3] > 0.5
        self.assertGreater(float(np.abs(with_ink["pixels"] - rec["pixels"])[ink].max()), 0.1,
                           "with the option off Combined carries the ink")


class Registered(unittest.TestCase):
    def test_render_layers_node_offers_the_enabled_passes(self):
        scene = lines_scene()
        tree, _ = compositor(scene)
        node = tree.nodes.new("CompositorNodeRLayers")
        names = {o.name for o in node.outputs if o.enabled}
        for name in ("Image", "Depth", "Normal", "Highlights", "Lines", "Surface"):
            self.assertIn(name, names)
        enable_passes(scene.view_layers[0], False)
        scene.view_layers[0].update_render_passes()
        names = {o.name for o in node.outputs if o.enabled}
        self.assertFalse({"Highlights", "Lines", "Surface", "Normal"} & names, names)

    def test_passes_off_read_back_nothing(self):
        helpers.needs_gpu()
        scene = lines_scene(samples=1)
        enable_passes(scene.view_layers[0], False)
        rec = helpers.render(resolution=(160, 120))
        self.assertEqual(rec["passes"], {})


class Recompose(unittest.TestCase):
    def check(self, transparent):
        helpers.needs_gpu()
        scene = lines_scene(transparent=transparent)
        rec = helpers.render(resolution=(320, 240))
        p = rec["passes"]
        self.assertEqual(set(p), {"Depth", "Normal", "Highlights", "Lines", "Surface"})
        self.assertGreater((p["Highlights"][..., 3] > 0.05).sum(), 50, "highlights in their pass")
        self.assertGreater((p["Lines"][..., 3] > 0.5).sum(), 200, "ink in its pass")
        error = np.abs(recompose(p, rec["scene"].ambient, transparent) - rec["pixels"]).max()
        self.assertLess(error, 1.0 / 255.0, f"transparent={transparent}")
        return scene, rec

    def test_combined_from_the_passes_opaque_film(self):
        self.check(False)

    def test_combined_from_the_passes_transparent_film(self):
        self.check(True)

    def test_blenders_compositor_recomposes_combined(self):
        """Alpha Over (premultiplied) of Highlights on Surface, Lines on that, the result on the
        world colour, in Blender's compositor: the frame it writes equals Combined."""
        helpers.needs_gpu()
        scene = lines_scene()
        tree, out = compositor(scene)
        layers = tree.nodes.new("CompositorNodeRLayers")
        world = tree.nodes.new("CompositorNodeRGB")
        world.outputs[0].default_value = (0.2, 0.3, 0.4, 1.0)
        o = layers.outputs
        image = alpha_over(tree, o["Surface"], o["Highlights"])
        image = alpha_over(tree, image, o["Lines"])
        tree.links.new(alpha_over(tree, world.outputs[0], image), out)
        rec, px = composited(scene, 'RGBA', resolution=(320, 240))
        h, w = px.shape[:2]
        self.assertEqual((h, w), (240, 320))
        error = np.abs(px - rec["pixels"]).max()
        self.assertLess(error, 1.0 / 255.0)
        self.assertGreater((rec["passes"]["Lines"][..., 3] > 0.5).sum(), 200)


class DepthAndNormal(unittest.TestCase):
    def plane_scene(self, ortho=False):
        scene = helpers.empty_scene(200, 150)
        zoo.mesh_object("Plane", [(-2, -1.5, 0), (2, -1.5, 0), (2, 1.5, 0), (-2, 1.5, 0)], [(0, 1, 2, 3)])
        # Tilted about x: the plane's distance along the view axis varies across the image.
        cam = helpers.add_camera((0.0, -3.0, 5.0), (0.0, 0.0, 0.0), lens=35.0)
        if ortho:
            cam.data.type, cam.data.ortho_scale = 'ORTHO', 6.0
        enable_passes(scene.view_layers[0])
        return scene, cam

    def check(self, ortho):
        helpers.needs_gpu()
        _, cam = self.plane_scene(ortho)
        rec = helpers.render()
        depth, normal = rec["passes"]["Depth"][..., 0], rec["passes"]["Normal"]
        world = np.array(cam.matrix_world)
        axis, eye = -world[:3, 2], world[:3, 3]
        c = rec["camera"]
        unproject = np.linalg.inv(c.projection @ c.view)
        for point in ((0.0, 0.0, 0.0), (1.5, 1.0, 0.0), (-1.0, -1.2, 0.0)):
            x, y = np.floor(helpers.project(rec, [point])[0]).astype(int)
            # Where the pixel centre's ray meets the plane z = 0, and its distance along the view axis.
            ndc = np.array([(x + 0.5) / c.width, (y + 0.5) / c.height]) * 2.0 - 1.0
            near, far = (unproject @ np.array([*ndc, z, 1.0]) for z in (-1.0, 1.0))
            near, far = near[:3] / near[3], far[:3] / far[3]
            hit = near + (far - near) * (near[2] / (near[2] - far[2]))
            want = float(np.dot(hit - eye, axis))
            self.assertAlmostEqual(depth[y, x], want, delta=1e-4 * want, msg=f"{point}")
            np.testing.assert_allclose(normal[y, x], (0.0, 0.0, 1.0), atol=1e-4)
        empty = rec["surface"][..., 3] == 0.0
        self.assertGreater(empty.sum(), 100)
        self.assertTrue((depth[empty] == 1e10).all(), "background: the depth Cycles and EEVEE write there")
        self.assertTrue((depth[~empty] < 10.0).all())

    def test_depth_is_distance_along_the_view_axis(self):
        self.check(False)

    def test_depth_orthographic(self):
        self.check(True)


class Mist(unittest.TestCase):
    """The Mist pass: each pixel centre's distance from the eye through the world's mist start,
    depth and falloff, as Cycles writes it; 1 where nothing was drawn."""

    def test_mist_is_the_distance_through_the_worlds_falloff(self):
        helpers.needs_gpu()
        for falloff in ('QUADRATIC', 'LINEAR', 'INVERSE_QUADRATIC'):
            scene, cam = DepthAndNormal.plane_scene(self)
            scene.view_layers[0].use_pass_mist = True
            if scene.world is None:
                scene.world = bpy.data.worlds.new("World")
            ms = scene.world.mist_settings
            ms.start, ms.depth, ms.falloff = 4.0, 3.0, falloff
            rec = helpers.render()
            got = rec["passes"]["Mist"][..., 0]
            c = rec["camera"]
            eye = np.array(cam.matrix_world)[:3, 3]
            unproject = np.linalg.inv(c.projection @ c.view)
            power = {'QUADRATIC': 2.0, 'LINEAR': 1.0, 'INVERSE_QUADRATIC': 0.5}[falloff]
            for point in ((0.0, 0.0, 0.0), (1.5, 1.0, 0.0), (-1.0, -1.2, 0.0), (1.8, -1.4, 0.0)):
                x, y = np.floor(helpers.project(rec, [point])[0]).astype(int)
                ndc = np.array([(x + 0.5) / c.width, (y + 0.5) / c.height]) * 2.0 - 1.0
                near, far = (unproject @ np.array([*ndc, z, 1.0]) for z in (-1.0, 1.0))
                near, far = near[:3] / near[3], far[:3] / far[3]
                hit = near + (far - near) * (near[2] / (near[2] - far[2]))
                want = np.clip((np.linalg.norm(hit - eye) - 4.0) / 3.0, 0.0, 1.0) ** power
                self.assertAlmostEqual(float(got[y, x]), float(want), delta=1e-4, msg=f"{falloff} {point}")
            empty = rec["surface"][..., 3] == 0.0
            self.assertTrue((got[empty] == 1.0).all())
            self.assertGreater(float(got[~empty].max() - got[~empty].min()), 0.2, "the plane's mist varies")

    def test_mist_matches_cycles(self):
        """Cycles' own Mist pass of the same plane (16 samples: its pixel filter averages the
        pixel's footprint), at the middle of the plane's image."""
        helpers.needs_gpu()
        scene, cam = DepthAndNormal.plane_scene(self)
        scene.view_layers[0].use_pass_mist = True
        if scene.world is None:
            scene.world = bpy.data.worlds.new("World")
        scene.world.mist_settings.start, scene.world.mist_settings.depth = 4.0, 3.0
        ours = helpers.render()["passes"]["Mist"][..., 0]
        scene.render.engine = 'CYCLES'
        scene.cycles.samples, scene.cycles.device, scene.cycles.use_denoising = 16, 'CPU', False
        tree, out = compositor(scene)
        layers = tree.nodes.new("CompositorNodeRLayers")
        tree.links.new(layers.outputs["Mist"], out)
        theirs = composited(scene, 'RGBA', record=False)[1][..., 0]
        h, w = ours.shape
        inner = (slice(h // 3, 2 * h // 3), slice(w // 3, 2 * w // 3))
        diff = np.abs(ours[inner] - theirs[inner])
        print(f"mist against Cycles: mean {diff.mean():.4f}, worst {diff.max():.4f}")
        self.assertLess(float(diff.mean()), 0.01)


class ObjectIndex(unittest.TestCase):
    """Blender's Object Index pass (IndexOB; "Object Index" from 5.0): each pixel's object
    pass_index, 0 where nothing was drawn, from the first sample's id image (docs/addon.md)."""

    def scene(self, highlights=False):
        scene = helpers.empty_scene(240, 160, highlights=highlights)
        zoo.top_camera(6.0)
        helpers.add_sun()
        a = zoo.box("A", 1.5, location=(-3.5, 0.0, 0.0))
        a.pass_index = 3
        b = bpy.data.objects.new("B", a.data)  # a linked duplicate: one extraction, its own index
        b.location, b.pass_index = (0.0, 0.0, 0.0), 7
        scene.collection.objects.link(b)
        part = bpy.data.collections.new("Part")  # instanced only: not in the scene itself
        zoo.box("Block", 1.5, collection=part).pass_index = 5
        empty = bpy.data.objects.new("Instancer", None)
        empty.instance_type, empty.instance_collection = 'COLLECTION', part
        empty.location, empty.pass_index = (3.5, 0.0, 0.0), 9  # the instanced object's index counts
        scene.collection.objects.link(empty)
        scene.view_layers[0].use_pass_object_index = True
        # Where each object's top face is, and two places where nothing is.
        self.points = {3.0: (-3.5, 0.2, 0.75), 7.0: (0.3, -0.2, 0.75), 5.0: (3.5, 0.0, 0.75),
                       0.0: (-1.75, 0.0, 0.0)}
        return scene

    def name(self):
        return helpers.addon().host.render_passes.OBJECT_INDEX

    def check_values(self, rec, index):
        self.assertEqual(index.shape, (160, 240, 1))
        for want, point in self.points.items():
            x, y = np.floor(helpers.project(rec, [point])[0]).astype(int)
            self.assertEqual(index[y, x, 0], want, f"at {point}")
        self.assertEqual(index[0, 0, 0], 0.0, "background")
        self.assertEqual(set(np.unique(index)), {0.0, 3.0, 5.0, 7.0})
        # Every drawn pixel holds one object's index; nothing drawn holds 0.
        drawn = zoo.coverage(rec) > 0.0
        self.assertTrue((index[~drawn] == 0.0).all())
        self.assertTrue((index[drawn] > 0.0).all())

    def test_render_layers_node_offers_it(self):
        scene = self.scene()
        tree, _ = compositor(scene)
        node = tree.nodes.new("CompositorNodeRLayers")
        self.assertIn(self.name(), {o.name for o in node.outputs if o.enabled})
        # Blender's own name for it: the one Cycles registers (5.0 renamed IndexOB).
        scene.render.engine = 'CYCLES'
        scene.view_layers[0].update_render_passes()
        self.assertIn(self.name(), {o.name for o in node.outputs if o.enabled}, "Cycles' name")
        scene.render.engine = 'EDGELIGHT'
        scene.view_layers[0].use_pass_object_index = False  # 4.2+ remove the socket, 3.4 disables it
        self.assertNotIn(self.name(), {o.name for o in node.outputs if o.enabled})

    def test_each_pixel_holds_its_objects_pass_index(self):
        """Highlights and lines off: the surface pass writes ids for this pass alone."""
        helpers.needs_gpu()
        self.scene()
        rec = helpers.render()
        self.assertEqual(set(rec["passes"]), {self.name()})
        self.check_values(rec, rec["passes"][self.name()])

    def test_blenders_compositor_reads_it(self):
        """The pass through the compositor's Render Layers node, written to a 32-bit EXR."""
        helpers.needs_gpu()
        scene = self.scene(highlights=True)
        tree, out = compositor(scene)
        tree.links.new(tree.nodes.new("CompositorNodeRLayers").outputs[self.name()], out)
        rec, px = composited(scene, 'RGB')
        np.testing.assert_array_equal(px[..., 0], px[..., 1])
        self.check_values(rec, px[..., :1])
        np.testing.assert_array_equal(px[..., :1], rec["passes"][self.name()])


class MaterialIndex(unittest.TestCase):
    """Blender's Material Index pass (IndexMA; "Material Index" from 5.0): each pixel's material
    pass_index through its face's slot, 0 where nothing was drawn or the slot is empty, beside
    the Object Index pass from the same ids."""

    def scene(self):
        scene = helpers.empty_scene(240, 160)
        zoo.top_camera(6.0)
        helpers.add_sun()
        a = zoo.box("A", 1.5, location=(-3.5, 0.0, 0.0))
        a.pass_index = 3
        two = [zoo.material("Two", (0.8, 0.2, 0.2)), zoo.material("Four", (0.2, 0.8, 0.2))]
        two[0].pass_index, two[1].pass_index = 2, 4
        for mat in two:
            a.data.materials.append(mat)
        top = max(a.data.polygons, key=lambda p: p.center.z)
        top.material_index = 1  # the top face takes the second slot
        b = zoo.box("B", 1.5, location=(0.0, 0.0, 0.0))
        six = zoo.material("Six", (0.2, 0.2, 0.8))
        six.pass_index = 6
        b.data.materials.append(six)
        zoo.box("Bare", 1.5, location=(3.5, 0.0, 0.0))  # no material: 0
        layer = scene.view_layers[0]
        layer.use_pass_material_index = True
        layer.use_pass_object_index = True
        return scene

    def test_each_pixel_holds_its_faces_material_pass_index(self):
        helpers.needs_gpu()
        self.scene()
        rec = helpers.render()
        names = helpers.addon().host.render_passes
        index = rec["passes"][names.MATERIAL_INDEX]
        self.assertEqual(index.shape, (160, 240, 1))
        seen_from_top = {4.0: (-3.5, 0.2, 0.75), 6.0: (0.3, -0.2, 0.75), 0.0: (3.5, 0.0, 0.75)}
        for want, point in seen_from_top.items():
            x, y = np.floor(helpers.project(rec, [point])[0]).astype(int)
            self.assertEqual(index[y, x, 0], want, f"at {point}")
        self.assertEqual(index[0, 0, 0], 0.0, "background")
        self.assertEqual(set(np.unique(index)), {0.0, 4.0, 6.0}, "only top faces are seen from the top")
        objects = rec["passes"][names.OBJECT_INDEX]
        x, y = np.floor(helpers.project(rec, [(-3.5, 0.2, 0.75)])[0]).astype(int)
        self.assertEqual(objects[y, x, 0], 3.0, "both passes from one id image")

    def test_a_side_face_takes_its_own_slot(self):
        helpers.needs_gpu()
        scene = self.scene()
        cam = scene.camera
        cam.data.type = 'PERSP'
        helpers.look_at(cam, (-3.5, -8.0, 0.0), (-3.5, 0.0, 0.0))  # the front face: A's slot 0
        rec = helpers.render()
        index = rec["passes"][helpers.addon().host.render_passes.MATERIAL_INDEX]
        x, y = np.floor(helpers.project(rec, [(-3.5, -0.75, 0.0)])[0]).astype(int)
        self.assertEqual(index[y, x, 0], 2.0)

    def test_blenders_name_for_it(self):
        scene = self.scene()
        tree, _ = compositor(scene)
        node = tree.nodes.new("CompositorNodeRLayers")
        name = helpers.addon().host.render_passes.MATERIAL_INDEX
        self.assertIn(name, {o.name for o in node.outputs if o.enabled})
        scene.render.engine = 'CYCLES'  # the name Cycles registers
        scene.view_layers[0].update_render_passes()
        self.assertIn(name, {o.name for o in node.outputs if o.enabled})
