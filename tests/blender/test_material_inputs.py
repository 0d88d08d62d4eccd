"""What a material or world sets that EdgeLight does not draw is said: once per material in a
render's warnings and in the viewport's status, and in the material's panel (material_inputs.py).
A plain Principled BSDF says nothing."""
import unittest

import bpy

import helpers
import scene_zoo as zoo


def principled(mat):
    return next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')


def scene():
    helpers.empty_scene(160, 120)
    helpers.add_camera((0.0, -6.0, 3.0), (0.0, 0.0, 0.0))


def assign(mat, copies=1):
    for i in range(copies):
        ob = zoo.box(f"Box{i}", 1.0, location=(1.5 * i, 0.0, 0.0))
        ob.data.materials.append(mat)


def warnings(rec, text):
    return [m for level, m in rec.get("messages", []) if level == 'WARNING' and text in m]


class MaterialInputs(unittest.TestCase):
    def inputs(self):
        return helpers.addon().extract.material_inputs

    def test_plain_principled_says_nothing(self):
        scene()
        mat = zoo.material("Plain", (0.5, 0.4, 0.3))
        mat.use_nodes = True
        node, unread = self.inputs().principled_of(mat)
        self.assertEqual(node.type, 'BSDF_PRINCIPLED')
        self.assertEqual(unread + helpers.addon().extract.materials.unread_inputs(node), [])
        assign(mat)
        self.assertEqual(warnings(helpers.render(), "does not draw"), [])

    def test_emission_drawn_and_an_image_through_a_node_said_once_per_material(self):
        scene()
        mat = zoo.material("Painted", (0.5, 0.4, 0.3))
        mat.use_nodes = True
        tree = mat.node_tree
        tex = tree.nodes.new("ShaderNodeTexImage")
        tex.image = bpy.data.images.new("Wood", 4, 4)
        node = principled(mat)
        node.inputs["Base Color"].default_value = (0.5, 0.4, 0.3, 1.0)
        tree.links.new(tex.outputs["Color"], node.inputs["Base Color"])
        emission = node.inputs.get("Emission Color") or node.inputs["Emission"]
        emission.default_value = (1.0, 0.5, 0.0, 1.0)
        node.inputs["Emission Strength"].default_value = 5.0
        assign(mat, copies=2)  # two objects, one material: one line
        # The image straight into Base Color (test_textures.py) and the emission's values
        # (test_emission.py) are drawn: nothing is said of them (the boxes have no UV map, and
        # that is said).
        self.assertEqual(warnings(helpers.render(), "does not draw"), [])
        self.assertEqual(helpers.addon().extract.materials.unread_inputs(node), [])
        # Through a node EdgeLight does not evaluate, the image is not drawn, and that is said.
        curves = tree.nodes.new("ShaderNodeRGBCurve")
        tree.links.new(tex.outputs["Color"], curves.inputs["Color"])
        tree.links.new(curves.outputs["Color"], node.inputs["Base Color"])
        # So is an image into the emission's strength: no emission is drawn then.
        mask = tree.nodes.new("ShaderNodeTexImage")
        mask.label = "Mask"
        tree.links.new(mask.outputs["Alpha"], node.inputs["Emission Strength"])
        lines = warnings(helpers.render(), "material 'Painted': EdgeLight does not draw")
        self.assertEqual(len(lines), 1, lines)
        self.assertIn("Base Color from RGB Curves", lines[0])
        self.assertIn("its value (0.5, 0.4, 0.3) is drawn", lines[0])
        self.assertIn("Emission Strength from Image Texture 'Mask': no image (no emission is drawn)", lines[0])
        unread = helpers.addon().extract.materials.unread_inputs(node)
        self.assertEqual(self.inputs().panel_line(unread), "Not drawn: Base Color: RGB Curves, Emission Strength: Image Texture")

    def test_other_surface_shader_is_named_and_the_render_goes_on(self):
        scene()
        mat = bpy.data.materials.new("Glass")
        mat.use_nodes = True
        tree = mat.node_tree
        for n in [n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED']:
            tree.nodes.remove(n)
        glass = tree.nodes.new("ShaderNodeBsdfGlass")
        out = next(n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL')
        tree.links.new(glass.outputs[0], out.inputs["Surface"])
        assign(mat)
        rec = helpers.render()
        lines = warnings(rec, "material 'Glass'")
        self.assertEqual(len(lines), 1, rec.get("messages"))
        self.assertIn("its Surface is a Glass BSDF (the viewport display colour is drawn)", lines[0])
        self.assertGreater(rec["stats"].objects, 0)

    def test_unsupported_lobe(self):
        mat = zoo.material("Frosted", (0.9, 0.9, 0.9))
        mat.use_nodes = True
        node = principled(mat)
        (node.inputs.get("Transmission Weight") or node.inputs["Transmission"]).default_value = 1.0
        self.assertEqual([s for s, _ in helpers.addon().extract.materials.unread_inputs(node)], ["Transmission"])

    def test_world_texture_said(self):
        scene()
        assign(zoo.material("Plain", (0.5, 0.5, 0.5)))
        world = bpy.context.scene.world
        world.use_nodes = True
        tree = world.node_tree
        background = next(n for n in tree.nodes if n.type == 'BACKGROUND')
        env = tree.nodes.new("ShaderNodeTexEnvironment")
        tree.links.new(env.outputs["Color"], background.inputs["Color"])
        lines = warnings(helpers.render(), f"world '{world.name}'")
        self.assertEqual(len(lines), 1)
        self.assertIn("its Color comes from Environment Texture, which has no image", lines[0])


if __name__ == "__main__":
    unittest.main()
