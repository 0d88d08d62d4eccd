"""Evaluates GLSL functions of the add-on's shaders on arrays, on the GPU: for tests that pin a
numpy copy of a shader's math (the CPU side of what a shader decides) to the shader's own text.
A throwaway render engine with a GPU context, as EdgeLight's, draws one point per sample into a
row of float pixels; each point's vertex shader calls the function on its inputs."""
import os
import re

import bpy
import numpy as np

import helpers

SHADERS = os.path.join(helpers.ROOT, "shaders")
_TYPES = {1: ('FLOAT', "float"), 2: ('VEC2', "vec2"), 3: ('VEC3', "vec3"), 4: ('VEC4', "vec4")}
_job = {}


def function_source(file_name, name):
    """The text of GLSL function `name` as shaders/`file_name` defines it (its signature through
    its closing brace)."""
    with open(os.path.join(SHADERS, file_name), encoding="utf-8") as f:
        text = f.read()
    found = re.search(r"^[a-z0-9_]+\s+" + re.escape(name) + r"\s*\(", text, re.M)
    if found is None:
        raise KeyError(f"{file_name} defines no function {name}")
    depth, i = 0, text.index("{", found.end())
    for j in range(i, len(text)):
        depth += {"{": 1, "}": -1}.get(text[j], 0)
        if depth == 0:
            return text[found.start():j + 1]
    raise ValueError(f"{name} in {file_name} has no closing brace")


class GlslEvalEngine(bpy.types.RenderEngine):
    bl_idname = "EDGELIGHT_GLSL_EVAL"
    bl_label = "GLSL eval"
    bl_use_gpu_context = True

    def render(self, depsgraph):
        try:
            _job["out"] = _draw(**_job["args"])
        except Exception as e:  # raised again by evaluate(): Blender would only print it
            _job["error"] = e


def _draw(functions, call, inputs, before):
    import gpu
    count = len(next(iter(inputs.values())))
    info = gpu.types.GPUShaderCreateInfo()
    names = list(inputs) + ["el_eval_index"]
    arrays = [np.asarray(a, np.float32).reshape(count, -1) for a in inputs.values()]
    arrays.append(np.arange(count, dtype=np.float32)[:, None])
    fmt = gpu.types.GPUVertFormat()
    for slot, (name, a) in enumerate(zip(names, arrays)):
        info.vertex_in(slot, _TYPES[a.shape[1]][0], name)
        fmt.attr_add(id=name, comp_type='F32', len=a.shape[1], fetch_mode='FLOAT')
    iface = gpu.types.GPUStageInterfaceInfo("el_eval_iface")
    iface.flat('VEC4', "el_eval_result")
    info.vertex_out(iface)
    info.push_constant('FLOAT', "el_eval_count")
    info.fragment_out(0, 'VEC4', "el_eval_out")
    info.vertex_source(functions + "\nvoid main()\n{\n  " + before + "\n  el_eval_result = vec4(" + call + ");\n"
                       "  gl_Position = vec4(2.0 * (el_eval_index + 0.5) / el_eval_count - 1.0, 0.0, 0.0, 1.0);\n}\n")
    info.fragment_source("void main()\n{\n  el_eval_out = el_eval_result;\n}\n")
    shader = gpu.shader.create_from_info(info)
    vbo = gpu.types.GPUVertBuf(fmt, count)
    for name, a in zip(names, arrays):
        vbo.attr_fill(name, a if a.shape[1] > 1 else a[:, 0])
    batch = gpu.types.GPUBatch(type='POINTS', buf=vbo)
    tex = gpu.types.GPUTexture((count, 1), format='RGBA32F')
    fb = gpu.types.GPUFrameBuffer(color_slots=(tex,))
    buf = gpu.types.Buffer('FLOAT', count * 4)
    with fb.bind():
        fb.clear(color=(np.nan, np.nan, np.nan, np.nan))
        gpu.state.point_size_set(1.0)
        shader.bind()
        shader.uniform_float("el_eval_count", float(count))
        batch.draw(shader)
        fb.read_color(0, 0, count, 1, 4, 0, 'FLOAT', data=buf)
    return np.asarray(buf, np.float32).reshape(count, 4)


def evaluate(functions, call, inputs, before=""):
    """(N, 4) float32: vec4(`call`) per sample, `call` a GLSL expression over the names of
    `inputs` ({name: (N,) or (N, k) array, k <= 4}, vertex inputs), what the GLSL statements
    `before` declare (an out parameter's variable, say) and the functions defined by the GLSL
    text `functions`. At most 16384 samples (one row of pixels)."""
    helpers.needs_gpu()
    if not GlslEvalEngine.is_registered:
        bpy.utils.register_class(GlslEvalEngine)
    scene = bpy.data.scenes.new("glsl_eval")
    cam = bpy.data.objects.new("glsl_eval_camera", bpy.data.cameras.new("glsl_eval_camera"))
    scene.collection.objects.link(cam)
    scene.camera = cam
    scene.render.engine = GlslEvalEngine.bl_idname
    scene.render.resolution_x = scene.render.resolution_y = 4
    scene.render.resolution_percentage = 100
    _job.clear()
    _job["args"] = dict(functions=functions, call=call, inputs=inputs, before=before)
    try:
        bpy.ops.render.render(scene=scene.name)
    finally:
        bpy.data.scenes.remove(scene)
    if "error" in _job:
        raise _job["error"]
    return _job["out"]
