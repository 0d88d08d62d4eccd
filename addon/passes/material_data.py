"""The MaterialData uniform block of a material slot (shaders/material_data.json): what does not
fit the push constants, packed by member name. One buffer per distinct value, kept while the
add-on is loaded (a scene has few distinct materials): a draw binds it, nothing is uploaded per
frame."""
import gpu

from ..bridge import shader_specs
from ..extract import node_program

MATERIAL_DATA = shader_specs.Block("material_data.json")
_buffers = {}


def values(shading):
    """The block's members of a materials.Shading: with an image, its node program
    (node_program.Program, run by material_program.glsl)."""
    t = shading.texture
    out = {"emission": (*shading.emission, 0.0),
           "alpha_clip": (t.alpha_threshold if t is not None else 0.5, 0.0, 0.0, 0.0)}
    if t is not None:
        p = t.program
        out["program"] = (float(len(p.code)), t.f0, t.shininess, float(len(p.images)))
        out["outputs"] = (*(float(p.outputs[k]) for k in node_program.PER_PIXEL),
                          float(p.outputs.get(node_program.NORMAL, -1)))
        out["code"], out["args"], out["consts"], out["images"] = p.packed
    return out


def buffer(shading):
    """The GPUUniformBuf of a slot's MaterialData (found by the values it holds: a draw per
    instance and sample asks, so no packing before the lookup)."""
    key = tuple(values(shading).items())
    ubo = _buffers.get(key)
    if ubo is None:
        if len(_buffers) >= 1024:
            _buffers.clear()
        data = MATERIAL_DATA.pack(values(shading))
        ubo = _buffers[key] = gpu.types.GPUUniformBuf(gpu.types.Buffer('FLOAT', data.size, data))
    return ubo
