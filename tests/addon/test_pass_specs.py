"""shaders/passes.json against programs.json and the library's binding, in plain Python: every
name a pass uses exists where it points, so both hosts (addon/passes/pass_state.py,
native/tools/pass_state.cpp) can draw from it; checked here before anything draws (at draw time
shader_lib.set_sampler and edgelight-render refuse an unknown name too).

    python3 tests/addon/test_pass_specs.py
"""
import unittest

from addon_modules import addon_module

shader_specs = addon_module("bridge.shader_specs")
native = addon_module("bridge.native")  # imports no bpy; the library is not loaded

# Blender's names that edgelight-render maps (native/tools/pass_state.cpp).
FORMATS = {"RGBA32F", "RG32F", "R32F", "DEPTH_COMPONENT32F"}
DEPTH_TESTS = {"NONE", "ALWAYS", "LESS", "LESS_EQUAL", "EQUAL", "GREATER", "GREATER_EQUAL"}
BLENDS = {"NONE", "ALPHA_PREMULT", "ADDITIVE_PREMULT", "MULTIPLY"}
FACE_CULLING = {"NONE", "BACK"}


class Passes(unittest.TestCase):
    def setUp(self):
        self.spec = shader_specs.load("passes.json")
        self.programs = shader_specs.load("programs.json")

    def test_targets_have_known_formats(self):
        self.assertLessEqual(set(self.spec["targets"].values()), FORMATS)

    def test_each_pass_names_what_its_program_declares(self):
        for name, p in self.spec["passes"].items():
            with self.subTest(pass_=name):
                d = self.programs[p["program"]]
                samplers = {var for _, var in d["samplers"]}
                self.assertLessEqual(set(p["inputs"]), samplers)
                # Every output of every variant has a target, and nothing else is named.
                outputs = {var for _, var in d["fragment_out"]}
                outputs |= {var for extra in d.get("fragment_out_if", {}).values() for _, var in extra}
                self.assertEqual(set(p["outputs"]), outputs)
                targets = set(self.spec["targets"])
                self.assertLessEqual(set(p["inputs"].values()) | set(p["outputs"].values()), targets)
                colour = {self.spec["targets"][t] for t in p["outputs"].values()}
                self.assertNotIn("DEPTH_COMPONENT32F", colour)
                if "depth_target" in p:
                    self.assertEqual(self.spec["targets"][p["depth_target"]], "DEPTH_COMPONENT32F")

    def test_state_uses_names_both_hosts_know(self):
        for name, p in self.spec["passes"].items():
            with self.subTest(pass_=name):
                s = p["state"]
                self.assertIn(s["depth_test"], DEPTH_TESTS)
                self.assertIsInstance(s["depth_write"], bool)
                self.assertIn(s["blend"], BLENDS)
                self.assertIn(s["face_culling"], FACE_CULLING)
                self.assertLessEqual(set(p.get("clear", {})), {"color", "depth"})

    def test_table_terms_are_table_info_fields(self):
        fields = {name for name, _ in native.TableInfo._fields_}
        for name, p in self.spec["passes"].items():
            if "table" not in p:
                continue
            t, d = p["table"], self.programs[p["program"]]
            self.assertIn(t["sampler"], {var for _, var in d["samplers"]})
            self.assertLessEqual(set(t["defines"].values()), fields)
            self.assertLessEqual(set(t.get("float_defines", {}).values()), fields)
            self.assertEqual(set(t) - {"sampler", "defines", "float_defines"}, set(), "a table term nobody reads")


if __name__ == "__main__":
    unittest.main()
