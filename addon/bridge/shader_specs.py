"""The JSON descriptions in shaders/, read without Blender (no gpu here, so plain-Python tests
import it): programs.json, the typedef specs (frame_data.json, surface_modes.json) and
passes.json.

A typedef spec is the one description of a contract between GLSL and a host: its GLSL (defines,
enum values, a struct) is written from it when a program is built, here and by
native/tools/typedef_spec.cpp, which must write the same text (tests/addon/test_shader_specs.py);
and a struct's std140 layout is derived from it for packing (Block).
"""
import json
import os

import numpy as np

_loaded = {}

# Floats per member type. VEC4 and MAT4 only: std140 pads nothing between them, so a member's
# offset is the sum of the sizes before it, with no alignment rule to get wrong in two hosts.
_FLOATS = {"VEC4": 4, "MAT4": 16}
_GLSL = {"VEC4": "vec4", "MAT4": "mat4"}


def shader_dir():
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for candidate in (os.path.join(here, "shaders"), os.path.join(os.path.dirname(here), "shaders")):
        if os.path.isfile(os.path.join(candidate, "programs.json")):
            return candidate
    raise FileNotFoundError(f"EdgeLight shaders not found beside {here}")


def load(name):
    """shaders/NAME parsed, read once."""
    if name not in _loaded:
        with open(os.path.join(shader_dir(), name), encoding="utf-8") as f:
            _loaded[name] = json.load(f)
    return _loaded[name]


def program(name):
    return load("programs.json")[name]


def enum(file_name, name):
    """{KEY: value} of enum `name` of the typedef spec shaders/FILE_NAME (EL_SURFACE_MODE of
    surface_modes.json, EL_LIGHT of frame_data.json)."""
    return load(file_name)["enums"][name]


def fragment_outputs(name, defines):
    """[(type, name)] of a program variant's fragment outputs in slot order: fragment_out, then
    each fragment_out_if whose define is set, in the defines' sorted order."""
    return outputs_of(program(name), defines)


def outputs_of(d, defines):
    """fragment_outputs of the program description `d` (a programs.json entry)."""
    outs = list(d["fragment_out"])
    for define, extra in sorted(d.get("fragment_out_if", {}).items()):
        if define in (defines or {}):
            outs += extra
    return outs


def defines(spec):
    """{NAME: value} of a typedef spec, in file order: its defines, then each enum's values as
    ENUM_KEY."""
    out = dict(spec.get("defines", {}))
    for enum, values in spec.get("enums", {}).items():
        out.update((f"{enum}_{key}", value) for key, value in values.items())
    return out


def typedef_glsl(file_name):
    """GLSL of the typedef spec shaders/FILE_NAME: #defines, then the struct if it has one."""
    spec = load(file_name)
    lines = [f"/* generated from {file_name} */"]
    lines += [f"#define {name} {value}" for name, value in defines(spec).items()]
    if "struct" in spec:
        lines.append(f"struct {spec['struct']} {{")
        for m in spec["members"]:
            _check_type(m, file_name)
            count = f"[{m['count']}]" if "count" in m else ""
            lines.append(f"  {_GLSL[m['type']]} {m['name']}{count};")
        lines.append("};")
    return "\n".join(lines) + "\n"


def _check_type(member, file_name):
    if member["type"] not in _FLOATS:
        raise ValueError(f"{file_name}: member {member['name']} is {member['type']}; only VEC4 and MAT4 are packed")


class Block:
    """The std140 layout of a typedef spec's struct, in floats: members[name] = (offset, count,
    floats per element)."""

    def __init__(self, file_name):
        spec = load(file_name)
        self.defines = defines(spec)
        self.members, offset = {}, 0
        for m in spec.get("members", []):  # none: defines only
            _check_type(m, file_name)
            count = m.get("count", 1)
            count = self.defines[count] if isinstance(count, str) else count
            self.members[m["name"]] = (offset, count, _FLOATS[m["type"]])
            offset += count * _FLOATS[m["type"]]
        self.size = offset

    def pack(self, values):
        """float32 block from {member: floats} (flattened; an array member's elements from the
        first, the rest zero). Every value must name a member and fit it."""
        out = np.zeros(self.size, np.float32)
        for name, value in values.items():
            offset, count, floats = self.members[name]
            with np.errstate(over='ignore'):  # past float32: inf, as the GPU would compute it
                flat = np.asarray(value, np.float32).reshape(-1)
            if flat.size > count * floats:
                raise ValueError(f"{name}: {flat.size} floats, room for {count * floats}")
            out[offset:offset + flat.size] = flat
        return out
