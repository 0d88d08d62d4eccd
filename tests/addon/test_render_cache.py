"""What the final render's extraction cache keeps (addon/extract/render_cache.py), in plain Python: per
scene, what its previous frame used survives a frame change; two scenes rendered in one job keep
each other's; a job's end keeps what each scene's last frame used, or nothing; the fingerprint
tells arrays apart by content, dtype and shape.

    /usr/bin/python3 tests/addon/test_render_cache.py
"""
import unittest

import numpy as np

from addon_modules import addon_module

render_cache = addon_module("extract.render_cache")


class Cache(unittest.TestCase):
    def setUp(self):
        self.c = render_cache.ExtractCache()

    def frame(self, scene, frame, keys):
        """One render of `scene` at `frame` that draws `keys` (kept ones reused, others added)."""
        self.c.begin(scene, frame)
        hits = [k for k in keys if self.c.get(k) is not None]
        for k in keys:
            if k not in hits:
                self.c.put(k, f"extract {k}")
        return hits

    def test_an_animation_reuses_and_drops(self):
        self.frame("S", 1, ["a", "b"])
        self.assertEqual(self.frame("S", 2, ["a"]), ["a"])
        self.assertEqual(len(self.c), 2, "b was used by the previous frame")
        self.frame("S", 3, ["a"])
        self.assertEqual(len(self.c), 1)

    def test_view_layers_of_one_frame(self):
        self.frame("S", 1, ["a"])
        self.frame("S", 1, ["b"])  # a second layer of the same frame drops nothing
        self.assertEqual(self.frame("S", 2, ["a", "b"]), ["a", "b"])

    def test_two_scenes_in_one_job(self):
        for f in (1, 2, 3):
            hits = self.frame("S", f, ["a"]) + self.frame("T", f, ["b"])
            self.assertEqual(hits, [] if f == 1 else ["a", "b"], f"frame {f}")

    def test_end_of_job(self):
        self.frame("S", 1, ["a", "b"])
        self.frame("S", 1, ["c"])
        self.c.end_job(keep=True)
        self.assertEqual(len(self.c), 3)
        self.frame("S", 1, ["a2"])  # the same frame again, after an edit: a new fingerprint
        self.c.end_job(keep=True)
        self.assertEqual(len(self.c), 1, "only what the last job's frame used")
        self.c.end_job(keep=False)
        self.assertEqual(len(self.c), 0)

    def test_a_job_keeps_only_its_scenes(self):
        self.frame("S", 1, ["a"])
        self.frame("T", 1, ["b"])
        self.c.end_job(keep=True)
        self.frame("S", 1, ["a"])
        self.c.end_job(keep=True)
        self.assertEqual(len(self.c), 1, "T was not rendered by the last job")

    def test_cleared_during_a_render(self):
        self.frame("S", 1, ["a"])
        self.c.clear()  # a file load or the add-on disabled while rendering
        self.assertIsNone(self.c.get("a"))
        self.c.put("a", "extract a")
        self.assertEqual(len(self.c), 0)

    def test_fingerprint(self):
        a = np.arange(12, dtype=np.float32)
        self.assertEqual(render_cache.fingerprint([a, a]), render_cache.fingerprint([a.copy(), a.copy()]))
        b = a.copy()
        b[5] += 1e-6
        self.assertNotEqual(render_cache.fingerprint([a]), render_cache.fingerprint([b]))
        self.assertNotEqual(render_cache.fingerprint([a]), render_cache.fingerprint([a.reshape(3, 4)]))
        self.assertNotEqual(render_cache.fingerprint([a]), render_cache.fingerprint([a.view(np.int32)]))
        self.assertNotEqual(render_cache.fingerprint([a[:6], a[6:]]), render_cache.fingerprint([a[:4], a[4:]]))


if __name__ == "__main__":
    unittest.main()
