"""What every backend accepts, checked on programs.json and the GLSL it names, in plain Python
(docs/lines.md, "Depth on every GPU"; docs/versions.md, "Backends"):

- a program whose fragment stage writes gl_FragDepth declares how (depth_write: ANY, GREATER or
  LESS), and only such a program declares one: Blender declares an undeclared write
  depth_unchanged (4.x on OpenGL; Metal drops it), and a driver may keep the rasterised depth;
- a program's push constants fit in 128 bytes, what Vulkan and Metal guarantee (Blender warns
  past it): the rest belongs in a uniform block;
- no GLSL beyond 3.30, the version Blender uses on OpenGL 3.3 (3.4's minimum, and Mesa's
  softpipe): the built-in functions of later versions are refused by name, except in code kept
  for GLSL 4 behind `#if __VERSION__ >= 400` with a 3.30 branch beside it.

    python3 tests/addon/test_program_limits.py
"""
import os
import re
import unittest

from addon_modules import addon_module

shader_specs = addon_module("bridge.shader_specs")

PUSH_CONSTANT_BYTES = 128
# std430 sizes of the push constant types, a vec3 counted as 16 (its alignment).
SIZES = {"FLOAT": 4, "INT": 4, "UINT": 4, "BOOL": 4, "VEC2": 8, "IVEC2": 8, "UVEC2": 8, "VEC3": 16,
         "IVEC3": 16, "UVEC3": 16, "VEC4": 16, "IVEC4": 16, "UVEC4": 16, "MAT3": 48, "MAT4": 64}
DEPTH_WRITES = {"ANY", "GREATER", "LESS"}
# Built-in functions GLSL 3.30 lacks (4.00 to 4.60), and the layouts of later versions.
LATER_GLSL = ("packHalf2x16", "unpackHalf2x16", "packUnorm2x16", "packSnorm2x16", "packUnorm4x8", "packSnorm4x8",
              "unpackUnorm2x16", "unpackSnorm2x16", "unpackUnorm4x8", "unpackSnorm4x8", "packDouble2x32",
              "bitfieldExtract", "bitfieldInsert", "bitfieldReverse", "bitCount", "findLSB", "findMSB", "uaddCarry",
              "usubBorrow", "umulExtended", "imulExtended", "fma", "frexp", "ldexp", "textureGather",
              "textureGatherOffset", "textureQueryLod", "textureQueryLevels", "textureSamples", "interpolateAtCentroid",
              "interpolateAtSample", "interpolateAtOffset", "imageLoad", "imageStore", "imageSize", "atomicAdd",
              "atomicMin", "atomicMax", "atomicCounter", "memoryBarrier", "barrier", "subroutine")


def source(name):
    with open(os.path.join(shader_specs.shader_dir(), name), encoding="utf-8") as f:
        text = f.read()
    # Comments may name anything, and code kept for GLSL 4 by `#if __VERSION__ >= 4..` may use it.
    text = re.sub(r"/\*.*?\*/|//[^\n]*", " ", text, flags=re.S)
    return re.sub(r"#if __VERSION__ >= 4\d\d\n.*?\n#(else|endif)", " ", text, flags=re.S)


def programs():
    return {name: d for name, d in shader_specs.load("programs.json").items() if not name.startswith("_")}


def glsl_files(d):
    return [f for f in d["typedefs"] + d["vertex"] + d["fragment"] if f.endswith(".glsl")]


def writes_depth(d):
    return any(re.search(r"\bgl_FragDepth\s*=", source(f)) for f in d["fragment"])


class ProgramLimits(unittest.TestCase):
    def test_a_depth_write_is_declared(self):
        for name, d in programs().items():
            with self.subTest(program=name):
                if writes_depth(d):
                    self.assertIn(d.get("depth_write"), DEPTH_WRITES, f"{name} writes gl_FragDepth undeclared")
                else:
                    self.assertNotIn("depth_write", d, f"{name} declares a depth write it does not make")

    def test_push_constants_fit_128_bytes(self):
        for name, d in programs().items():
            with self.subTest(program=name):
                size = sum(SIZES[t] for t, _ in d["push_constants"])
                self.assertLessEqual(size, PUSH_CONSTANT_BYTES, f"{name}: {size} bytes of push constants")

    def test_no_glsl_past_330(self):
        pattern = re.compile(r"\b(" + "|".join(LATER_GLSL) + r")\s*\(")
        files = sorted({f for d in programs().values() for f in glsl_files(d)})
        self.assertGreater(len(files), 10)
        for f in files:
            with self.subTest(file=f):
                self.assertIsNone(pattern.search(source(f)))

    def test_the_checks_catch_what_they_look_for(self):
        """Each check against a program made to break it."""
        line = dict(programs()["line"])
        self.assertTrue(writes_depth(line))
        self.assertNotIn(line.pop("depth_write"), (None, "UNCHANGED"))
        self.assertNotIn(line.get("depth_write"), DEPTH_WRITES)
        edge = programs()["edge_highlight"]
        grown = edge["push_constants"] + [["VEC4", "table_params"]]
        self.assertGreater(sum(SIZES[t] for t, _ in grown), PUSH_CONSTANT_BYTES)  # the 136 bytes before
        self.assertIsNotNone(re.search(r"\bpackHalf2x16\s*\(", "end0 = uvec4(packHalf2x16(vec2(0.0)));"))


if __name__ == "__main__":
    unittest.main()
