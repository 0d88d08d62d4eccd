"""The engine registers and renders every sample."""
import unittest

import bpy
import numpy as np

import helpers


class EngineRegisters(unittest.TestCase):
    def test_engine_is_listed(self):
        # 4.x registers engines without a bl_idname of their own (HydraRenderEngine's base class).
        engines = [getattr(cls, "bl_idname", None) for cls in bpy.types.RenderEngine.__subclasses__()]
        self.assertIn("EDGELIGHT", engines)
        bpy.context.scene.render.engine = "EDGELIGHT"
        self.assertEqual(bpy.context.scene.render.engine, "EDGELIGHT")
        self.assertTrue(hasattr(bpy.types.Material, "edgelight"))
        self.assertTrue(hasattr(bpy.types.Scene, "edgelight"))


class Panels(unittest.TestCase):
    def test_blender_panels_for_lights_cameras_output_and_world_show_for_edgelight(self):
        compat = helpers.addon().compat
        engines = [i.identifier for i in bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items]
        self.assertIn(compat.eevee_engine_id(), engines)
        for name in ("DATA_PT_context_light", "DATA_PT_lens", "RENDER_PT_format", "EEVEE_WORLD_PT_surface"):
            self.assertIn("EDGELIGHT", getattr(bpy.types, name).COMPAT_ENGINES, name)
        # Which material, light and world panels show (and which don't): test_panels.py.


class RendersEverySample(unittest.TestCase):
    def check(self, name, min_edges):
        helpers.open_sample(name)
        rec = helpers.render(resolution=(320, 240))
        px = rec["pixels"]
        self.assertEqual(px.shape, (240, 320, 4))
        self.assertTrue(np.isfinite(px).all())
        self.assertEqual(rec.get("messages", []), [], "no warnings or errors")
        # The object covers part of the frame: pixels differ from the world colour there.
        background = np.array(bpy.context.scene.world.color[:3], np.float32)
        covered = np.abs(px[..., :3] - background).max(axis=2) > 1e-3
        self.assertGreater(covered.mean(), 0.05)
        self.assertGreaterEqual(rec["stats"].edges_drawn, min_edges)
        return rec

    def test_cube(self):
        self.check("cube", 12)

    def test_fandisk(self):
        self.check("fandisk", 300)

    def test_prop(self):
        self.check("prop", 8)


if __name__ == "__main__":
    unittest.main()
