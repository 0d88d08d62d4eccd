"""One frame: surface -> edge highlight -> composite, accumulated over jittered samples.

The same code serves the final render and (later) the viewport; only the camera, the size and
where the result goes differ.
"""
import os
import time
from dataclasses import dataclass

import gpu
import numpy as np

from .. import compat, native
from .. import lines as ink
from . import batches, line_pass, pass_state, shader_lib, shader_specs, table, toon

# The FrameData block (shaders/frame_data.json): its layout, the light limit and the surface
# program's modes are read from the one description the shaders are built from.
FRAME_DATA = shader_specs.Block("frame_data.json")
MAX_LIGHTS = FRAME_DATA.defines["EL_MAX_LIGHTS"]
SURFACE_MODES = shader_specs.load("surface_modes.json")["enums"]["EL_SURFACE_MODE"]

# How the edge pass shades bands (shaders/edge_band.glsl). Not a user setting: the ground-truth
# benchmark (bench/ground_truth.py) sets EDGELIGHT_EDGE_METHOD to render the earlier methods with
# the same shaders. Unset or unknown: "partial", the add-on's method.
EDGE_METHODS = {"partial": 0.0, "whole": 1.0, "paper": 2.0, "quadrature": 3.0}


def edge_method():
    return EDGE_METHODS.get(os.environ.get("EDGELIGHT_EDGE_METHOD", "partial"), 0.0)


def edge_floor():
    """EDGELIGHT_EDGE_FLOOR=1: the edge pass's quads with a fragment shader that does next to
    nothing (shaders/edge_highlight.frag.glsl), for the viewport benchmark's floor. Not a user
    setting: it draws no highlights."""
    return os.environ.get("EDGELIGHT_EDGE_FLOOR") == "1"


@dataclass
class Camera:
    view: np.ndarray          # world -> view, 4x4 row-major
    projection: np.ndarray    # view -> clip, 4x4 row-major
    eye: tuple
    view_dir: tuple           # direction the camera looks along
    orthographic: bool
    width: int
    height: int

    @property
    def px_per_unit(self):
        """Pixels per world unit at distance 1 (perspective) or anywhere (orthographic)."""
        return float(self.projection[0, 0]) * self.width / 2.0


def halton(i, base):
    f, r = 1.0, 0.0
    while i > 0:
        f /= base
        r += f * (i % base)
        i //= base
    return r


def jitter(sample):
    """Sub-pixel offset of a sample; sample 0 is the pixel centre, so one sample is exact."""
    if sample == 0:
        return 0.0, 0.0
    return halton(sample, 2) - 0.5, halton(sample, 3) - 0.5


def jittered_projection(projection, width, height, dx, dy):
    t = np.eye(4, dtype=np.float64)
    t[0, 3] = 2.0 * dx / width
    t[1, 3] = 2.0 * dy / height
    return t @ projection


def _mat(m):
    """numpy row-major 4x4 -> std140 column-major floats."""
    return np.asarray(m, dtype=np.float32).T.reshape(-1)


def frame_data(camera, projection, scene):
    """The FrameData block's floats (members: shaders/frame_data.json)."""
    lights = scene.lights[:MAX_LIGHTS]
    return FRAME_DATA.pack({
        "view": _mat(camera.view),
        "projection": _mat(projection),
        "eye": (*camera.eye, 0.0 if camera.orthographic else 1.0),
        "view_dir": (*camera.view_dir, 0.0),
        "viewport": (camera.width, camera.height, 1.0 / camera.width, 1.0 / camera.height),
        "ambient": (*scene.ambient, 1.0),
        "camera": (camera.px_per_unit, len(lights), 0.0, 0.0),
        "light_color": [(*light.color, light.kind) for light in lights],
        "light_position": [(*light.position, 0.0) for light in lights],
        "light_direction": [(*light.direction, light.spot_cos) for light in lights],
        "light_spot": [(light.spot_blend, 0.0, 0.0, 0.0) for light in lights],
    })


