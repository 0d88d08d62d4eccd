"""The EDGELIGHT RenderEngine: a thin layer that gathers the scene and runs the passes.

Every failure is loud: whatever goes wrong in render, view_update or view_draw becomes an ERROR
report naming it. An ERROR report from render() is what makes Blender treat the frame as failed:
it is not saved, and `blender -b -f` exits with code 1 (docs/addon.md, "When a render fails").
"""
import math
import time
import traceback

import bpy
import gpu
import numpy as np

from .. import compat
from ..bridge import native
from ..extract import render_cache, scene_sync
from ..linework import lines
from ..passes import batches, camera, frame, shadow_plan, toon
from . import clamp_notes, render_passes, svg_output, viewport

# Tests set `capture = True` to receive the last render's record (pixels, pass buffers, camera,
# scene, reports) in `last_render`, per view layer in `last_render["layers"]`. Otherwise a
# render keeps nothing once it ends.
capture = False
last_render = {}


class RenderRefused(Exception):
    """The frame cannot be rendered as asked; the message says why and what to do."""


def load_library():
    """The native library, or None with the reason in `error` (the render then reports it)."""
    try:
        return native.load(), None
    except native.NativeError as e:
        return None, str(e)


def render_region(r, full_w, full_h):
    """(x, y, width, height) of the pixels Blender asks for: the render region when one is set
    (bounds truncated to whole pixels, as Blender's render pipeline does), else the frame."""
    if not r.use_border:
        return 0, 0, full_w, full_h
    f = np.float32  # single-precision products, as Blender's pipeline computes them
    x0, x1 = int(f(r.border_min_x) * f(full_w)), int(f(r.border_max_x) * f(full_w))
    y0, y1 = int(f(r.border_min_y) * f(full_h)), int(f(r.border_max_y) * f(full_h))
    return x0, y0, max(0, x1 - x0), max(0, y1 - y0)


def drawn_region(region, full_w, full_h, margin):
    """The region grown by `margin` pixels on each side that lies inside the frame (a region's
    edge on the frame's edge stays), and where the region lies in it: (x, y, w, h), (dx, dy).
    Drawn past its edges, a region's pixels are the full frame's: ink whose centre lies outside
    still reaches in, and the line pass judges a stroke's visibility from the 3 x 3 pixels round
    its centre (docs/lines.md), which the region's edge would cut."""
    x0, y0, w, h = region
    ax, ay = max(0, x0 - margin), max(0, y0 - margin)
    bx, by = min(full_w, x0 + w + margin), min(full_h, y0 + h + margin)
    return (ax, ay, bx - ax, by - ay), (x0 - ax, y0 - ay)


class Crop:
    """The region's pixels (w x h at dx, dy) of an image drawn over its drawn_region: (h, w, ...)
    arrays, rows bottom-up."""

    def __init__(self, dx, dy, w, h):
        self.dx, self.dy, self.w, self.h = dx, dy, w, h

    def __call__(self, image):
        return np.ascontiguousarray(image[self.dy:self.dy + self.h, self.dx:self.dx + self.w])


# The most a render region is drawn past its inner edges, in pixels.
MOST_MARGIN = 128


def region_margin(line_settings):
    """Pixels drawn past a render region's inner edges: half the widest ink in pixels and its
    3 x 3 window, at least a few pixels, at most MOST_MARGIN; ink of a width in scene units,
    whose pixels grow near the camera, takes the most."""
    widest = max((MOST_MARGIN if st.scene_units else max(st.width, st.min_pixels) / 2.0
                  for _, st in line_settings.styles), default=0.0) if line_settings is not None else 0.0
    return int(min(MOST_MARGIN, math.ceil(widest) + 4))


def region_projection(projection, full_w, full_h, region):
    """The full frame's projection restricted to a region of it: the region's pixels keep their
    place and size in the frame (same pixels per unit), only the window moves."""
    x0, y0, w, h = region
    t = np.eye(4)
    t[0, 0], t[0, 3] = full_w / w, (full_w - 2.0 * x0) / w - 1.0
    t[1, 1], t[1, 3] = full_h / h, (full_h - 2.0 * y0) / h - 1.0
    return t @ projection


