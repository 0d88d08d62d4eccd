"""One frame, in pass order: per jittered sample the surface pass, on the first (unjittered)
one the edge highlight and line passes, and the composite, accumulated into targets.result.
draw() serves the viewport (nothing read back); render() the final render (drawn, then the image
and the render passes asked for read back). The passes themselves: surface_pass.py,
edge_pass.py, line_pass.py, composite_pass.py; the camera and jitter: camera.py; the uniform
block: frame_data.py; the targets and read-back: targets.py.
"""
import time
from dataclasses import dataclass

import gpu
import numpy as np

from . import (
    batches,
    composite_pass,
    edge_pass,
    frame_data,
    line_pass,
    shadow_pass,
    shadow_plan,
    surface_pass,
    view_lines,
)
from .camera import Camera, jitter, jittered_projection  # noqa: F401 - Camera: engine.py and svg_output.py
from .frame_data import MAX_LIGHTS  # noqa: F401 - engine.py reports past the light limit
from .lighting_inputs import LightingInputs
from .targets import Targets, read, unbind_targets


@dataclass
class Settings:
    samples: int = 8
    highlights: bool = True
    transparent: bool = False
    lines: object = None          # lines.LineSettings, or None: no lines
    ids: bool = False             # the first sample writes ids even without edges or lines (Object Index)
    lines_in_combined: bool = True  # False: the ink goes to the Lines pass only (its own pass)
    shadows: object = None        # shadow_plan.ShadowSettings, or None: no light casts a shadow


@dataclass
class Stats:
    objects: int = 0
    edges_drawn: int = 0
    samples: int = 0
    samples_requested: int = 0
    lines_drawn: int = 0
    meshes_built: int = 0         # meshes whose GPU batches this frame built (render(gpu_cache=...) keeps the rest)


def draw(scene, camera, settings, targets, gpu_meshes, progress=None, cancelled=None, view_batches=None,
         first_sample=None):
    """Draws `scene` from `camera` into targets.result (GPU only, nothing read back).

    view_batches: per instance, the view-dependent line batches for this camera.
    progress(samples done, samples) and cancelled() are called between samples;
    first_sample(), when given, right after the first (unjittered) sample's surface pass."""
    full_screen = batches.fullscreen_batch()
    background = (*scene.ambient, 0.0 if settings.transparent else 1.0)
    stats = Stats(objects=len(scene.instances))
    samples = max(1, int(settings.samples))
    with targets.result_fb.bind():
        targets.result_fb.clear(color=(0.0, 0.0, 0.0, 0.0))
    # Between samples too, a cancel check first waits for the queued draws: the loop queues
    # samples far faster than llvmpipe draws them, and a cancel would land after all of them.
    between = CancelCheck(targets.result, cancelled) if cancelled else None
    culls = surface_pass.cull_modes(scene, camera)
    unlit = settings.lines is not None and settings.lines.whiteout  # nothing reads a shadow
    shadows = shadow_plan.plan(scene, camera, settings.shadows) if settings.shadows and not unlit else None
    shadow_maps = None
    if shadows:
        shadow_maps = shadow_pass.draw(shadows, scene, gpu_meshes, targets.shadow_maps)
    else:
        targets.shadow_maps.release()  # Shadows off: the viewport's atlas goes
    # Unlit (whiteout), nothing reads the world's image; its texture is kept for the next frame.
    lighting = LightingInputs(shadow_maps, None if unlit else targets.environment.texture_of(scene.environment))
    if shadows and shadows.left_out and scene.reports is not None:
        scene.reports.append(f"{shadows.left_out} light{'s' if shadows.left_out != 1 else ''} cast no shadow: "
                             f"the lights before took all {settings.shadows.max_layers} shadow layers")
    for s in range(samples):
        if cancelled and (cancelled() if s == 0 else between()):
            break
        projection = jittered_projection(np.asarray(camera.projection, np.float64), camera.width, camera.height, *jitter(s))
        data = frame_data.pack(camera, projection, scene, shadows, s)
        ubo = gpu.types.GPUUniformBuf(gpu.types.Buffer('FLOAT', data.size, data))
        whiteout = settings.lines is not None and settings.lines.whiteout
        # The first sample's surface also writes ids for the edge and line passes, which run on
        # it alone, and for the Object Index pass.
        surface_pass.draw_surface(targets, scene, gpu_meshes, ubo, whiteout, ids=s == 0 and (
            settings.ids or settings.lines is not None or (settings.highlights and not whiteout)),
            rounded=settings.highlights and not whiteout, culls=culls, lighting=lighting)
        if s == 0 and first_sample:
            first_sample()
        # The edge and line passes run once, on the unjittered first sample: their coverage is
        # filtered across the edge or stroke analytically, so later samples reuse them and
        # only the surface is re-jittered (docs/addon.md).
        if s == 0:
            if settings.highlights and not whiteout:
                edge_pass.draw_highlights(targets, scene, gpu_meshes, ubo, stats, lighting)
            else:
                with targets.highlight_fb.bind():
                    targets.highlight_fb.clear(color=(0.0, 0.0, 0.0, 0.0))
            checkpoint = CancelCheck(targets.lines, cancelled) if cancelled else None
            if line_pass.draw_lines(targets, view_lines.line_instances(scene, gpu_meshes, view_batches) if settings.lines else [],
                                    settings.lines, ubo, stats, checkpoint, rounded=settings.highlights and not whiteout):
                break
        composite_pass.draw_composite(targets, background, full_screen, 1.0 / samples, settings.lines_in_combined,
                                      ubo, lighting)
        stats.samples += 1
        if progress:
            progress(s + 1, samples)
    stats.samples_requested = samples
    return stats