class Targets:
    """Float render targets of one size (shaders/passes.json: one attribute per target), reused
    across samples and frames. surface_depth holds 1 / view depth (0 = empty); surface_id which
    instance and face covers each pixel (first sample, for the edge and line passes).

    normal / surface_sum: extra attachments for the Normal and Surface render passes, made only
    when a render asks for them (their programs are variants that write them, so a render
    without those passes pays nothing)."""

    def __init__(self, width, height, normal=False, surface_sum=False):
        self.size = (width, height)
        wanted = {"normal": normal, "surface_sum": surface_sum}
        for name in pass_state.target_names():
            setattr(self, name, pass_state.texture(name, self.size) if wanted.get(name, True) else None)
        self.surface_fb = pass_state.framebuffer(self, "surface", surface_outputs(self, ids=False))
        self.surface_ids_fb = pass_state.framebuffer(self, "surface", surface_outputs(self, ids=True))
        self.highlight_fb = pass_state.framebuffer(self, "edge_highlight")
        self.result_fb = pass_state.framebuffer(self, "composite", composite_outputs(self))
        self.line_fb = gpu.types.GPUFrameBuffer(depth_slot=self.line_depth, color_slots=(self.lines,))
        self.lines_empty = False  # the line target holds no stroke (cleared, none drawn since)


def surface_outputs(targets, ids):
    """Defines of the surface variant that also writes the Normal pass (when `targets` has its
    target) and which instance and face covers each pixel (`ids`)."""
    return {**({"EL_NORMAL_PASS": 1} if targets.normal is not None else {}), **({"EL_SURFACE_IDS": 1} if ids else {})}


def composite_outputs(targets):
    """Defines of the composite variant that also writes the Surface pass when asked for."""
    return {"EL_SURFACE_PASS": 1} if targets.surface_sum is not None else {}


@dataclass
class Settings:
    samples: int = 8
    highlights: bool = True
    transparent: bool = False
    lines: object = None          # lines.LineSettings, or None: no lines


@dataclass
class Stats:
    objects: int = 0
    edges_drawn: int = 0
    samples: int = 0
    samples_requested: int = 0
    lines_drawn: int = 0


def _shading_uniforms(shader, s):
    shader_lib.set_uniform(shader, "base_color", (*s.base_color, s.alpha))
    shader_lib.set_uniform(shader, "spec_color", (*s.spec_color, s.shininess))


def _surface_mode(s, whiteout):
    """The surface program's shading mode (shaders/surface_modes.json): the material's
    (toon.mode: materials.py), or WHITEOUT."""
    return SURFACE_MODES["WHITEOUT"] if whiteout else int(s.toon.mode)


def _toon_uniforms(shader, s, mode):
    """The toon parameters, and the texture of a ramp or X-Toon mode."""
    t = s.toon
    shader_lib.set_uniform(shader, "toon", (float(mode), t.near, t.far, (1.0 if t.smooth else 0.0) + (2.0 if t.orientation else 0.0)))
    if mode == SURFACE_MODES["RAMP"]:
        shader_lib.set_sampler(shader, "toon_ramp", toon.ramp_texture(t))
    elif mode == SURFACE_MODES["XTOON"]:
        shader_lib.set_sampler(shader, "toon_map", toon.map_texture(t, s.base_color))


def slot_first_ids(extract):
    """slot -> the surface id of its batch's first triangle (scene_sync: ids follow slot order)."""
    out, first = {}, 1
    for slot, tris in extract.slot_triangles.items():
        out[slot] = first
        first += len(tris)
    return out


def draw_surface(targets, scene, gpu_meshes, ubo, whiteout=False, ids=False):
    """One program per shading mode in use (EL_SURFACE_MODE is fixed when it is built: a uniform
    branch would make every fragment pay for every mode on llvmpipe). With `ids`, the variant
    that also writes which instance and face covers each pixel (the line pass's visibility,
    docs/lines.md)."""
    draws, firsts = {}, {}
    for index, inst in enumerate(scene.instances):
        gm = gpu_meshes[id(inst.mesh)]
        if ids and id(gm.extract) not in firsts:  # once per geometry, not per instance
            firsts[id(gm.extract)] = slot_first_ids(gm.extract)
        first = firsts.get(id(gm.extract), {})
        for slot, batch in gm.surface.items():
            s = gm.extract.slot_shading[slot]
            draws.setdefault(_surface_mode(s, whiteout), []).append(
                (inst.matrix, s, batch, (float(index + 1), float(first.get(slot, 0)))))
    outputs = surface_outputs(targets, ids)
    with pass_state.drawing("surface", targets.surface_ids_fb if ids else targets.surface_fb):
        for mode, items in sorted(draws.items()):
            shader = shader_lib.get("surface", {"EL_SURFACE_MODE": mode, **outputs})
            shader.bind()
            shader.uniform_block("frame", ubo)
            for matrix, s, batch, surface_ids in items:
                shader_lib.set_uniform(shader, "model", _mat(matrix))
                shader_lib.set_uniform(shader, "surface_ids", surface_ids)
                _shading_uniforms(shader, s)
                _toon_uniforms(shader, s, mode)
                batch.draw(shader)


