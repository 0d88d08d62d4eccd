"""addon/library_check.py in plain Python (no Blender): damaged copies of the built library are
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
sys.path.insert(0, os.path.join(ROOT, "addon"))
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

    def test_intact_copy_passes_with_and_without_record(self):
        self.assertEqual(library_check.check(self.copy("record", self.data)), "record")
        self.assertEqual(library_check.check(self.copy("bare", self.data, record=False)), "elf")

    def test_truncated_copies_are_refused_by_size(self):
        for size in (len(self.data) // 2, 100, len(self.data) - 1):
            message = self.refused(self.copy(f"cut{size}", self.data[:size]))
            self.assertIn(f"is {size} bytes but libedgelight.json records {len(self.data)}", message)
            self.assertIn("truncated", message)

    def test_truncated_copies_without_record_are_refused_by_elf_headers(self):
        for size in (len(self.data) // 2, 100, 10, 0):
            message = self.refused(self.copy(f"cut{size}", self.data[:size], record=False))
            self.assertIn("truncated", message)
        # Not a whole section short: the section header table ends the file.
        message = self.refused(self.copy("short", self.data[:-1], record=False))
        self.assertIn(f"is {len(self.data) - 1} bytes but its ELF headers declare {len(self.data)}", message)

    def test_flipped_bit_is_refused_by_checksum(self):
        flipped = bytearray(self.data)
        flipped[len(flipped) // 2] ^= 0x10
        message = self.refused(self.copy("flip", bytes(flipped)))
        self.assertIn("does not match the SHA-256 checksum in libedgelight.json", message)

    def test_not_elf_and_unreadable_record(self):
        self.assertIn("is not an ELF library", self.refused(self.copy("text", b"#!/bin/sh\n" * 100, record=False)))
        path = self.copy("badrecord", self.data)
        with open(library_check.record_path(path), "w", encoding="utf-8") as f:
            f.write('{"size": 1')
        with self.assertRaises(library_check.Corrupt) as caught:
            library_check.check(path)
        self.assertIn("libedgelight.json (the record of " + path + ") is unreadable", str(caught.exception))

    def test_hashed_once_per_file(self):
        path, bare = self.copy("timed", self.data), self.copy("timed_bare", self.data, record=False)
        times = []
        with mock.patch.object(library_check.hashlib, "sha256", wraps=hashlib.sha256) as hashed:
            for p in (path, path, bare):
                start = time.perf_counter()
                library_check.check(p)
                times.append((time.perf_counter() - start) * 1e3)
        self.assertEqual(hashed.call_count, 1)
        print(f"\nchecks of {len(self.data)} bytes: with record {times[0]:.2f} ms, again {times[1]:.3f} ms; "
              f"ELF headers only {times[2]:.2f} ms", file=sys.stderr)

if __name__ == "__main__":
    unittest.main()
