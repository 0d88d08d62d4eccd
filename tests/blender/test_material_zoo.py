"""Issue 42's scene zoo (material_zoo.py), each scene rendered by EdgeLight: it draws something
besides the world, says what it does not draw (the scene's declared unsupported parts, each
once), and says nothing of what it draws. bench/zoo_renders.py compares them with EEVEE and
Cycles."""
import unittest

import numpy as np

import helpers
import material_zoo


class MaterialZoo(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_every_scene_draws_and_says_what_it_does_not(self):
        for build in material_zoo.SCENES:
            with self.subTest(scene=build.__name__):
                info = build()
                rec = helpers.render()
                px = np.asarray(rec["pixels"])[..., :3]
                self.assertGreater(rec["stats"].objects, 0)
                # Something besides the world: the image is not one colour.
                self.assertGreater(float(px.reshape(-1, 3).std(axis=0).max()), 0.02, info.name)
                said = [m for _level, m in rec.get("messages", []) if "does not draw" in m or "does not read" in m]
                for fragment in info.unsupported:
                    self.assertEqual(sum(fragment in m for m in said), 1, f"{info.name}: {fragment!r} in {said}")
                if not info.unsupported:
                    self.assertEqual(said, [], info.name)


if __name__ == "__main__":
    unittest.main()
