"""addon/bridge/native.py in plain Python (no Blender), against the built library and its header.

The header's layouts and constants come from a C program generated from edgelight.h
(abi_dump_source.py), so a field or flag changed in C and not in the binding fails here.

    EDGELIGHT_LIBRARY=build/native/libedgelight.so EDGELIGHT_ABI_DUMP=build/tests/addon/edgelight_abi_dump \
        python3 tests/addon/test_native_binding.py
"""
import ctypes
import json
import os
import subprocess
import unittest

import numpy as np

from addon_modules import addon_module

native = addon_module("bridge.native")  # imports no bpy

# Constants the binding does not mirror, and why.
NOT_MIRRORED = {
    # Status codes reach Python as names (el_status_name) inside NativeError, never as numbers.
    "EL_OK", "EL_ERR_NULL_POINTER", "EL_ERR_INVALID_COUNT", "EL_ERR_INDEX_OUT_OF_RANGE",
    "EL_ERR_NON_FINITE", "EL_ERR_OVERFLOW", "EL_ERR_INVALID_ARGUMENT", "EL_ERR_BUFFER_TOO_SMALL",
    "EL_ERR_OUT_OF_MEMORY", "EL_ERR_INTERNAL",
}


def header():
    dump = os.environ.get("EDGELIGHT_ABI_DUMP")
    if not dump:
        raise unittest.SkipTest("EDGELIGHT_ABI_DUMP not set (ctest sets it)")
    return json.loads(subprocess.run([dump], check=True, capture_output=True, text=True).stdout)


def binding_of(struct_name):
    """el_mesh_info -> native.MeshInfo (ctypes), el_chain_link -> native.CHAIN_LINK (numpy)."""
    words = struct_name[len("el_"):].split("_")
    return getattr(native, "".join(w.title() for w in words), None) or getattr(native, "_".join(words).upper(), None)


def layout(binding):
    if isinstance(binding, np.dtype):
        return binding.itemsize, {name: binding.fields[name][1] for name in binding.names}
    return ctypes.sizeof(binding), {name: getattr(binding, name).offset for name, *_ in binding._fields_}


class HeaderAgreement(unittest.TestCase):
    def test_every_struct_has_the_headers_size_and_offsets(self):
        for name, c in header()["structs"].items():
            with self.subTest(struct=name):
                binding = binding_of(name)
                self.assertIsNotNone(binding, f"no binding for {name}")
                size, offsets = layout(binding)
                self.assertEqual(size, c["size"])
                self.assertEqual(offsets, c["fields"])

    def test_every_constant_has_the_headers_value(self):
        for name, value in header()["constants"].items():
            if name in NOT_MIRRORED:
                continue
            with self.subTest(constant=name):
                self.assertEqual(getattr(native, name[len("EL_"):], None), value)

    def test_the_outline_records_are_shaders_outline_layout_json(self):
        """The edge and corner records el_outline_lines reads are the surface program's outline
        texels: the header's counts are the layout's (shaders/outline_layout.json)."""
        layout = addon_module("bridge.shader_specs").load("outline_layout.json")["defines"]
        constants = header()["constants"]
        for name in ("EL_OUTLINE_EDGE_TEXELS", "EL_OUTLINE_CORNER_TEXELS"):
            with self.subTest(constant=name):
                self.assertEqual(constants[name], layout[name])


class Library(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.lib = native.load()

    def cube(self, flip=()):
        p = np.array([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], np.float32)
        quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        tris = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], np.uint32)
        tris[list(flip)] = tris[list(flip)][:, ::-1]
        return native.Mesh(p, tris, lib=self.lib)

    def test_cube_classifies_as_a_cube(self):
        m = self.cube()
        info = m.info()
        self.assertEqual((info["vertex_count"], info["triangle_count"], info["edge_count"]), (8, 12, 18))
        flags = m.edge_flags()
        self.assertEqual(int(((flags & native.EDGE_CREASE) != 0).sum()), 12)
        self.assertEqual(int(((flags & native.EDGE_CONVEX) != 0).sum()), 12)
        self.assertTrue(np.allclose(np.sort(m.edge_angles())[-12:], 90.0, atol=1e-3))

    def test_half_flipped_cube_classifies_like_the_cube(self):
        good, bad = self.cube(), self.cube(flip=range(0, 12, 2))
        self.assertEqual(bad.info()["reoriented_triangles"], 6)
        self.assertEqual(int(bad.triangle_flips().sum()), 6)
        self.assertEqual(good.info()["reoriented_triangles"], 0)
        self.assertTrue(np.array_equal(bad.edge_flags(), good.edge_flags()))

    def test_errors_carry_the_status_and_message(self):
        p = np.zeros((3, 3), np.float32)
        p[1, 0] = np.nan
        with self.assertRaises(native.NativeError) as e:
            native.Mesh(p, np.array([[0, 1, 2]], np.uint32), lib=self.lib)
        self.assertEqual(e.exception.status, "EL_ERR_NON_FINITE")
        self.assertTrue(e.exception.message)


if __name__ == "__main__":
    unittest.main(verbosity=2)
