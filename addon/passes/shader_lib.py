"""Builds GPU programs from shaders/programs.json with GPUShaderCreateInfo (3.4 through 5.x).

Programs are created lazily, inside a GPU context (render() or view_draw()), and cached for the
life of the add-on; sources are read from the `shaders` folder beside the package (installed
layout) or at the repository root (development tree). A typedef that is a JSON spec
(frame_data.json) becomes GLSL here (shader_specs.typedef_glsl).

use_variant() lets a benchmark or test build one program from its own description and sources
(the edge pass's earlier methods: bench/edge_methods.py); the add-on never calls it.
"""
import json
import os

import gpu

from .. import compat
from ..bridge import shader_specs
from ..bridge.shader_specs import shader_dir

_cache = {}
# id(program) -> (its declared push constants, those its compiler kept, its declared samplers).
_names = {}
# Program name -> (description, folder read before shaders/, defines, key) set by use_variant().
_variants = {}


def _read(name, source_dir=None):
    if name.endswith(".json"):
        return shader_specs.typedef_glsl(name)
    path = os.path.join(source_dir, name) if source_dir else None
    if path is None or not os.path.isfile(path):
        path = os.path.join(shader_dir(), name)
    with open(path, encoding="utf-8") as f:
        return f.read()


def get(name, defines=None):
    """The compiled program `name`, built on first use; `defines` ({NAME: value}) fix choices
    at build time (a variant per set), where a uniform branch would cost every fragment both
    sides on llvmpipe."""
    d, source_dir, fixed, variant = _variants.get(name) or (shader_specs.program(name), None, {}, None)
    defines = {**(defines or {}), **fixed}
    key = (name, variant, tuple(sorted(defines.items())))
    shader = _cache.get(key)
    if shader is None:
        shader = _cache[key] = _build(name, d, defines, source_dir)
        declared = [var for _, var in d["push_constants"]]
        _names[id(shader)] = (frozenset(declared), frozenset(v for v in declared if _kept(shader, v)),
                              frozenset(var for _, var in d["samplers"]),
                              {var: _kept_block(shader, var) for _, _, var in d["uniform_bufs"]})
    return shader


def set_uniform(shader, name, value):
    """Sets push constant `name` of a program from get() if its variant's compiler kept it.

    A variant's compiler drops what its code does not read (spec_color in a toon surface,
    lighting inputs in the edge pass's no-shading benchmark variant), and Blender refuses to set a dropped
    uniform; the callers set everything the pass has and need not know which variant reads what.
    A name programs.json does not declare for the program is still an error."""
    declared, kept, _, _ = _names[id(shader)]
    if name not in declared:
        raise KeyError(f"EdgeLight: the program declares no push constant '{name}'")
    if name in kept:
        shader.uniform_float(name, value)


def set_sampler(shader, name, texture):
    """Binds `texture` to sampler `name` of a program from get(). Blender checks no sampler name
    (an unknown one binds outside the texture units, and 5.x crashes on that later), so the name
    is checked against programs.json here. A sampler the compiler dropped is bound harmlessly."""
    if name not in _names[id(shader)][2]:
        raise KeyError(f"EdgeLight: the program declares no sampler '{name}'")
    shader.uniform_sampler(name, texture)


def set_block(shader, name, ubo):
    """Binds uniform buffer `ubo` to block `name` of a program from get() if its variant's
    compiler kept the block (a whiteout surface reads no material block; Blender refuses to bind
    a dropped one). A name programs.json does not declare is an error."""
    blocks = _names[id(shader)][3]
    if name not in blocks:
        raise KeyError(f"EdgeLight: the program declares no uniform block '{name}'")
    if blocks[name]:
        shader.uniform_block(name, ubo)


def _kept_block(shader, name):
    try:
        shader.uniform_block_from_name(name)
    except ValueError:
        return False
    return True


def _kept(shader, name):
    try:
        shader.uniform_from_name(name)
    except ValueError:  # "uniform not found": the compiler dropped it
        return False
    return True


def use_variant(name, description=None, source_dir=None, defines=None):
    """Builds program `name` from `description` (in the form of a programs.json entry) instead
    of programs.json's, its files read from `source_dir` where they are there and from shaders/
    otherwise, with `defines` added to every build; without a description, programs.json's own
    again. For the benchmarks and tests that compare a pass with variants kept outside the
    add-on (bench/edge_methods.py): the add-on itself never calls it. Built programs stay cached
    (freeing one that a draw still refers to can crash Blender), so switching back costs nothing."""
    if description is None:
        _variants.pop(name, None)
        return
    variant = (json.dumps(description, sort_keys=True), source_dir)
    _variants[name] = (description, source_dir, dict(defines or {}), variant)


def _build(name, d, defines, source_dir=None):
    info = gpu.types.GPUShaderCreateInfo()
    for define, value in sorted(defines.items()):
        info.define(define, str(value))
    if d["typedefs"]:
        info.typedef_source("\n".join(_read(f, source_dir) for f in d["typedefs"]))
    for slot, type_name, var in d["uniform_bufs"]:
        info.uniform_buf(slot, type_name, var)
    for type_name, var in d["push_constants"]:
        info.push_constant(type_name, var)
    for slot, (type_name, var) in enumerate(d["vertex_in"]):
        info.vertex_in(slot, type_name, var)
    out = d["vertex_out"]
    iface = gpu.types.GPUStageInterfaceInfo(out["name"])
    for type_name, var in out.get("smooth", []):
        iface.smooth(type_name, var)
    for type_name, var in out.get("flat", []):
        iface.flat(type_name, var)
    for type_name, var in out.get("no_perspective", []):
        iface.no_perspective(type_name, var)
    info.vertex_out(iface)
    for slot, (type_name, var) in enumerate(d["samplers"]):
        info.sampler(slot, type_name, var)
    # Outputs a variant adds (a render pass asked for) follow the program's own.
    for slot, (type_name, var) in enumerate(shader_specs.outputs_of(d, defines)):
        info.fragment_out(slot, type_name, var)
    if "depth_write" in d:
        compat.declare_depth_write(info, d["depth_write"])
    info.vertex_source("\n".join(_read(f, source_dir) for f in d["vertex"]))
    info.fragment_source("\n".join(_read(f, source_dir) for f in d["fragment"]))
    try:
        return gpu.shader.create_from_info(info)
    except Exception as e:
        raise RuntimeError(f"EdgeLight: cannot compile GPU program '{name}': {e}") from e


def clear():
    _cache.clear()
    _names.clear()
