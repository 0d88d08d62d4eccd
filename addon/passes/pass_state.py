"""Pass state from shaders/passes.json, for Blender's gpu module: the render targets, a pass's
framebuffer, what it clears, its fixed-function state, the targets its samplers read, and the
table's defines and push constants. edgelight-render draws from the same file
(native/tools/pass_state.cpp), so a change to a pass is made there once."""
import contextlib

import gpu

from .. import compat
from ..bridge import shader_specs
from . import shader_lib


def _spec():
    return shader_specs.load("passes.json")


def _pass(name):
    return _spec()["passes"][name]


def target_names():
    return list(_spec()["targets"])


def texture(name, size):
    """A new texture for target `name`, in its format."""
    return compat.texture(size, _spec()["targets"][name])


def framebuffer(targets, pass_name, defines=None):
    """The framebuffer of a pass for the program variant built with `defines`: a colour slot for
    each of the variant's outputs, in slot order, on the target passes.json names for it (an
    attribute of `targets`), and the pass's depth target."""
    p = _pass(pass_name)
    slots = {"color_slots": tuple(getattr(targets, p["outputs"][var])
                                  for _, var in shader_specs.fragment_outputs(p["program"], defines))}
    if "depth_target" in p:
        slots["depth_slot"] = getattr(targets, p["depth_target"])
    return gpu.types.GPUFrameBuffer(**slots)


@contextlib.contextmanager
def drawing(pass_name, fb):
    """Binds `fb`, clears what the pass clears and sets its state; after the pass, depth test,
    depth writes and blending are back to NONE, False, NONE."""
    p = _pass(pass_name)
    with fb.bind():
        clear = p.get("clear")
        if clear:
            fb.clear(**{k: tuple(v) if k == "color" else v for k, v in clear.items()})
        state = p["state"]
        gpu.state.depth_test_set(state["depth_test"])
        gpu.state.depth_mask_set(state["depth_write"])
        gpu.state.blend_set(state["blend"])
        gpu.state.face_culling_set(state["face_culling"])
        try:
            yield
        finally:
            gpu.state.depth_test_set('NONE')
            gpu.state.depth_mask_set(False)
            gpu.state.blend_set('NONE')


def bind_inputs(shader, pass_name, targets):
    """Each sampler of the pass on the target it reads (attributes of `targets`)."""
    for sampler, target in _pass(pass_name)["inputs"].items():
        shader_lib.set_sampler(shader, sampler, getattr(targets, target))


def float_literal(x):
    """A GLSL float literal of x, as edgelight-render writes it (%.9e: a float32 round-trips)."""
    return f"{float(x):.9e}"


def table_defines(pass_name, info):
    """{define: value} the pass fixes from the table's el_table_info (`info`: field -> value):
    `defines` as integers, `float_defines` as float literals."""
    t = _pass(pass_name)["table"]
    out = {define: int(info[field]) for define, field in t["defines"].items()}
    out.update((define, float_literal(info[field])) for define, field in t.get("float_defines", {}).items())
    return out


def bind_table(shader, pass_name, texture, info):
    """The table's texture on its sampler (its el_table_info is in the program: table_defines)."""
    shader_lib.set_sampler(shader, _pass(pass_name)["table"]["sampler"], texture)
