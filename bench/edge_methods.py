"""The edge pass's earlier methods and its no-shading floor, for the benchmarks and tests that
compare against them. The add-on ships one method, EdgeLight's; the others live in bench/shaders/
(edge_methods.json: how they change the add-on's edge_highlight program) and reach the add-on
running in this Blender through passes/shader_lib.use_variant:

    sys.path.insert(0, "bench")
    import edge_methods
    edge_methods.use("whole")                 # later draws of the edge pass: the whole-arc mean
    edge_methods.use("partial", floor=True)   # EdgeLight's quads with no shading
    edge_methods.restore()                    # the add-on's own program again
    with edge_methods.method("whole"):
        ...

Methods: "partial" (EdgeLight's, the add-on's code), "whole" (the band centred on the line, the
whole visible arc's mean everywhere), "paper" (a 1-pixel line), "quadrature" (EdgeLight's with
the kernel by brute-force quadrature). edgelight-render's tests and benchmarks build the same
variants (native/tools/render_passes.cpp, Scene::edge_method, tight_edge_quads, edge_floor).
"""
import contextlib
import copy
import importlib
import json
import os
import sys

SHADERS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "shaders")
OVERLAY = os.path.join(SHADERS, "edge_methods.json")
# EL_EDGE_METHOD of each method (bench/shaders/edge_methods.glsl).
METHODS = {"partial": 0, "whole": 1, "paper": 2, "quadrature": 3}


def variant(program, overlay):
    """The program description `program` (a programs.json entry) changed as `overlay` says
    (edge_methods.json): its flat outputs added, and per stage each file it names replaced by
    its list. A file the program does not have is an error: the variant would silently be the
    add-on's program."""
    d = copy.deepcopy(program)
    d["vertex_out"]["flat"] = list(d["vertex_out"].get("flat", [])) + overlay.get("vertex_out_flat", [])
    for stage in ("vertex", "fragment"):
        swap = overlay.get(stage, {})
        missing = sorted(set(swap) - set(d[stage]))
        if missing:
            raise ValueError(f"{OVERLAY}: the {stage} stage of '{overlay['program']}' has no {', '.join(missing)}")
        d[stage] = [f for name in d[stage] for f in swap.get(name, [name])]
    return d


def defines(method="partial", floor=False, tight_quads=True):
    """The defines that pick a variant (edge_methods.json)."""
    if method not in METHODS:
        raise ValueError(f"unknown edge method '{method}' (one of {', '.join(METHODS)})")
    out = {"EL_EDGE_METHOD": METHODS[method], "EL_TIGHT_QUADS": "true" if tight_quads else "false"}
    if floor:
        out["EL_EDGE_FLOOR"] = 1
    return out


def _addon_module(name):
    """NAME ("passes.shader_lib") of the add-on loaded in this Blender ("edgelight" as a legacy
    add-on, "bl_ext.user_default.edgelight" as an extension)."""
    for key, module in list(sys.modules.items()):
        if key == "edgelight." + name or key.endswith(".edgelight." + name):
            return module
    return importlib.import_module("edgelight." + name)


def use(method="partial", floor=False, tight_quads=True):
    """The add-on's edge pass draws with `method` (and with no shading when `floor`) until
    restore()."""
    with open(OVERLAY, encoding="utf-8") as f:
        overlay = json.load(f)
    program = variant(_addon_module("bridge.shader_specs").program(overlay["program"]), overlay)
    _addon_module("passes.shader_lib").use_variant(overlay["program"], program, SHADERS, defines(method, floor, tight_quads))


def restore():
    """The add-on's own edge pass again."""
    _addon_module("passes.shader_lib").use_variant("edge_highlight")


@contextlib.contextmanager
def method(name, floor=False):
    """use(name, floor) for the duration of a `with` block."""
    use(name, floor)
    try:
        yield
    finally:
        restore()