def camera_world(cam, matrix=None):
    """The camera's matrix (or `matrix`, a view's of it) without its scale, as Blender's own
    engines use it; refuses a transform that has no orientation (scaled to zero, or NaN)."""
    world = np.array(cam.matrix_world if matrix is None else matrix, dtype=np.float64)
    axes = world[:3, :3]
    norms = np.linalg.norm(axes, axis=0)
    if not np.all(np.isfinite(world)) or norms.min() < 1e-12:
        raise RenderRefused(f"camera '{cam.name}' has a singular transform (scale "
                            f"{tuple(round(s, 6) for s in cam.matrix_world.to_scale())}); give it a non-zero scale")
    world[:3, :3] = axes / norms
    if abs(np.linalg.det(world[:3, :3])) < 1e-6:
        raise RenderRefused(f"camera '{cam.name}' has a degenerate transform (its axes are parallel)")
    return world


def stereo_shift(projection, shift, full_w, full_h, r, cam):
    """`projection` with its window moved by `shift` (in Blender's shift units: the sensor-fit
    side of the frame) more: a stereo view's off-axis shift, beyond the camera's own that
    calc_matrix_camera applied. Perspective: the window's centre column; orthographic: its offset."""
    if shift == 0.0:
        return projection
    w, h = full_w * r.pixel_aspect_x, full_h * r.pixel_aspect_y
    fit = {'HORIZONTAL': w, 'VERTICAL': h}.get(cam.data.sensor_fit, max(w, h))
    dx = 2.0 * shift * fit / w
    p = projection.copy()
    if cam.data.type == 'ORTHO':
        p[0, 3] -= dx
    else:
        p[0, 2] += dx
    return p


def camera_for_render(depsgraph, full_w, full_h, region, view=None):
    """The camera of the frame's `region`; `view`: (world matrix, shift_x) of a multiview
    render's view (RenderEngine.camera_model_matrix, camera_shift_x), else the camera's own."""
    scene = depsgraph.scene
    if scene.camera is None:
        raise RenderRefused("the scene has no camera")
    cam = scene.camera.evaluated_get(depsgraph)
    if cam.type != 'CAMERA':
        raise RenderRefused(f"the scene's camera '{cam.name}' is not a camera object")
    if cam.data.type == 'PANO':
        raise RenderRefused(f"camera '{cam.name}' is panoramic; EdgeLight renders perspective and "
                            "orthographic cameras only")
    r = scene.render
    world = camera_world(cam, None if view is None else view[0])
    proj = np.array(cam.calc_matrix_camera(depsgraph, x=full_w, y=full_h, scale_x=r.pixel_aspect_x,
                                           scale_y=r.pixel_aspect_y), dtype=np.float64)
    if view is not None:
        proj = stereo_shift(proj, view[1] - cam.data.shift_x, full_w, full_h, r, cam)
    x, y, w, h = region
    return camera.from_view(np.linalg.inv(world), region_projection(proj, full_w, full_h, region),
                            cam.data.type == 'ORTHO', w, h, frame_projection=proj, pixel_origin=(x, y))


def render_views(r):
    """The views a render draws: [None] (the camera's one) without multiview, else the names of
    the views it uses (Stereo 3D: left and right), each its own camera and result."""
    if not r.use_multiview:
        return [None]
    names = [v.name for v in r.views if v.use]
    if r.views_format == 'STEREO_3D':
        names = [n for n in names if n in ("left", "right")]
    return names or [None]


def check_size(w, h):
    """Refuses a frame larger than the GPU's textures (a clear message instead of a texture error)."""
    limit = gpu.capabilities.max_texture_size_get()
    if w > limit or h > limit:
        raise RenderRefused(f"the frame is {w} x {h} pixels, and this GPU's textures go up to {limit} "
                            f"x {limit}: lower the resolution, or render it in parts with Render Region")


