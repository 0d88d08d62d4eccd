"""An image's alpha into the Principled BSDF's Alpha as well as its colour into Base Color
(material_inputs.image_alpha, materials.BaseTexture's alpha, surface.frag.glsl): cut as EEVEE
cuts it. Alpha Clip (3.4's Blend Mode) keeps a texel at or above the threshold and shows the
world below it; Alpha Hashed (3.4) and Dithered (EEVEE Next, 4.2+) cut against a per-pixel,
per-sample hash, which the samples average into the alpha's coverage; Blend Mode Opaque (3.4)
ignores the alpha; Alpha Blend is drawn hashed and says so."""
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo

SIZE = 64
WORLD = (0.0, 1.0, 0.0)
RED = (0.8, 0.1, 0.1)


def card(alphas, samples=1):
    """A 2 x 2 quad filling the frame from above, its image 4 x 1 texels of red at `alphas`
    (left to right, Closest), the image's colour into Base Color and its alpha into Alpha, under
    a green world and no light."""
    scene = helpers.empty_scene(SIZE, SIZE, highlights=False, samples=samples)
    helpers.set_world_color(scene, WORLD)
    bpy.ops.mesh.primitive_plane_add(size=2.0)
    ob = bpy.context.object
    zoo.top_camera(1.0)
    img = bpy.data.images.new("Leaf", 4, 1, alpha=True, float_buffer=True)
    img.pixels.foreach_set(np.array([(*RED, a) for a in alphas], np.float32).reshape(-1))
    mat = zoo.material("Card", (0.8, 0.8, 0.8))
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = next(n for n in nodes if n.type == 'BSDF_PRINCIPLED')
    bsdf.inputs["Specular IOR Level" if "Specular IOR Level" in bsdf.inputs else "Specular"].default_value = 0.0
    tex = nodes.new('ShaderNodeTexImage')
    tex.image, tex.interpolation = img, 'Closest'
    links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
    ob.data.materials.append(mat)
    return scene, mat


def columns(px):
    """The mean colour of each quarter of the image, left to right (the texels' columns)."""
    q = SIZE // 4
    return [px[4:-4, k * q + 2:(k + 1) * q - 2, :3].reshape(-1, 3).mean(axis=0) for k in range(4)]


def messages(rec):
    return [m for _level, m in rec.get("messages", [])]


