"""blend_samples/make_samples.py regenerates every sample, and they render."""
import os
import subprocess
import tempfile
import unittest

import bpy

import helpers


class MakeSamples(unittest.TestCase):
    def test_regenerates_all_samples(self):
        out = tempfile.mkdtemp()
        mesh_dir = os.environ.get("EDGELIGHT_MESH_DIR", "/usr/share/doc/libcgal-dev")
        cmd = helpers.blender_command(os.path.join(helpers.SAMPLES, "make_samples.py"), out, mesh_dir)
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stdout[-2000:] + run.stderr[-2000:])
        for name in ("cube", "fandisk", "prop", "toon"):
            path = os.path.join(out, name + ".blend")
            self.assertTrue(os.path.exists(path), name)
            bpy.ops.wm.open_mainfile(filepath=path)
            self.assertEqual(bpy.context.scene.render.engine, "EDGELIGHT")
            rec = helpers.render(resolution=(64, 48))
            self.assertGreater(rec["stats"].edges_drawn, 0, name)
            if name == "toon":
                self.assertGreater(rec["stats"].lines_drawn, 0, name)


if __name__ == "__main__":
    unittest.main()