class EdgeLightRenderEngine(bpy.types.RenderEngine):
    bl_idname = "EDGELIGHT"
    bl_label = "EdgeLight"
    bl_use_gpu_context = True
    bl_use_preview = False

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)  # 4.4+ passes arguments through
        self.viewport = None
        self._viewport_errors = set()
        self._gpu_caches = {}  # view layer -> passes.batches.GpuCache (_gpu_cache)
        self._last_extracts = {}  # view layer -> its last frame's SceneData.extracts (_render_pixels)

    # ---- viewport -------------------------------------------------------------------------
    def view_update(self, context, depsgraph):
        try:
            lib, error = load_library()
            if lib is None:
                self._viewport_error(f"native library unavailable: {error}")
                return
            if self.viewport is None:
                self.viewport = viewport.ViewportState()
                if capture:
                    viewport.last_state = self.viewport
            self.viewport.sync(depsgraph, lib, context.space_data)
        except Exception as e:  # noqa: BLE001 - any failure must reach the artist
            traceback.print_exc()
            self._viewport_error(f"viewport update failed: {type(e).__name__}: {e}")

    def view_draw(self, context, depsgraph):
        if self.viewport is None:
            return  # nothing synced (library missing): Blender shows the cleared view
        try:
            self.viewport.draw(self, context, depsgraph)
        except Exception as e:  # noqa: BLE001
            traceback.print_exc()
            self._viewport_error(f"viewport draw failed: {type(e).__name__}: {e}")

    def _viewport_error(self, message):
        """Once per distinct message: view_draw runs on every redraw."""
        if message not in self._viewport_errors:
            self._viewport_errors.add(message)
            self.report({'ERROR'}, f"EdgeLight: {message}")
        self.update_stats("EdgeLight", f"Error: {message}")

    # ---- final render -----------------------------------------------------------------------
    def update_render_passes(self, scene=None, renderlayer=None):
        """The passes a view layer's render result holds (View Layer -> Passes, the compositor's
        Render Layers node): Blender asks before a render and when a pass setting changes."""
        render_passes.register_passes(self, scene, renderlayer)

    def _report(self, level, message, record):
        record.setdefault("messages", []).append((level, message))
        self.report({level}, message)
        if level == 'ERROR':
            # Where the artist looks after F12: the render window's stats line (the result's
            # error, as Cycles sets it) and, while the job ends, the engine's stats text. The
            # report itself reaches the Info editor, the status bar and the render window's popup.
            self.error_set(message)
            self.update_stats("", message)

    def render(self, depsgraph):
        layer = depsgraph.view_layer.name
        record = {"layer": layer}
        if not capture:
            last_render.clear()  # a render keeps nothing once it ends
        else:
            last_render["rendering"] = record  # live while it renders: the UI test reads progress
        try:
            for view in render_views(depsgraph.scene.render):
                self._render_layer(depsgraph, layer, record, view)
        except RenderRefused as e:
            self._report('ERROR', f"EdgeLight: {e}", record)
        except Exception as e:  # noqa: BLE001 - a silently empty frame would be saved as if it had worked
            traceback.print_exc()
            self._report('ERROR', f"EdgeLight: rendering view layer '{layer}' failed: {type(e).__name__}: {e}", record)
        finally:
            if capture:  # the test clears last_render before a render; its layers accumulate
                layers = last_render.get("layers", {})
                layers[layer] = record
                last_render.clear()
                last_render.update(record, layers=layers)

    def _view(self, depsgraph, view):
        """(world matrix, shift_x) of multiview view `view` (None: the camera's own)."""
        if view is None or depsgraph.scene.camera is None:
            return None
        self.active_view_set(view)
        cam = depsgraph.scene.camera.evaluated_get(depsgraph)
        return (self.camera_model_matrix(cam, use_spherical_stereo=False),
                self.camera_shift_x(cam, use_spherical_stereo=False))

    def _render_layer(self, depsgraph, layer, record, view=None):
        """One view layer's frame, or of a multiview render one `view` of it (its name)."""
        scene = depsgraph.scene
        full_w, full_h = self.resolution_x, self.resolution_y  # the resolution percentage applied
        region = render_region(scene.render, full_w, full_h)
        if region[2] <= 0 or region[3] <= 0:
            raise RenderRefused(f"the render region is empty ({region[2]} x {region[3]} pixels)")
        check_size(region[2], region[3])
        drawn, at = drawn_region(region, full_w, full_h, region_margin(lines.settings_of(scene.edgelight)))
        if max(drawn[2], drawn[3]) > gpu.capabilities.max_texture_size_get():
            drawn, at = region, (0, 0)  # a region that just fits the GPU's textures: drawn without a margin
        eye = self._view(depsgraph, view)
        record["view"] = view
        camera = camera_for_render(depsgraph, full_w, full_h, drawn, eye)
        crop = Crop(at[0], at[1], region[2], region[3])
        record["camera"] = camera_for_render(depsgraph, full_w, full_h, region, eye)  # the pixels Blender gets
        lib, error = load_library()
        if lib is None:
            raise RenderRefused(f"native library unavailable: {error}")
        result = self.begin_result(0, 0, region[2], region[3], layer=layer, view=view or "")
        if view is not None and capture:
            record.setdefault("views", {})[view] = record_view = {}
        else:
            record_view = None
        try:
            size = (result.resolution_x, result.resolution_y)
            if size != (region[2], region[3]):
                raise RenderRefused(f"Blender asked for {size[0]} x {size[1]} pixels where EdgeLight "
                                    f"computed a region of {region[2]} x {region[3]}")
            record["result_layer"] = result.layers[0].name
            view_layer = depsgraph.view_layer
            buffers = render_passes.buffers_wanted(view_layer)
            combined = result.layers[0].passes["Combined"]

            def preview(pixels):  # the partial image in the Image Editor while samples accumulate
                compat.write_pass(combined, crop(pixels).reshape(-1, 4))
                self.update_result(result)
                if capture:
                    record["previews"] = record.get("previews", 0) + 1

            pixels = self._render_pixels(depsgraph, camera, crop, lib, record, buffers, preview)
            compat.write_pass(combined, pixels.reshape(-1, 4))
            if record_view is not None:
                record_view.update(pixels=pixels, camera=record["camera"])
            written = {} if capture else None
            render_passes.write(result.layers[0], view_layer, buffers, written)
            if capture:
                record["passes"] = written
        finally:
            self.end_result(result)

    def _gpu_cache(self, depsgraph):
        """The view layer's GPU batches kept from this engine's last render of it. Blender keeps
        a GPU engine, and the render thread's GPU context its batches live in, for one render
        job (every frame of an animation, every view layer) and frees both when the job ends,
        Persistent Data or not (RE_engine_use_persistent_data): so a frame whose meshes did not
        change builds no batch, and what is held is what the layer's last frame drew."""
        return self._gpu_caches.setdefault(depsgraph.view_layer.name, batches.GpuCache())

    def _render_pixels(self, depsgraph, camera, crop, lib, record, buffers, preview):
        """The region's pixels, drawn over `camera`'s (the region with its margin) and cropped;
        `buffers` receives the render passes' buffers, cropped."""
        self.update_stats("EdgeLight", "Gathering scene")
        toon.forget_images()  # an image may have been painted since the last render
        settings = depsgraph.scene.edgelight
        line_settings = lines.settings_of(settings)
        # Extractions are kept for the next render (render_cache.py): a frame of an animation
        # whose meshes did not change reuses them.
        scene = depsgraph.scene
        render_cache.EXTRACTS.begin(scene.name, (scene.frame_current, scene.frame_subframe))
        # Blender keeps the engine and its depsgraph for every frame of a job: a frame where only
        # objects, cameras and lights moved draws the last frame's extractions, reading no mesh.
        # The view layers share that depsgraph, whose updates each layer's render clears: one
        # layer sees what changed since the layer before it, so anything more than a move
        # drops what every layer kept.
        layer = depsgraph.view_layer.name
        if not scene_sync.only_moved(depsgraph):
            self._last_extracts.clear()
        kept = self._last_extracts.get(layer)
        data = scene_sync.collect(depsgraph, lib=lib, line_settings=line_settings, cache=render_cache.EXTRACTS,
                                  kept=kept)
        self._last_extracts[layer] = data.extracts
        clamp_notes.NOTES.rendered(layer, (inst.mesh for inst in data.instances))  # the material panel's note
        if len(data.lights) > frame.MAX_LIGHTS:
            data.reports.append(f"{len(data.lights)} lights; the {frame.MAX_LIGHTS} first are used")
        for line in dict.fromkeys(data.reports):  # once each: geometries share materials
            self._report('WARNING', f"EdgeLight: {line}", record)
        if data.failed and not data.instances:  # the frame would be empty, as if nothing were there
            names = ", ".join(f"'{n}'" for n in data.failed[:6]) + (" and more" if len(data.failed) > 6 else "")
            raise RenderRefused(f"nothing could be drawn: {len(data.failed)} object"
                                f"{'s' if len(data.failed) != 1 else ''} failed ({names}; see the warnings)")
        s = frame.Settings(samples=settings.samples, highlights=settings.highlights,
                           transparent=depsgraph.scene.render.film_transparent, lines=line_settings,
                           ids="ids" in buffers,
                           lines_in_combined=render_passes.lines_in_combined(depsgraph.view_layer),
                           shadows=shadow_plan.settings_of(settings))
        reported = len(data.reports)

        def progress(done, total):
            self.update_progress(done / total)
            self.update_stats("EdgeLight", f"Sample {done}/{total}")
            if capture:
                record.setdefault("progress", []).append((done, total, time.monotonic()))

        svg = line_settings is not None and svg_output.wanted(depsgraph.scene, depsgraph.view_layer.name)
        out = frame.render(data, camera, s, progress=progress, cancelled=self.test_break, keep=capture,
                           passes=tuple(buffers), preview=preview, vector=svg, gpu_cache=self._gpu_cache(depsgraph))
        stats, vector = out.stats, out.lines
        buffers.update(out.passes)
        # Which instance and face cover each pixel -> its object's and its material's pass_index.
        render_passes.from_ids(buffers, depsgraph.view_layer, data.instances)
        pixels = crop(out.pixels)
        for name, buffer in buffers.items():
            if buffer is not None:
                buffers[name] = crop(buffer)
        if depsgraph.view_layer.use_pass_mist and buffers.get("depth") is not None:
            world = depsgraph.scene.world
            buffers["mist"] = render_passes.mist(buffers["depth"], record["camera"],
                                                 world.mist_settings if world else render_passes.DEFAULT_MIST)
        kept = {name: crop(buffer) for name, buffer in (out.kept or {}).items()}
        if vector is not None and not self.test_break():  # the lines as SVG beside the frame
            view = (crop.dx, camera.height - crop.dy - crop.h, crop.w, crop.h)
            try:
                # A still (F12, render(write_still=True)) is saved without a frame number, an
                # animation's frames (-a, -f) with one: the SVG takes the name its image takes.
                svg_output.write_render(depsgraph.scene, record["layer"], data, camera, line_settings, vector, record,
                                        view, still=not self.is_animation, eye=record.get("view"))
            except OSError as e:  # the SVG's own failure: the frame and its image still go out
                self._report('WARNING', f"EdgeLight: the SVG of view layer '{record['layer']}' could not be written: "
                                        f"{e.strerror or e} ({e.filename})", record)
        for line in data.reports[reported:]:  # what the passes skipped
            self._report('WARNING', f"EdgeLight: {line}", record)
        if stats.samples == 0 and not self.test_break():
            raise RenderRefused("no sample was drawn")
        if capture:
            record.update(kept, pixels=pixels, stats=stats, reports=list(data.reports), scene=data)
        self.update_stats("EdgeLight", f"{stats.objects} objects, {stats.edges_drawn} edges, {stats.lines_drawn} line segments")
        return pixels


