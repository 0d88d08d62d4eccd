"""The EDGELIGHT RenderEngine: a thin layer that gathers the scene and runs the passes."""
import bpy
import numpy as np

from . import compat, lines, native, scene_sync, viewport
from .passes import frame, toon

# The last final render's buffers, stats and reports, for tests and the benchmark script.
last_render = {}


def load_library():
    """The native library, or None with the reason in `error` (the render then reports it)."""
    try:
        return native.load(), None
    except native.NativeError as e:
        return None, str(e)


def camera_for_render(depsgraph, width, height):
    scene = depsgraph.scene
    cam = scene.camera
    if cam is None:
        return None
    cam = cam.evaluated_get(depsgraph)
    r = scene.render
    proj = cam.calc_matrix_camera(depsgraph, x=width, y=height, scale_x=r.pixel_aspect_x, scale_y=r.pixel_aspect_y)
    world = np.array(cam.matrix_world, dtype=np.float64)
    forward = -world[:3, 2] / np.linalg.norm(world[:3, 2])
    return frame.Camera(view=np.linalg.inv(world), projection=np.array(proj, dtype=np.float64),
                        eye=tuple(world[:3, 3]), view_dir=tuple(forward),
                        orthographic=cam.data.type == 'ORTHO', width=width, height=height)


class EdgeLightRenderEngine(bpy.types.RenderEngine):
    bl_idname = "EDGELIGHT"
    bl_label = "EdgeLight"
    bl_use_gpu_context = True
    bl_use_preview = False

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)  # 4.4+ passes arguments through
        self.viewport = None

    def view_update(self, context, depsgraph):
        lib, error = load_library()
        if lib is None:
            self.report({'ERROR'}, f"EdgeLight: native library unavailable: {error}")
            return
        if self.viewport is None:
            self.viewport = viewport.ViewportState()
            viewport.last_state = self.viewport
        self.viewport.sync(depsgraph, lib)

    def view_draw(self, context, depsgraph):
        if self.viewport is None:
            return  # nothing synced (library missing): Blender shows the cleared view
        self.viewport.draw(self, context, depsgraph)

    def _report(self, level, message):
        last_render.setdefault("messages", []).append((level, message))
        self.report({level}, message)

    def render(self, depsgraph):
        last_render.clear()
        scene = depsgraph.scene
        r = scene.render
        scale = r.resolution_percentage / 100.0
        width, height = max(1, int(r.resolution_x * scale)), max(1, int(r.resolution_y * scale))
        result = self.begin_result(0, 0, width, height)
        try:
            pixels = self._render_pixels(depsgraph, width, height)
            if pixels is not None:
                compat.write_pass(result.layers[0].passes["Combined"], pixels.reshape(-1, 4))
        finally:
            self.end_result(result)

    def _render_pixels(self, depsgraph, width, height):
        lib, error = load_library()
        if lib is None:
            self._report('ERROR', f"EdgeLight: native library unavailable: {error}")
            return None
        camera = camera_for_render(depsgraph, width, height)
        if camera is None:
            self._report('ERROR', "EdgeLight: the scene has no camera")
            return None
        self.update_stats("EdgeLight", "Gathering scene")
        toon.forget_images()  # an image may have been painted since the last render
        settings = depsgraph.scene.edgelight
        line_settings = lines.settings_of(settings)
        data = scene_sync.collect(depsgraph, lib=lib, line_settings=line_settings)
        if len(data.lights) > frame.MAX_LIGHTS:
            data.reports.append(f"{len(data.lights)} lights; the {frame.MAX_LIGHTS} first are used")
        for line in data.reports:
            self._report('WARNING', f"EdgeLight: {line}")
        s = frame.Settings(samples=settings.samples, highlights=settings.highlights,
                           transparent=depsgraph.scene.render.film_transparent, lines=line_settings)
        keep = {}
        reported = len(data.reports)
        pixels, stats = frame.render(data, camera, s, progress=self.update_progress, cancelled=self.test_break, keep=keep)
        for line in data.reports[reported:]:  # what the passes skipped
            self._report('WARNING', f"EdgeLight: {line}")
        last_render.update(keep, pixels=pixels, stats=stats, reports=list(data.reports), camera=camera, scene=data)
        self.update_stats("EdgeLight", f"{stats.objects} objects, {stats.edges_drawn} edges, {stats.lines_drawn} line segments")
        return pixels


def register():
    bpy.utils.register_class(EdgeLightRenderEngine)


def unregister():
    bpy.utils.unregister_class(EdgeLightRenderEngine)
