"""Can this Blender draw with the GPU here? Run in its own process by runner.py (a failing GPU
context may abort the process, which must not take the test run with it).

Renders a 4x4 frame with a throwaway engine that has `bl_use_gpu_context`, as EdgeLight does,
clears a float framebuffer inside render() and reads it back. Prints one line:
    EDGELIGHT_GPU_PROBE ok <vendor, renderer, backend>
    EDGELIGHT_GPU_PROBE unavailable <reason>
"""
import os

import bpy

result = {}


class GpuProbeEngine(bpy.types.RenderEngine):
    bl_idname = "EDGELIGHT_GPU_PROBE"
    bl_label = "GPU probe"
    bl_use_gpu_context = True

    def render(self, depsgraph):
        try:
            import gpu
            import numpy as np
            tex = gpu.types.GPUTexture((4, 4), format='RGBA32F')
            fb = gpu.types.GPUFrameBuffer(color_slots=(tex,))
            buf = gpu.types.Buffer('FLOAT', 4)
            with fb.bind():
                fb.clear(color=(0.25, 0.5, 0.75, 1.0))
                fb.read_color(0, 0, 1, 1, 4, 0, 'FLOAT', data=buf)
            got = np.asarray(buf)
            if not np.allclose(got, (0.25, 0.5, 0.75, 1.0)):
                result["error"] = f"a cleared framebuffer reads back {got.tolist()}"
                return
            backend = getattr(gpu.platform, "backend_type_get", lambda: "OPENGL")()
            result["ok"] = f"{gpu.platform.vendor_get()}, {gpu.platform.renderer_get()}, {backend}"
        except Exception as e:  # reported, not raised: Blender would only print it
            result["error"] = f"{type(e).__name__}: {e}"


def probe():
    bpy.utils.register_class(GpuProbeEngine)
    scene = bpy.data.scenes.new("gpu_probe")
    cam = bpy.data.objects.new("gpu_probe_camera", bpy.data.cameras.new("gpu_probe_camera"))
    scene.collection.objects.link(cam)
    scene.camera = cam
    scene.render.engine = GpuProbeEngine.bl_idname
    scene.render.resolution_x = scene.render.resolution_y = 4
    scene.render.resolution_percentage = 100
    try:
        bpy.ops.render.render(scene=scene.name)
    except RuntimeError as e:
        result.setdefault("error", f"render failed: {e}")
    if not result:
        result["error"] = "Blender did not call the engine's render()"
    return ("ok", result["ok"]) if "ok" in result else ("unavailable", result["error"])


status, text = probe()
print(f"EDGELIGHT_GPU_PROBE {status} {text}", flush=True)
os._exit(0)