@bpy.app.handlers.persistent
def _forget_extractions(*_args):
    """Another file: nothing of the last one's meshes is kept (render_cache.py), nor its
    materials' radius clamp notes (clamp_notes.py)."""
    render_cache.EXTRACTS.clear()
    clamp_notes.NOTES.clear()


@bpy.app.handlers.persistent
def _render_job_ended(scene=None, *_args):
    """A render job (a still, or every frame of an animation) ended: what its last frame used is
    kept for the next job only with Persistent Data on (shown in EdgeLight's render panel; Cycles
    has it under Performance): it holds memory while nothing renders."""
    render_cache.EXTRACTS.end_job(keep=getattr(getattr(scene, "render", None), "use_persistent_data", False))


_HANDLERS = (("load_post", _forget_extractions), ("render_complete", _render_job_ended),
             ("render_cancel", _render_job_ended))


def register():
    bpy.utils.register_class(EdgeLightRenderEngine)
    for name, handler in _HANDLERS:
        getattr(bpy.app.handlers, name).append(handler)


def unregister():
    for name, handler in _HANDLERS:
        handlers = getattr(bpy.app.handlers, name)
        while handler in handlers:
            handlers.remove(handler)
    render_cache.EXTRACTS.clear()
    bpy.utils.unregister_class(EdgeLightRenderEngine)