class CancelCheck:
    """Called between batches of a long pass: True once the render is cancelled.

    Queued draws run only when something waits for them, so a check first waits for what was
    queued (a 1-pixel read back): otherwise the cancel would land after every draw. Waiting
    costs a little each time, so while batches finish quickly the check waits only every 2nd,
    4th, ... batch (the gap doubles while a wait is under 0.1 s and halves past 0.5 s)."""

    def __init__(self, texture, cancelled):
        self.texture, self.cancelled = texture, cancelled
        self.gap, self.skipped, self.last = 1, 0, time.monotonic()

    def __call__(self):
        self.skipped += 1
        if self.skipped < self.gap:
            return False
        self.skipped = 0
        read(self.texture, 1, 1)
        now = time.monotonic()
        took, self.last = now - self.last, now
        if took < 0.1:
            self.gap = min(self.gap * 2, 64)
        elif took > 0.5:
            self.gap = max(self.gap // 2, 1)
        return bool(self.cancelled())


# Line segments per batch in a final render: a cancel lands between batches (1000-pixel strokes
# on the toon sample at 960 x 540 take about 10 ms per segment on llvmpipe, so about 1 s each).
LINE_CHUNK = 128


# The partial image is read back at most this often (seconds): a full-resolution float read
# back waits for the GPU to drain and costs about as much as a cheap sample (docs/addon.md).
PREVIEW_INTERVAL = 1.0


# Render passes a final render can read back besides the image (render_passes.py names them).
PASS_BUFFERS = ("surface", "highlight", "lines", "depth", "normal", "ids")


@dataclass(frozen=True)
class LineRecord:
    """What the line pass decided visibility from, for the vector output, which repeats its rule
    (vector_lines.py): the first sample's surface_depth (1 / view depth, 0 = empty) and
    surface_id (instance + 1, face), which later samples overwrite; per instance the
    view-dependent LineSegments; and whether the fillets' outline was drawn with the silhouettes
    on it, so that creases past it are left out (line_pass.draw_lines)."""
    depth: np.ndarray
    ids: np.ndarray
    view_segments: list
    rounded: bool


@dataclass(frozen=True)
class FrameResult:
    """A final render's frame: the image ((h, w, 4) scene-linear float RGBA), its Stats, the
    render-pass buffers asked for (render(passes=...)), the last sample's buffers when kept, and
    the line record when asked for. Read, never filled in by the caller."""
    pixels: np.ndarray
    stats: "Stats"
    passes: dict
    kept: dict = None
    lines: LineRecord = None


def render(scene, camera, settings, progress=None, cancelled=None, keep=False, passes=(), preview=None,
           vector=False, gpu_cache=None):
    """Final render: draws and reads back a FrameResult.

    `keep`: the result keeps the last sample's surface, highlight, depth and lines buffers.
    `passes` names the render-pass buffers to read back (keys of PASS_BUFFERS): "surface" the
    sample mean of the surface, "highlight" and "lines" the premultiplied bands and ink,
    "depth" the first sample's 1 / view depth (0 = empty), "normal" its world normals, "ids" the
    first sample's surface_id (instance + 1, face; drawn only when settings.ids or the edge or
    line passes run). Only what is named is drawn into or read back.
    `preview(pixels)`, when given, receives the image accumulated so far, at most once per
    PREVIEW_INTERVAL seconds of drawing.
    `vector`: the result carries the LineRecord the vector output needs.
    `gpu_cache`: a batches.GpuCache the meshes' batches are taken from and kept in (the engine's,
    for the frames of one render job), else they are built for this render alone."""
    w, h = camera.width, camera.height
    wanted = set(passes or ())
    read_back, line_depth = {}, []
    targets = Targets(w, h, normal="normal" in wanted, surface_sum="surface" in wanted)
    gpu_meshes = {}
    built = gpu_cache.built if gpu_cache is not None else 0
    for inst in scene.instances:
        if id(inst.mesh) not in gpu_meshes:
            gpu_meshes[id(inst.mesh)] = (gpu_cache.mesh(inst.mesh, LINE_CHUNK) if gpu_cache is not None
                                         else batches.GpuMesh(inst.mesh, LINE_CHUNK))
    built = gpu_cache.built - built if gpu_cache is not None else len(gpu_meshes)
    if gpu_cache is not None:
        gpu_cache.end_render()
    whiteout = settings.lines is not None and settings.lines.whiteout
    view_segments = view_lines.view_line_segments(scene, camera, settings.lines,
                                                  rounded=settings.highlights and not whiteout)
    view_batches = line_pass.view_line_batches(view_segments, LINE_CHUNK)
    last_preview = [time.monotonic()]

    def each_sample(done, total):
        if progress:
            progress(done, total)
        if preview and done < total and time.monotonic() - last_preview[0] >= PREVIEW_INTERVAL:
            preview(read(targets.result, w, h) * (total / done))
            last_preview[0] = time.monotonic()

    def first_sample():  # depth and normal of the pixel centres, before later samples jitter them
        for name, texture in (("depth", targets.surface_depth), ("normal", targets.normal)):
            if name in wanted:
                read_back[name] = read(texture, w, h)
        if vector:  # what the line pass reads; later samples overwrite the depth
            line_depth.append(read(targets.surface_depth, w, h, 1)[..., 0])

    stats = draw(scene, camera, settings, targets, gpu_meshes, each_sample, cancelled, view_batches,
                 first_sample if wanted & {"depth", "normal"} or vector else None)
    stats.meshes_built = built
    pixels = read(targets.result, w, h)
    lines = None
    if vector and line_depth:  # only the first sample writes ids: still the line pass's
        lines = LineRecord(line_depth[0], read(targets.surface_id, w, h, 2), view_segments,
                           bool(settings.highlights and not whiteout and settings.lines is not None
                                and "silhouette" in settings.lines.types))
    if "ids" in wanted and stats.samples:  # the index passes' ids (drawn when settings.ids)
        read_back["ids"] = read(targets.surface_id, w, h, 2)
    scale = stats.samples_requested / stats.samples if 0 < stats.samples < stats.samples_requested else 1.0
    pixels *= scale  # cancelled: rescale what was accumulated
    if "surface" in wanted:
        read_back["surface"] = read(targets.surface_sum, w, h) * scale
    for name, texture in (("highlight", targets.highlight), ("lines", targets.lines)):
        if name in wanted:
            read_back[name] = read(texture, w, h)
    kept = None
    if keep:
        kept = {"surface": read(targets.surface_color, w, h), "highlight": read(targets.highlight, w, h),
                "depth": read(targets.surface_depth, w, h), "lines": read(targets.lines, w, h)}
    unbind_targets()
    return FrameResult(pixels, stats, read_back, kept, lines)
