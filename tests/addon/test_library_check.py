"""addon/bridge/library_check.py in plain Python (no Blender): damaged copies of the built library are
refused before anything maps them, intact ones pass.

    EDGELIGHT_LIBRARY_UNDER_TEST=build/native/libedgelight.so python3 tests/addon/test_library_check.py
"""
import hashlib
import json
import os
import shutil
import sys
import tempfile
import time
import unittest
from unittest import mock

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "addon", "bridge"))
import library_check  # noqa: E402  (plain Python, imports no bpy)

LIBRARY = os.environ.get("EDGELIGHT_LIBRARY_UNDER_TEST", os.path.join(ROOT, "build", "native", "libedgelight.so"))


class LibraryFileCheck(unittest.TestCase):
    def setUp(self):
        self.assertTrue(os.path.isfile(LIBRARY), f"EDGELIGHT_LIBRARY_UNDER_TEST={LIBRARY!r} (set by ctest)")
        with open(LIBRARY, "rb") as f:
            self.data = f.read()
        self.dir = tempfile.mkdtemp(prefix="edgelight_check_")
        self.addCleanup(shutil.rmtree, self.dir)

    def copy(self, name, content, record=True):
        """A copy of the library holding `content`, with the intact library's record if `record`."""
        os.mkdir(os.path.join(self.dir, name))
        path = os.path.join(self.dir, name, "libedgelight.so")
        with open(path, "wb") as f:
            f.write(content)
        if record:
            with open(library_check.record_path(path), "w", encoding="utf-8") as f:
                json.dump(dict(library_check.make_record(LIBRARY), file="libedgelight.so"), f)
        return path

    def refused(self, path):
        with self.assertRaises(library_check.Corrupt) as caught:
            library_check.check(path)
        message = str(caught.exception)
        self.assertIn(path, message)
        return message

    def test_intact_copy_passes_with_its_record(self):
        self.assertEqual(library_check.check(self.copy("record", self.data)), "record")

    def test_a_copy_without_record_is_refused(self):
        """Intact, truncated or flipped: without a record nothing tells a damaged file from the
        library, and a flipped byte passes any check of a format's headers."""
        flipped = bytearray(self.data)
        flipped[len(flipped) // 2] ^= 0x10
        for name, content in (("intact", self.data), ("half", self.data[:len(self.data) // 2]), ("flipped", bytes(flipped)),
                              ("text", b"#!/bin/sh\n" * 100)):
            message = self.refused(self.copy(f"bare_{name}", content, record=False))
            self.assertIn("has no checksum record (libedgelight.json beside it)", message)

    def test_truncated_copies_are_refused_by_size(self):
        for size in (len(self.data) // 2, 100, len(self.data) - 1):
            message = self.refused(self.copy(f"cut{size}", self.data[:size]))
            self.assertIn(f"is {size} bytes but libedgelight.json records {len(self.data)}", message)
            self.assertIn("truncated", message)

    def test_flipped_bit_is_refused_by_checksum(self):
        flipped = bytearray(self.data)
        flipped[len(flipped) // 2] ^= 0x10
        message = self.refused(self.copy("flip", bytes(flipped)))
        self.assertIn("does not match the SHA-256 checksum in libedgelight.json", message)

    def test_unreadable_record(self):
        path = self.copy("badrecord", self.data)
        with open(library_check.record_path(path), "w", encoding="utf-8") as f:
            f.write('{"size": 1')
        with self.assertRaises(library_check.Corrupt) as caught:
            library_check.check(path)
        self.assertIn("libedgelight.json (the record of " + path + ") is unreadable", str(caught.exception))

    def test_the_build_writes_the_record(self):
        """The built library has its record beside it (native/CMakeLists.txt), and it passes."""
        self.assertTrue(os.path.isfile(library_check.record_path(LIBRARY)), "the build writes libedgelight.json")
        self.assertEqual(library_check.check(LIBRARY), "record")

    def test_hashed_once_per_file(self):
        path = self.copy("timed", self.data)
        times = []
        with mock.patch.object(library_check.hashlib, "sha256", wraps=hashlib.sha256) as hashed:
            for p in (path, path):
                start = time.perf_counter()
                library_check.check(p)
                times.append((time.perf_counter() - start) * 1e3)
        self.assertEqual(hashed.call_count, 1)
        print(f"\nchecks of {len(self.data)} bytes: with record {times[0]:.2f} ms, again {times[1]:.3f} ms",
              file=sys.stderr)


if __name__ == "__main__":
    unittest.main()
