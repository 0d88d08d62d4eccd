"""Builds GPU programs from shaders/programs.json with GPUShaderCreateInfo (3.4 through 5.x).

Programs are created lazily, inside a GPU context (render() or view_draw()), and cached for the
life of the add-on; sources are read from the `shaders` folder beside the package (installed
layout) or at the repository root (development tree).
"""
import json
import os

import gpu

_cache = {}


def shader_dir():
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for candidate in (os.path.join(here, "shaders"), os.path.join(os.path.dirname(here), "shaders")):
        if os.path.isfile(os.path.join(candidate, "programs.json")):
            return candidate
    raise FileNotFoundError(f"EdgeLight shaders not found beside {here}")


def _read(name):
    with open(os.path.join(shader_dir(), name), encoding="utf-8") as f:
        return f.read()


def program_description(name):
    with open(os.path.join(shader_dir(), "programs.json"), encoding="utf-8") as f:
        return json.load(f)[name]


def get(name, defines=None):
    """The compiled program `name`, built on first use; `defines` ({NAME: value}) fix choices
    at build time (a variant per set), where a uniform branch would cost every fragment both
    sides on llvmpipe."""
    key = (name, tuple(sorted((defines or {}).items())))
    shader = _cache.get(key)
    if shader is None:
        shader = _cache[key] = _build(name, program_description(name), defines or {})
    return shader


def _build(name, d, defines):
    info = gpu.types.GPUShaderCreateInfo()
    for define, value in sorted(defines.items()):
        info.define(define, str(value))
    if d["typedefs"]:
        info.typedef_source("\n".join(_read(f) for f in d["typedefs"]))
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
    info.vertex_out(iface)
    for slot, (type_name, var) in enumerate(d["samplers"]):
        info.sampler(slot, type_name, var)
    outs = list(d["fragment_out"])
    for define, extra in sorted(d.get("fragment_out_if", {}).items()):
        if define in defines:  # an output only a variant has (a render pass asked for)
            outs += extra
    for slot, (type_name, var) in enumerate(outs):
        info.fragment_out(slot, type_name, var)
    info.vertex_source("\n".join(_read(f) for f in d["vertex"]))
    info.fragment_source("\n".join(_read(f) for f in d["fragment"]))
    try:
        return gpu.shader.create_from_info(info)
    except Exception as e:
        raise RuntimeError(f"EdgeLight: cannot compile GPU program '{name}': {e}") from e


def clear():
    _cache.clear()