def draw_highlights(targets, scene, gpu_meshes, ubo, stats):
    tex, info = table.table()
    # The table layout and the edge method are fixed in the program (highlight_arc.glsl).
    defines = {**pass_state.table_defines("edge_highlight", info), "EL_EDGE_METHOD": int(edge_method())}
    if edge_floor():
        defines["EL_EDGE_FLOOR"] = 1
    defines["EL_EDGE_IDS"] = 1  # the surface pass wrote ids: visibility by face (docs/lines.md)
    shader = shader_lib.get("edge_highlight", defines)
    with pass_state.drawing("edge_highlight", targets.highlight_fb):
        shader.bind()
        shader.uniform_block("frame", ubo)
        pass_state.bind_table(shader, "edge_highlight", tex, info)
        pass_state.bind_inputs(shader, "edge_highlight", targets)
        for index, inst in enumerate(scene.instances):
            gm = gpu_meshes[id(inst.mesh)]
            if not gm.edges:
                continue
            shader_lib.set_uniform(shader, "model", _mat(inst.matrix))
            shader_lib.set_uniform(shader, "instance_id", float(index + 1))
            for slot, batch in gm.edges.items():
                s = gm.extract.slot_shading[slot]
                _shading_uniforms(shader, s)
                shader_lib.set_uniform(shader, "tint", (*s.tint, s.K))
                batch.draw(shader)
                stats.edges_drawn += len(gm.extract.edges[slot])


def draw_composite(targets, background, full_screen, weight):
    """Adds weight x the composited sample to the result (cleared by the caller), and the
    surface alone to surface_sum when the Surface pass is asked for."""
    shader = shader_lib.get("composite", composite_outputs(targets))
    with pass_state.drawing("composite", targets.result_fb):
        shader.bind()
        pass_state.bind_inputs(shader, "composite", targets)
        shader_lib.set_uniform(shader, "background", background)
        shader_lib.set_uniform(shader, "weight", weight)
        full_screen.draw(shader)


def read(texture, width, height, channels=4):
    buf = gpu.types.Buffer('FLOAT', width * height * channels)
    fb = gpu.types.GPUFrameBuffer(color_slots=(texture,))
    with fb.bind():
        fb.read_color(0, 0, width, height, channels, 0, 'FLOAT', data=buf)
    return np.asarray(buf, dtype=np.float32).reshape(height, width, channels)


def line_instances(scene, gpu_meshes, view_batches):
    """[(matrix, {type: (batch, count)}, instance id)]: each instance's static line batches (shared by the
    instances of a mesh) and its own view-dependent ones (view_batches[i] for instance i)."""
    out = []
    for i, inst in enumerate(scene.instances):
        batches_of = dict(gpu_meshes[id(inst.mesh)].lines)
        if view_batches and i < len(view_batches) and view_batches[i]:
            batches_of.update(view_batches[i])
        out.append((inst.matrix, batches_of, i + 1))  # i + 1: the instance's surface id
    return out


def view_line_segments(scene, camera, line_settings, counters=None):
    """Per instance, type -> LineSegments of the view-dependent types (native view calls). An
    instance the library refuses (a singular transform, say) gets none, and a report."""
    out, seen = [], {}
    for inst in scene.instances:
        index = seen[id(inst.mesh)] = seen.get(id(inst.mesh), -1) + 1
        try:
            out.append(ink.view_lines(inst.mesh, index, inst.matrix, camera, line_settings, counters))
        except native.NativeError as e:
            note = f"{inst.mesh.name}: no silhouettes or contours ({e.message})"
            if note not in scene.reports:
                scene.reports.append(note)
            out.append({})
    return out


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
    for s in range(samples):
        if cancelled and (cancelled() if s == 0 else between()):
            break
        projection = jittered_projection(np.asarray(camera.projection, np.float64), camera.width, camera.height, *jitter(s))
        data = frame_data(camera, projection, scene)
        ubo = gpu.types.GPUUniformBuf(gpu.types.Buffer('FLOAT', data.size, data))
        whiteout = settings.lines is not None and settings.lines.whiteout
        # The first sample's surface also writes ids for the edge and line passes, which run on
        # it alone.
        draw_surface(targets, scene, gpu_meshes, ubo, whiteout,
                     ids=s == 0 and (settings.lines is not None or (settings.highlights and not whiteout)))
        if s == 0 and first_sample:
            first_sample()
        # The edge and line passes run once, on the unjittered first sample: their coverage is
        # box-filtered across the edge or stroke analytically, so later samples reuse them and
        # only the surface is re-jittered (docs/addon.md).
        if s == 0:
            if settings.highlights and not whiteout:
                draw_highlights(targets, scene, gpu_meshes, ubo, stats)
            else:
                with targets.highlight_fb.bind():
                    targets.highlight_fb.clear(color=(0.0, 0.0, 0.0, 0.0))
            checkpoint = CancelCheck(targets.lines, cancelled) if cancelled else None
            if line_pass.draw_lines(targets, line_instances(scene, gpu_meshes, view_batches) if settings.lines else [],
                                    settings.lines, ubo, stats, checkpoint):
                break
        draw_composite(targets, background, full_screen, 1.0 / samples)
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
PASS_BUFFERS = ("surface", "highlight", "lines", "depth", "normal")


