"""An Image Texture into the Principled BSDF's Base Color (material_inputs.image_node_input,
shaders/textures.glsl): a texel's colour at its place on a UV-mapped quad, its colour space
decoded; Closest and Linear; the UV map a UV Map node names; a metal's reflection tinted by the
texel; what is still not drawn, and a UV map the mesh lacks, said."""
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo

SIZE = 64
# The image's four pixels, bottom row first, as an 8-bit sRGB image stores them.
TEXELS = np.array([[[0.9, 0.1, 0.1, 1.0], [0.1, 0.8, 0.2, 1.0]],
                   [[0.2, 0.3, 0.9, 1.0], [0.95, 0.9, 0.3, 1.0]]])


def srgb_to_linear(c):
    c = np.asarray(c, np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def stored(texels):
    """What the 8-bit image holds, decoded to linear as the GPU reads it."""
    return srgb_to_linear(np.floor(texels[..., :3] * 255.0 + 0.5) / 255.0)  # Blender rounds half up


def quad_scene(interpolation='Closest', metallic=0.0, uv_map=None, between=None):
    """A 2 x 2 quad filling the frame of a camera straight above it, under a uniform white world
    and no light; its material's Base Color from a 2 x 2 Image Texture (through a UV Map node
    naming `uv_map`, or a `between` node, when given)."""
    scene = helpers.empty_scene(SIZE, SIZE, highlights=False)
    helpers.set_world_color(scene, (1.0, 1.0, 1.0))
    bpy.ops.mesh.primitive_plane_add(size=2.0)
    ob = bpy.context.object
    zoo.top_camera(1.0)
    img = bpy.data.images.new("Texels", 2, 2)
    img.pixels.foreach_set(TEXELS.reshape(-1).astype(np.float32))
    mat = zoo.material("Textured", (0.8, 0.8, 0.8))
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = next(n for n in nodes if n.type == 'BSDF_PRINCIPLED')
    bsdf.inputs["Metallic"].default_value = metallic
    tex = nodes.new('ShaderNodeTexImage')
    tex.image, tex.interpolation = img, interpolation
    if between is not None:
        mix = nodes.new(between)
        links.new(tex.outputs["Color"], mix.inputs[0])
        links.new(mix.outputs[0], bsdf.inputs["Base Color"])
    else:
        links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    if uv_map is not None:
        node = nodes.new('ShaderNodeUVMap')
        node.uv_map = uv_map
        links.new(node.outputs["UV"], tex.inputs["Vector"])
    ob.data.materials.append(mat)
    return scene, ob, mat


def expected(albedo, spec, nv=1.0):
    """A surface under a uniform white world, no light: its albedo plus what the world puts in its
    specular lobe (lighting.glsl's el_env_specular, helpers.env_specular)."""
    n = helpers.addon().extract.materials.shininess_from_roughness(0.5)
    return np.asarray(albedo) + helpers.env_specular(spec, n, nv)


def quadrant(px, qx, qy):
    """The pixel at the centre of quadrant (qx, qy) (rows bottom-up)."""
    return px[SIZE // 4 + qy * SIZE // 2, SIZE // 4 + qx * SIZE // 2, :3]


class TexelsAtTheirPlaces(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_each_texel_on_its_quarter_of_the_quad(self):
        quad_scene()
        rec = helpers.render()
        px = rec["pixels"]
        want = stored(TEXELS)
        for qy in (0, 1):
            for qx in (0, 1):
                got = quadrant(px, qx, qy)
                print(f"texel ({qx}, {qy}): drawn {np.round(got, 4)}, linear texel {np.round(want[qy, qx], 4)}")
                np.testing.assert_allclose(got, expected(want[qy, qx], (0.04,) * 3), atol=2e-3)
        self.assertFalse([m for _, m in rec.get("messages", []) if "Base Color" in m], "a drawn texture is not reported")

    def test_linear_blends_the_four_at_the_middle(self):
        quad_scene('Linear')
        got = helpers.render()["pixels"][SIZE // 2 - 1:SIZE // 2 + 1, SIZE // 2 - 1:SIZE // 2 + 1, :3].mean(axis=(0, 1))
        mean = stored(TEXELS).reshape(-1, 3).mean(axis=0)
        print(f"middle of the quad: {np.round(got, 4)}, the texels' mean {np.round(mean, 4)}")
        np.testing.assert_allclose(got, expected(mean, (0.04,) * 3), atol=4e-3)

    def test_a_uv_map_node_picks_its_map(self):
        """A second UV map with u mirrored, named by a UV Map node: the texels swap sides; the
        active render map is left alone."""
        scene, ob, mat = quad_scene(uv_map="Mirrored")
        layer = ob.data.uv_layers.new(name="Mirrored", do_init=True)
        uv = np.empty(len(layer.data) * 2, np.float32)
        layer.data.foreach_get("uv", uv)
        uv = uv.reshape(-1, 2)
        uv[:, 0] = 1.0 - uv[:, 0]
        layer.data.foreach_set("uv", uv.reshape(-1))
        ob.data.uv_layers[0].active_render = True
        px = helpers.render()["pixels"]
        want = stored(TEXELS)
        np.testing.assert_allclose(quadrant(px, 0, 0), expected(want[0, 1], (0.04,) * 3), atol=2e-3)
        np.testing.assert_allclose(quadrant(px, 1, 1), expected(want[1, 0], (0.04,) * 3), atol=2e-3)

    def test_a_metal_reflects_the_world_in_the_texels_colour(self):
        quad_scene(metallic=1.0)
        px = helpers.render()["pixels"]
        want = stored(TEXELS)
        for qy, qx in ((0, 0), (1, 1)):
            np.testing.assert_allclose(quadrant(px, qx, qy), expected((0.0,) * 3, want[qy, qx]), atol=2e-3)


def band_cube(name, base_color):
    """A cube with rounded edges (radius 0.08) seen from a corner, under a sun and a grey world;
    its material's Base Color fed by base_color(cube, node tree) (an output socket). The
    highlight pass's band pixels' count and summed rgb."""
    scene = helpers.empty_scene(160, 160, highlights=True)
    helpers.set_world_color(scene, (0.3, 0.3, 0.3))
    helpers.add_camera((4.0, -5.0, 3.5))
    helpers.add_sun((0.4, -1.0, 0.8), 3.0)
    bpy.ops.mesh.primitive_cube_add(size=2.0)
    ob = bpy.context.object
    mat = zoo.material(name, (0.8, 0.8, 0.8))
    mat.use_nodes = True
    bsdf = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
    mat.node_tree.links.new(base_color(ob, mat.node_tree), bsdf.inputs["Base Color"])
    mat.edgelight.radius = 0.08
    ob.data.materials.append(mat)
    rec = helpers.render()
    hl = np.asarray(rec["highlight"])
    band = hl[..., 3] > 0.2
    return rec, int(band.sum()), hl[band][:, :3].sum(axis=0)


class RoundedEdgesUnderTheImage(unittest.TestCase):
    def test_bands_and_corners_take_the_texel_not_the_images_mean(self):
        """A cube whose every corner maps into the red half of a half-blue, half-red image: its
        bands and corner patches are red, as a bevel under that image would be; the image's mean
        (purple) would give them as much blue as red, and a UV of zero (none found) blue."""
        helpers.needs_gpu()

        def halves(ob, tree):
            layer = ob.data.uv_layers.active
            layer.data.foreach_set("uv", np.tile([0.75, 0.5], len(layer.data)).astype(np.float32))
            img = bpy.data.images.new("Halves", 4, 2)
            px = np.zeros((2, 4, 4), np.float32)
            px[:, :2] = (0.0, 0.0, 1.0, 1.0)
            px[:, 2:] = (1.0, 0.0, 0.0, 1.0)
            img.pixels.foreach_set(px.reshape(-1))
            tex = tree.nodes.new('ShaderNodeTexImage')
            tex.image, tex.interpolation = img, 'Closest'
            return tex.outputs["Color"]
        _rec, count, (red, _green, blue) = band_cube("Halves", halves)
        print(f"{count} band pixels: red {red:.2f}, blue {blue:.2f}")
        self.assertGreater(count, 100)
        self.assertGreater(red, 20.0 * blue)


class SaidWhenNotDrawn(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_a_node_between_is_still_reported(self):
        quad_scene(between='ShaderNodeRGBCurve')
        rec = helpers.render()
        said = [m for _, m in rec.get("messages", []) if "'Textured'" in m]
        print(said)
        self.assertTrue(any("Base Color from RGB Curves" in m for m in said), said)

    def test_under_toon_shading_the_image_is_its_mean_and_that_is_said(self):
        scene, ob, mat = quad_scene()
        mat.edgelight.shading = 'RAMP'
        rec = helpers.render()
        said = " ".join(m for _, m in rec.get("messages", []))
        self.assertIn("is drawn as its mean colour under toon shading", said)

    def test_a_uv_map_the_mesh_lacks(self):
        quad_scene(uv_map="Nope")
        rec = helpers.render()
        said = " ".join(m for _, m in rec.get("messages", []))
        print(said)
        self.assertIn("UV map 'Nope' the mesh does not have", said)
        px = rec["pixels"]
        mean = stored(TEXELS).reshape(-1, 3).mean(axis=0)
        np.testing.assert_allclose(quadrant(px, 0, 0), expected(mean, (0.04,) * 3), atol=3e-3)


if __name__ == "__main__":
    unittest.main()
