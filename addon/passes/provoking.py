"""Which vertex of a triangle provides flat varyings on this GPU backend (first or last).

Blender's OpenGL backend uses the last; Vulkan and Metal may use the first. Measured once per
session by drawing one triangle whose vertices carry their own index."""
import gpu
import numpy as np

from .. import compat

_state = {}

_VERT = "void main() { vid = float(gl_VertexID); gl_Position = vec4(pos, 0.0, 1.0); }"
_FRAG = "void main() { out_value = vid; }"


def first_vertex():
    """True when flat varyings come from a triangle's first vertex."""
    if "first" not in _state:
        iface = gpu.types.GPUStageInterfaceInfo("el_provoking_iface")
        iface.flat('FLOAT', "vid")
        info = gpu.types.GPUShaderCreateInfo()
        info.vertex_in(0, 'VEC2', "pos")
        info.vertex_out(iface)
        info.fragment_out(0, 'FLOAT', "out_value")
        info.vertex_source(_VERT)
        info.fragment_source(_FRAG)
        shader = gpu.shader.create_from_info(info)
        from gpu_extras.batch import batch_for_shader
        batch = batch_for_shader(shader, 'TRIS', {"pos": [(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)]})
        tex = compat.texture((2, 2), 'R32F')
        fb = gpu.types.GPUFrameBuffer(color_slots=(tex,))
        buf = gpu.types.Buffer('FLOAT', 4)
        with fb.bind():
            fb.clear(color=(-1.0, -1.0, -1.0, -1.0))
            shader.bind()
            batch.draw(shader)
            fb.read_color(0, 0, 1, 1, 1, 0, 'FLOAT', data=buf)
        _state["first"] = bool(np.asarray(buf)[0] == 0.0)
    return _state["first"]