def render(scene, camera, settings, progress=None, cancelled=None, keep=None, passes=None, preview=None,
           vector=None):
    """Final render: draws and reads back ((h, w, 4) scene-linear float RGBA, Stats).

    `keep`, when a dict, receives the last sample's surface, highlight and depth buffers.
    `passes`, when a dict, names the render-pass buffers to read back (keys of PASS_BUFFERS) and
    receives them: "surface" the sample mean of the surface, "highlight" and "lines" the
    premultiplied bands and ink, "depth" the first sample's 1 / view depth (0 = empty), "normal"
    its world normals. Only what is named is drawn into or read back.
    `preview(pixels)`, when given, receives the image accumulated so far, at most once per
    PREVIEW_INTERVAL seconds of drawing.
    `vector`, when a dict, receives what the line pass decided visibility from (the vector
    output repeats its rule): "depth" and "ids" (the first sample's surface_depth and
    surface_id) and "view_segments" (per instance, the view-dependent LineSegments)."""
    w, h = camera.width, camera.height
    wanted = set(passes or ())
    targets = Targets(w, h, normal="normal" in wanted, surface_sum="surface" in wanted)
    gpu_meshes = {}
    for inst in scene.instances:
        if id(inst.mesh) not in gpu_meshes:
            gpu_meshes[id(inst.mesh)] = batches.GpuMesh(inst.mesh, LINE_CHUNK)
    view_segments = view_line_segments(scene, camera, settings.lines)
    view_batches = [line_pass.line_batches(segs, LINE_CHUNK) for segs in view_segments]
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
                passes[name] = read(texture, w, h)
        if vector is not None:  # what the line pass reads; later samples overwrite the depth
            vector.update(depth=read(targets.surface_depth, w, h, 1)[..., 0], view_segments=view_segments)

    stats = draw(scene, camera, settings, targets, gpu_meshes, each_sample, cancelled, view_batches,
                 first_sample if wanted & {"depth", "normal"} or vector is not None else None)
    pixels = read(targets.result, w, h)
    if vector is not None:  # only the first sample writes ids: still the line pass's
        vector["ids"] = read(targets.surface_id, w, h, 2)
    scale = stats.samples_requested / stats.samples if 0 < stats.samples < stats.samples_requested else 1.0
    pixels *= scale  # cancelled: rescale what was accumulated
    if "surface" in wanted:
        passes["surface"] = read(targets.surface_sum, w, h) * scale
    for name, texture in (("highlight", targets.highlight), ("lines", targets.lines)):
        if name in wanted:
            passes[name] = read(texture, w, h)
    if keep is not None:
        keep["surface"] = read(targets.surface_color, w, h)
        keep["highlight"] = read(targets.highlight, w, h)
        keep["depth"] = read(targets.surface_depth, w, h)
        keep["lines"] = read(targets.lines, w, h)
    unbind_targets()
    return pixels, stats


def unbind_targets():
    """Rebinds the texture units the passes used to a 1 x 1 texture: the driver frees a deleted
    texture only once nothing has it bound, and Blender leaves units bound until its next
    draw, so a finished render's targets (0.6 GB at 4K) would otherwise outlive it."""
    tiny = compat.texture((1, 1), 'RGBA32F')
    fb = gpu.types.GPUFrameBuffer(color_slots=(compat.texture((1, 1), 'RGBA32F'),))
    shader = shader_lib.get("composite")
    with fb.bind():
        shader.bind()
        for _, name in shader_specs.program("composite")["samplers"]:
            shader_lib.set_sampler(shader, name, tiny)
        shader_lib.set_uniform(shader, "background", (0.0, 0.0, 0.0, 0.0))
        shader_lib.set_uniform(shader, "weight", 0.0)
        batches.fullscreen_batch().draw(shader)
