"""The world's light on the specular lobe (lighting.glsl's el_env_specular): a metal under a
uniform world is lit as Cycles lights it, not black, and a dielectric gains the world's
reflection at its rim (docs/highlight_math.md, "The world's light on the specular lobe")."""
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo
from test_render_passes import composited

WORLD = (0.5, 0.5, 0.5)


def sphere_scene(metallic, base, roughness):
    """A smooth sphere of radius 1 under a uniform grey world, no lights, seen from 6 units."""
    scene = helpers.empty_scene(160, 160, highlights=False)
    helpers.set_world_color(scene, WORLD)
    helpers.add_camera((0.0, -6.0, 0.0), (0.0, 0.0, 0.0))
    bpy.ops.mesh.primitive_uv_sphere_add(segments=96, ring_count=48, radius=1.0)
    ob = bpy.context.object
    bpy.ops.object.shade_smooth()
    mat = zoo.material("Metal", base)
    mat.use_nodes = True
    node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
    node.inputs["Base Color"].default_value = (*base, 1.0)
    node.inputs["Metallic"].default_value = metallic
    node.inputs["Roughness"].default_value = roughness
    ob.data.materials.append(mat)
    return scene


def cycles_pixels(scene, samples=64):
    """Cycles' linear render of the scene (its pixel filter off, so each pixel is its centre's),
    read back from a 32-bit EXR as test_render_passes reads the compositor's."""
    scene.render.engine = 'CYCLES'
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.cycles.filter_width = 0.01
    px = composited(scene, 'RGBA', record=False)[1]
    scene.render.engine = 'EDGELIGHT'
    return px


def ring(image, radius_px, centre=(80, 80)):
    """Mean colour of the pixels at about radius_px from the image's centre."""
    y, x = np.mgrid[:image.shape[0], :image.shape[1]]
    r = np.hypot(x + 0.5 - centre[0], y + 0.5 - centre[1])
    sel = np.abs(r - radius_px) < 1.5
    return image[sel][:, :3].mean(axis=0)


class WorldOnTheLobe(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_a_metal_is_lit_by_the_world_as_cycles_lights_it(self):
        base = (0.9, 0.6, 0.2)
        scene = sphere_scene(1.0, base, 0.4)
        ours = helpers.render()["pixels"]
        theirs = cycles_pixels(scene)
        # The sphere's image: 1 / (6 tan(fov / 2)) of the half width (50 mm on 36 mm: 0.3 of it).
        edge_px = 80.0 * (36.0 / 50.0 / 2.0) ** -1 / 6.0 * (1.0 / (1.0 - (1.0 / 6.0) ** 2)) ** 0.5
        for frac in (0.0, 0.5, 0.8):
            r = frac * edge_px
            a, b = (ring(img, max(r, 1.0)) for img in (ours, theirs))
            print(f"metal at {frac:.1f} of its radius: EdgeLight {np.round(a, 3)}, Cycles {np.round(b, 3)}")
            self.assertGreater(a.min(), 0.25 * np.array(WORLD).min() * min(base), "not black")
            # Measured: within 0.018 of Cycles (64 samples) in every channel.
            np.testing.assert_allclose(a, b, atol=0.03, err_msg=f"at {frac} of the radius")

    def test_a_dielectric_gains_the_worlds_reflection_at_its_rim(self):
        scene = sphere_scene(0.0, (0.2, 0.2, 0.2), 0.3)
        del scene
        ours = helpers.render()["pixels"]
        centre, rim = ring(ours, 1.0), ring(ours, 0.9 * 39.0)
        # Diffuse alone gives the same grey everywhere under a uniform world; the lobe adds the
        # Fresnel rise towards the rim.
        self.assertGreater(rim.mean(), centre.mean() + 0.01)
        np.testing.assert_allclose(centre, np.array(WORLD) * (0.2 + helpers.env_specular((0.04,) * 3, 2.0 / 0.09 ** 2 - 2.0, 1.0)),
                                   rtol=0.02)


if __name__ == "__main__":
    unittest.main()
