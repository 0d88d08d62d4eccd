"""Ink line pass: line segments -> screen-space quads (line.vert.glsl), drawn into the line
target, where each pixel keeps its most opaque stroke (line.frag.glsl)."""
import gpu
import numpy as np

from . import shader_lib

# Corners of a segment's quad: (end, side); two triangles 0-1-3, 0-3-2.
_CORNERS = np.array([[0, -1], [0, 1], [1, -1], [1, 1]], dtype=np.float32)
_TRIS = np.array([0, 1, 3, 0, 3, 2], dtype=np.int64)
# Relative part of the depth bias (line.frag.glsl), against float rounding of depths.
REL_BIAS = 1e-4
# Line types that can lie on an outline: the background beside them does not hide them.
OUTLINE_TYPES = frozenset({"silhouette", "border", "contour", "wire"})


def line_batch(seg, start=0, stop=None):
    """GPUBatch of segments [start, stop) of one LineSegments, or None when that is empty."""
    stop = len(seg) if stop is None else min(stop, len(seg))
    n = stop - start
    if n <= 0:
        return None
    fmt = gpu.types.GPUVertFormat()
    faces = seg.faces if seg.faces is not None else np.zeros((len(seg), 2), np.float32)
    attrs = {"p0": seg.p0, "p1": seg.p1, "n1": seg.n1, "n2": seg.n2, "taper": seg.taper, "faces": faces}
    for name, a in attrs.items():
        fmt.attr_add(id=name, comp_type='F32', len=a.shape[1], fetch_mode='FLOAT')
    fmt.attr_add(id="corner", comp_type='F32', len=2, fetch_mode='FLOAT')
    vbo = gpu.types.GPUVertBuf(fmt, 4 * n)
    for name, a in attrs.items():
        vbo.attr_fill(name, np.repeat(np.ascontiguousarray(a[start:stop], np.float32), 4, axis=0))
    vbo.attr_fill("corner", np.tile(_CORNERS, (n, 1)))
    idx = (np.repeat(np.arange(n) * 4, 6) + np.tile(_TRIS, n)).astype(np.int32).reshape(-1, 3)
    return gpu.types.GPUBatch(type='TRIS', buf=vbo, elem=gpu.types.GPUIndexBuf(type='TRIS', seq=idx))


def line_batches(segments, chunk=None):
    """type -> ([GPUBatch, ...], count) for the non-empty sets of `segments` (type ->
    LineSegments). With `chunk`, each batch holds at most that many segments, so a final render
    can check for a cancel between them; the viewport draws each set as one batch."""
    out = {}
    for kind, seg in segments.items():
        step = chunk or max(len(seg), 1)
        parts = [b for b in (line_batch(seg, i, i + step) for i in range(0, len(seg), step)) if b is not None]
        if parts:
            out[kind] = (parts, len(seg))
    return out


def _mat(m):
    return np.asarray(m, dtype=np.float32).T.reshape(-1)


def draw_lines(targets, instances, settings, ubo, stats, checkpoint=None):
    """instances: [(model matrix, {type: ([batch, ...], count)}, surface id of the instance)];
    types drawn in settings' order. checkpoint(), when given, runs after each batch; True stops the pass (a cancel):
    returns whether it stopped."""
    if settings is None and targets.lines_empty:
        return False  # still clear from the last frame: no full-screen clear per frame without lines
    shader = shader_lib.get("line")
    with targets.line_fb.bind():
        targets.line_fb.clear(color=(0.0, 0.0, 0.0, 0.0), depth=1.0)
        targets.lines_empty = settings is None
        if settings is None:
            return False
        gpu.state.depth_test_set('LESS')
        gpu.state.depth_mask_set(True)
        gpu.state.blend_set('NONE')
        gpu.state.face_culling_set('NONE')
        shader.bind()
        shader.uniform_block("frame", ubo)
        shader.uniform_sampler("surface_depth", targets.surface_depth)
        shader.uniform_sampler("surface_id", targets.surface_id)
        for kind, style in settings.styles:
            shader.uniform_float("line_color", (*style.color, style.opacity))
            shader.uniform_float("line_style", (style.width, 1.0 if style.scene_units else 0.0, style.min_pixels, style.taper))
            for matrix, batches, instance_id in instances:
                entry = batches.get(kind)
                if entry is None:
                    continue
                shader.uniform_float("model", _mat(matrix))
                shader.uniform_float("line_vis", (settings.hidden_opacity, REL_BIAS, float(instance_id),
                                                  1.0 if kind in OUTLINE_TYPES else 0.0))
                stats.lines_drawn += entry[1]
                for batch in entry[0]:
                    batch.draw(shader)
                    if checkpoint is not None and checkpoint():
                        gpu.state.depth_test_set('NONE')
                        gpu.state.depth_mask_set(False)
                        return True
        gpu.state.depth_test_set('NONE')
        gpu.state.depth_mask_set(False)
    return False
