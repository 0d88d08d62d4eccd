"""The typedef specs of shaders/ (frame_data.json, surface_modes.json) in plain Python: the add-on
(addon/bridge/shader_specs.py) and edgelight-render (native/tools/typedef_spec.cpp) write the
same GLSL from them and derive the same layout, so the two hosts cannot drift apart.

    EDGELIGHT_TYPEDEF_DUMP=build/tests/addon/typedef_spec_dump python3 tests/addon/test_shader_specs.py
"""
import json
import os
import subprocess
import unittest

import numpy as np

from addon_modules import ROOT, addon_module

shader_specs = addon_module("bridge.shader_specs")
SHADERS = os.path.join(ROOT, "shaders")


def typedef_specs():
    """Every JSON typedef a program of programs.json lists."""
    programs = shader_specs.load("programs.json")
    return sorted({f for name, d in programs.items() if not name.startswith("_")
                   for f in d["typedefs"] if f.endswith(".json")})


def native(file_name):
    dump = os.environ.get("EDGELIGHT_TYPEDEF_DUMP")
    if not dump:
        raise unittest.SkipTest("EDGELIGHT_TYPEDEF_DUMP not set (ctest sets it)")
    run = subprocess.run([dump, SHADERS, file_name], check=True, capture_output=True, text=True)
    return json.loads(run.stdout)


class BothHosts(unittest.TestCase):
    def test_the_programs_list_the_specs(self):
        self.assertEqual(typedef_specs(), ["frame_data.json", "material_data.json", "surface_modes.json"])

    def test_same_glsl(self):
        for name in typedef_specs():
            with self.subTest(spec=name):
                self.assertEqual(shader_specs.typedef_glsl(name), native(name)["glsl"])

    def test_same_layout_and_defines(self):
        for name in typedef_specs():
            with self.subTest(spec=name):
                block, cpp = shader_specs.Block(name), native(name)
                self.assertEqual(block.size, cpp["size"])
                self.assertEqual(block.defines, cpp["defines"])
                self.assertEqual({k: list(v) for k, v in block.members.items()}, cpp["members"])


class FrameData(unittest.TestCase):
    def setUp(self):
        self.block = shader_specs.Block("frame_data.json")

    def test_members_follow_each_other(self):
        # The GL compiler's own offsets are checked against these in render.TypedefSpec.
        self.assertEqual(self.block.members["view"], (0, 1, 16))
        self.assertEqual(self.block.members["eye"], (32, 1, 4))
        self.assertEqual(self.block.members["light_color"], (52, 16, 4))
        # The shadows' members follow the lights' (docs/shadows.md): 16 light_shadow, 16
        # shadow_split, shadow_map, frame_pixel; the world image's (environment.glsl): env,
        # 8 env_level, env_irradiance, env_rotation, and the background's clip_to_world; then
        # the 32 shadow matrices.
        self.assertEqual(self.block.members["light_shadow"], (308, 16, 4))
        self.assertEqual(self.block.members["env"], (444, 1, 4))
        self.assertEqual(self.block.members["env_level"], (448, 8, 4))
        self.assertEqual(self.block.members["clip_to_world"], (500, 1, 16))
        self.assertEqual(self.block.members["shadow_matrix"], (516, 32, 16))
        self.assertEqual(self.block.size, 1028)

    def test_pack_places_values_and_refuses_what_does_not_fit(self):
        data = self.block.pack({"camera": (2.0, 3.0, 0.0, 0.0), "light_position": [(1, 2, 3, 0), (4, 5, 6, 0)]})
        self.assertEqual(data.dtype, np.float32)
        self.assertEqual(data[48:50].tolist(), [2.0, 3.0])
        self.assertEqual(data[116:124].tolist(), [1, 2, 3, 0, 4, 5, 6, 0])
        self.assertEqual(np.count_nonzero(data), 8)
        with self.assertRaises(ValueError):
            self.block.pack({"eye": (1.0, 2.0, 3.0, 4.0, 5.0)})
        with self.assertRaises(KeyError):
            self.block.pack({"no_such_member": (0.0,)})

    def test_light_kinds_are_blenders_light_types(self):
        kinds = shader_specs.load("frame_data.json")["enums"]["EL_LIGHT"]
        self.assertLessEqual(set(kinds), {"SUN", "POINT", "SPOT", "AREA"})
        self.assertEqual(len(set(kinds.values())), len(kinds))

    def test_only_vec4_and_mat4_are_packed(self):
        shader_specs._loaded["bad.json"] = {"struct": "Bad", "members": [{"type": "VEC3", "name": "v"}]}
        self.addCleanup(shader_specs._loaded.pop, "bad.json")
        with self.assertRaises(ValueError):
            shader_specs.Block("bad.json")
        with self.assertRaises(ValueError):
            shader_specs.typedef_glsl("bad.json")


if __name__ == "__main__":
    unittest.main()
