"""A Principled BSDF's Emission (materials.emission_of, shaders/material_data.json): what an
emissive surface shows is its colour x strength on top of what it reflects, as Cycles renders
it; its rounded edges and corners glow as its faces do; toon materials glow on top of their
ramp."""
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo
from test_world_light import cycles_pixels

EMISSION, STRENGTH = (1.0, 0.5, 0.25), 2.0


def emissive(name, base=(0.0, 0.0, 0.0)):
    mat = zoo.material(name, base)
    mat.use_nodes = True
    node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
    node.inputs["Base Color"].default_value = (*base, 1.0)
    (node.inputs.get("Emission Color") or node.inputs["Emission"]).default_value = (*EMISSION, 1.0)
    node.inputs["Emission Strength"].default_value = STRENGTH
    return mat


def dark_scene(**settings):
    scene = helpers.empty_scene(200, 160, **settings)
    helpers.set_world_color(scene, (0.0, 0.0, 0.0))
    return scene


class Emission(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_an_emissive_panel_shows_its_radiance_as_cycles_does(self):
        scene = dark_scene(highlights=False)
        helpers.add_camera((0.0, -6.0, 0.0), (0.0, 0.0, 0.0))
        bpy.ops.mesh.primitive_plane_add(size=2.0, rotation=(1.5707963, 0.0, 0.0))
        bpy.context.object.data.materials.append(emissive("Panel"))
        ours = np.asarray(helpers.render()["pixels"])
        theirs = cycles_pixels(scene, samples=4)
        expected = np.array(EMISSION) * STRENGTH
        np.testing.assert_allclose(ours[80, 100, :3], expected, atol=1e-4)
        # Cycles: 1 % brighter (2.0199 of 2), measured on 3.4.
        np.testing.assert_allclose(theirs[80, 100, :3], expected, rtol=0.02)
        np.testing.assert_allclose(ours[5, 5, :3], 0.0, atol=1e-6, err_msg="the world stays black")

    def test_rounded_edges_and_corners_glow_as_the_faces_do(self):
        """Nothing else lights the box: with its bands and corner patches drawn, every pixel
        well inside its outline is the emission, the bands' included."""
        scene = dark_scene(highlights=True, samples=1, use_shadows=False)
        scene.render.film_transparent = True  # alpha: the box's coverage
        helpers.add_camera((3.0, -4.0, 2.5), (0.0, 0.0, 0.0))
        ob = zoo.box("Box", 1.5)
        mat = emissive("Glow", base=(0.3, 0.3, 0.3))
        mat.edgelight.radius = 0.1
        ob.data.materials.append(mat)
        rec = helpers.render()
        self.assertGreater(rec["stats"].edges_drawn, 0)
        self.assertGreater(int((helpers.highlight_change(rec) > 0.05).sum()), 200, "the bands are drawn")
        px = np.asarray(rec["pixels"])
        covered = px[..., 3] > 0.999
        inside = covered.copy()
        for dy, dx in ((-2, 0), (2, 0), (0, -2), (0, 2)):  # two pixels in from the outline
            inside &= np.roll(covered, (dy, dx), axis=(0, 1))
        self.assertGreater(int(inside.sum()), 2000)
        off = np.abs(px[inside][:, :3] - np.array(EMISSION) * STRENGTH).max(axis=1)
        self.assertLess(float(off.max()), 1e-3, f"{int((off > 1e-3).sum())} pixels off, up to {off.max():.4f}")

    def test_a_linked_emission_draws_no_glow_and_says_so(self):
        """4.0's unlinked Emission Color is white: a texture into it must not glow white."""
        dark_scene(highlights=False)
        helpers.add_camera((0.0, -6.0, 0.0), (0.0, 0.0, 0.0))
        bpy.ops.mesh.primitive_plane_add(size=2.0, rotation=(1.5707963, 0.0, 0.0))
        mat = emissive("Screen")
        tree = mat.node_tree
        node = next(n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED')
        tex = tree.nodes.new("ShaderNodeTexChecker")
        tree.links.new(tex.outputs["Color"], node.inputs.get("Emission Color") or node.inputs["Emission"])
        bpy.context.object.data.materials.append(mat)
        rec = helpers.render()
        np.testing.assert_allclose(np.asarray(rec["pixels"])[80, 100, :3], 0.0, atol=1e-6)
        said = [m for _level, m in rec.get("messages", []) if "material 'Screen'" in m]
        self.assertEqual(len(said), 1, said)
        self.assertIn("from Checker Texture (no emission is drawn)", said[0])

    def test_a_toon_material_glows_over_its_ramp(self):
        dark_scene(highlights=False)
        helpers.add_camera((0.0, -6.0, 0.0), (0.0, 0.0, 0.0))
        bpy.ops.mesh.primitive_plane_add(size=2.0, rotation=(1.5707963, 0.0, 0.0))
        mat = emissive("Cel", base=(0.4, 0.2, 0.1))
        mat.edgelight.shading = 'RAMP'
        bpy.context.object.data.materials.append(mat)
        px = np.asarray(helpers.render()["pixels"])
        # Unlit, the default ramp's first stop: a third of the base colour (materials.default_ramp).
        np.testing.assert_allclose(px[80, 100, :3], 0.35 * np.array((0.4, 0.2, 0.1)) + np.array(EMISSION) * STRENGTH,
                                   atol=2e-3)


if __name__ == "__main__":
    unittest.main()