class ImageAlpha(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    @unittest.skipIf("surface_render_method" in bpy.types.Material.bl_rna.properties,
                     "EEVEE Next (4.2+) has no Alpha Clip: its render method is Dithered or Blended")
    def test_alpha_clip_cuts_below_the_threshold(self):
        scene, mat = card((1.0, 0.6, 0.4, 0.0))
        mat.blend_method, mat.alpha_threshold = 'CLIP', 0.5
        cols = columns(np.asarray(helpers.render()["pixels"]))
        for k, kept in enumerate((True, True, False, False)):
            if kept:
                self.assertLess(cols[k][1], 0.5, f"texel {k} kept")
            else:
                np.testing.assert_allclose(cols[k], WORLD, atol=1e-4, err_msg=f"texel {k} cut: the world shows")
        mat.blend_method = 'OPAQUE'  # EEVEE ignores the alpha: every texel drawn
        cols = columns(np.asarray(helpers.render()["pixels"]))
        self.assertTrue(all(c[1] < 0.5 for c in cols), cols)

    def test_hashed_alpha_averages_into_coverage(self):
        """Alpha 1, 0.75, 0.25, 0 over 32 samples: the world shows through by 1 - alpha."""
        scene, mat = card((1.0, 0.75, 0.25, 0.0), samples=32)
        if hasattr(mat, "surface_render_method"):
            mat.surface_render_method = 'DITHERED'
        else:
            mat.blend_method = 'HASHED'
        rec = helpers.render()
        px = np.asarray(rec["pixels"])
        cols = columns(px)
        kept = cols[0][1]  # the red texel's own green, lit by the world
        q = SIZE // 4
        for k, alpha in enumerate((1.0, 0.75, 0.25, 0.0)):
            shown = (cols[k][1] - 1.0) / (kept - 1.0)  # 1 where the texel covers, 0 where the world shows
            self.assertAlmostEqual(shown, alpha, delta=0.06, msg=f"texel {k}")
            # Per pixel too: a hash that stood still over the samples would cut each pixel
            # wholly or not at all (RMS about 0.43 at 0.75); moving, about 0.03.
            each = (px[4:-4, k * q + 2:(k + 1) * q - 2, 1] - 1.0) / (kept - 1.0)
            self.assertLess(float(np.sqrt(np.mean((each - alpha) ** 2))), 0.15, f"texel {k}, per pixel")
        self.assertFalse([m for m in messages(rec) if "material 'Card'" in m], "drawn, so nothing is said")

    def test_blended_alpha_is_drawn_hashed_and_says_so(self):
        scene, mat = card((1.0, 0.75, 0.25, 0.0), samples=16)
        if hasattr(mat, "surface_render_method"):
            mat.surface_render_method = 'BLENDED'
        else:
            mat.blend_method = 'BLEND'
        rec = helpers.render()
        cols = columns(np.asarray(rec["pixels"]))
        np.testing.assert_allclose(cols[3], WORLD, atol=1e-4)
        said = [m for m in messages(rec) if "material 'Card'" in m]
        self.assertEqual(len(said), 1, said)
        self.assertIn("blended alpha is drawn hashed", said[0])


def _set_cut(mat, hashed=False, shadow='CUT'):
    """Alpha Clip at 1/2 (3.4), or hashed: Alpha Hashed (3.4) / Dithered (4.2+); its shadow cut
    as its surface (3.4: Shadow Mode Clip or Hashed; 4.2+: Transparent Shadows), whole
    ('OPAQUE') or none ('NONE', 3.4 only)."""
    if hasattr(mat, "surface_render_method"):
        mat.surface_render_method = 'DITHERED'
        mat.use_transparent_shadow = shadow == 'CUT'
    else:
        mat.blend_method, mat.alpha_threshold = ('HASHED' if hashed else 'CLIP'), 0.5
        mat.shadow_method = {'CUT': mat.blend_method}.get(shadow, shadow)


class CutShadows(unittest.TestCase):
    """An alpha-cut card 1 above a white floor, its left half kept (alpha 1) and its right half
    cut (alpha 0), under a sun 45 degrees to the side: the kept half's shadow falls on the floor
    under the cut half (seen through it), and the cut half casts none, as in EEVEE."""

    def setUp(self):
        helpers.needs_gpu()

    def scene(self, hashed, toon=False, shadow='CUT'):
        scene = helpers.empty_scene(96, 64, highlights=False)
        helpers.set_world_color(scene, (0.0, 0.0, 0.0))
        bpy.ops.mesh.primitive_plane_add(size=20.0)
        floor = bpy.context.object
        floor.data.materials.append(zoo.material("Floor", (0.8, 0.8, 0.8)))
        bpy.ops.mesh.primitive_plane_add(size=2.0, location=(0.0, 0.0, 1.0))
        card_ob = bpy.context.object
        img = bpy.data.images.new("Half", 2, 1, alpha=True, float_buffer=True)
        img.pixels.foreach_set(np.array([(*RED, 1.0), (*RED, 0.0)], np.float32).reshape(-1))
        mat = zoo.material("Card", (0.8, 0.8, 0.8))
        mat.use_nodes = True
        nodes, links = mat.node_tree.nodes, mat.node_tree.links
        bsdf = next(n for n in nodes if n.type == 'BSDF_PRINCIPLED')
        tex = nodes.new('ShaderNodeTexImage')
        tex.image, tex.interpolation = img, 'Closest'
        links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
        links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
        _set_cut(mat, hashed, shadow)
        if toon:
            mat.edgelight.shading = 'RAMP'
        card_ob.data.materials.append(mat)
        cam = zoo.top_camera(3.0)
        cam.location.x = 1.0
        sun = helpers.add_sun((-1.0, 0.0, 1.0), 3.0)  # light travels towards +x and down
        sun.data.angle = 0.0
        return scene

    def floor_at(self, px, x):
        """Mean luminance of a column band of the floor at world x (16 px a unit, x from -2)."""
        col = int(round((x + 2.0) * 16.0))
        return float(px[20:44, col - 3:col + 4, :3].mean())

    def floor(self, hashed=False, toon=False, shadow='CUT'):
        """The floor's brightness under the kept half's shadow, where the cut half's would fall,
        and lit."""
        self.scene(hashed, toon, shadow)
        px = np.asarray(helpers.render()["pixels"])
        return self.floor_at(px, 0.5), self.floor_at(px, 1.5), self.floor_at(px, 3.0)

    def check(self, hashed, toon=False):
        shadowed, under_cut, lit = self.floor(hashed, toon)
        print(f"floor: under the kept half's shadow {shadowed:.4f}, where the cut half's would fall {under_cut:.4f}, "
              f"lit {lit:.4f}")
        self.assertGreater(lit, 0.1)
        self.assertLess(shadowed, 0.05 * lit, "the kept half casts its shadow, seen through the cut half")
        self.assertAlmostEqual(under_cut / lit, 1.0, delta=0.01, msg="the cut half casts no shadow")

    def test_clipped_card(self):
        self.check(hashed=False)

    def test_hashed_card_and_a_toon_card(self):
        self.check(hashed=True)
        self.check(hashed=False, toon=True)

    def test_the_materials_shadow_mode(self):
        """Shadows not cut (3.4's Shadow Mode Opaque, 4.2+'s Transparent Shadows off): the whole
        card casts, its cut half too; 3.4's Shadow Mode None: nothing."""
        shadowed, under_cut, lit = self.floor(shadow='OPAQUE')
        self.assertLess(under_cut, 0.05 * lit, "the cut half casts")
        if "surface_render_method" not in bpy.types.Material.bl_rna.properties:  # 3.4
            shadowed, under_cut, lit = self.floor(shadow='NONE')
            self.assertAlmostEqual(shadowed / lit, 1.0, delta=0.01, msg="no shadow at all")


if __name__ == "__main__":
    unittest.main()
