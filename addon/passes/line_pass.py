"""Ink line pass: chains of line segments -> screen-space quads (line.vert.glsl), drawn into the
line target, where each pixel keeps its most opaque stroke (line.frag.glsl).

Lines at the screen's resolution (docs/lines.md): each chain (lines.LineSegments.chain_links)
is cut into groups of up to LOD_GROUP consecutive segments, and each group is a binary tree of
chords over them, the segments its leaves; a chord carries a bound on how far (object space)
the segments it stands for stray from it. The library writes one record per segment
(native.line_nodes): its ends, its ancestors' bounds and, for the chords it is the first
segment of, their lengths in segments. Per view and instance the vertex shader finds the
coarsest chord on each segment's path whose projected bound is within TOLERANCE_PX and draws it
from its first segment (the others draw nothing), skips crease chains whose whole projection
fits in SUBPIXEL_PX, and, with hidden lines off, every quad the visibility rule would hide at
every pixel. The records live in two float textures per line set (NODE_TEXELS texels and two
faces a segment), so a batch's vertices carry one integer each.
"""
import gpu
import numpy as np

from .. import compat
from ..bridge import native
from ..linework.line_visibility import OUTLINE_TYPES, REL_BIAS
from . import shader_lib

# A chord is drawn for the segments it stands for when none of them strays farther than this
# from it on screen (pixels; a bound, docs/lines.md derives it).
TOLERANCE_PX = 0.25
# Crease chains whose whole projection fits in a disc this wide (pixels) are not drawn.
SUBPIXEL_PX = 1.0
# Quads that the visibility rule would hide at every pixel are not rasterised (hidden lines
# off); False draws them (the tests compare both).
CULL_HIDDEN = True
# Segments per simplification group: a chord stands for at most this many (its faces: twice as
# many, line_faces0..3 in the shaders).
LOD_GROUP = native.LINE_GROUP
# Layout of the record texture (line.vert.glsl): NODE_TEXELS texels a segment, NODES_PER_ROW
# segments a row (4095 texels: a record never straddles two rows); the face texture:
# FACES_PER_ROW segments a row.
NODE_TEXELS = native.LINE_NODE_FLOATS // 4
NODES_PER_ROW = 819
FACES_PER_ROW = 4096


class LineNodes:
    """The records of one LineSegments, as the library writes them (native.line_nodes), as
    (N, NODE_TEXELS, 4) texels, and the segments' faces (N, 2), both in chain order."""

    def __init__(self, seg, chain_spheres=True):
        nodes, order = native.line_nodes(seg.p0, seg.p1, seg.taper, getattr(seg, "chain_links", None), chain_spheres)
        self.nodes = nodes.reshape(-1, NODE_TEXELS, 4)
        faces = seg.faces if seg.faces is not None else np.zeros((len(seg), 2), np.float32)
        self.faces = np.ascontiguousarray(np.asarray(faces, np.float32)[order])

    def __len__(self):
        return len(self.nodes)


def _rows(data, per_row, texels_per_item, channels):
    """(items, ...) float32 -> ((w, h), flat Buffer) of a float texture holding per_row items a
    row, zero-padded."""
    rows = max(1, -(-len(data) // per_row))
    flat = np.zeros((rows * per_row, texels_per_item * channels), np.float32)
    flat[:len(data)] = np.asarray(data, np.float32).reshape(len(data), -1)
    flat = flat.reshape(-1)
    return (per_row * texels_per_item, rows), gpu.types.Buffer('FLOAT', flat.size, flat)


class LineSet:
    """One line type's set of one geometry (or one instance's view-dependent set) on the GPU:
    its record and face textures and the batches that draw them (several in a final render, so a
    cancel lands between them). count: its segments."""

    def __init__(self, seg, chunk=None, chain_spheres=True):
        self.count = len(seg)
        rows = -(-len(seg) // NODES_PER_ROW)
        limit = gpu.capabilities.max_texture_size_get()
        if rows > limit:
            raise RuntimeError(f"{len(seg)} line segments of one type in one object; the GPU holds at most "
                               f"{limit * NODES_PER_ROW}")
        records = LineNodes(seg, chain_spheres)
        self.nodes, self.faces = _textures(records.nodes, records.faces)
        self.batches = _batches(0, len(records), chunk)

    @classmethod
    def shared(cls, nodes, faces, start, stop, chunk=None):
        """The segments [start, stop) of record and face textures that several sets share."""
        self = cls.__new__(cls)
        self.count, self.nodes, self.faces = stop - start, nodes, faces
        self.batches = _batches(start, stop, chunk)
        return self


def _textures(nodes, faces):
    """The record and face textures of records (N, NODE_TEXELS, 4) and faces (N, 2)."""
    size, buf = _rows(nodes, NODES_PER_ROW, NODE_TEXELS, 4)
    node_texture = compat.texture(size, 'RGBA32F', buf)
    size, buf = _rows(faces, FACES_PER_ROW, 1, 2)
    return node_texture, compat.texture(size, 'RG32F', buf)


def _batches(start, stop, chunk):
    """Batches of the segments [start, stop) in chain order, `chunk` at most each. Any split
    works: a chord is drawn from its first segment's record and the textures."""
    step = chunk or max(stop - start, 1)
    return [_batch(i, min(i + step, stop)) for i in range(start, stop, step)]


def _batch(start, stop):
    """GPUBatch of segments [start, stop) in chain order: four vertices each, `node` = 4 *
    segment + corner."""
    n = stop - start
    fmt = gpu.types.GPUVertFormat()
    fmt.attr_add(id="node", comp_type='I32', len=1, fetch_mode='INT')
    vbo = gpu.types.GPUVertBuf(fmt, 4 * n)
    vbo.attr_fill("node", np.arange(4 * start, 4 * stop, dtype=np.int32))
    # Corners: 0 (a, -1), 1 (a, +1), 2 (b, -1), 3 (b, +1); triangles 0-1-3, 0-3-2.
    quad = np.array([0, 1, 3, 0, 3, 2], dtype=np.int32)
    idx = (np.arange(n, dtype=np.int32)[:, None] * 4 + quad[None, :]).reshape(-1, 3)
    return gpu.types.GPUBatch(type='TRIS', buf=vbo, elem=gpu.types.GPUIndexBuf(type='TRIS', seq=idx))


def line_batches(segments, chunk=None):
    """type -> LineSet for the non-empty sets of `segments` (type -> LineSegments). With
    `chunk`, each batch holds at most that many segments, so a final render can check for a
    cancel between them; the viewport draws each set as one batch."""
    out = {}
    for kind, seg in segments.items():
        if len(seg):
            out[kind] = LineSet(seg, chunk, chain_spheres=kind == "crease")
    return out


def view_line_batches(per_instance, chunk=None):
    """[{type: LineSet}] of the view-dependent sets of each instance ([{type: LineSegments}],
    lines.view_lines). Each type's sets of all instances share one record texture and one face
    texture, written by one library call, each instance drawing its own range of them: a scene
    of many objects uploads two textures a type per frame, not two per object. Sets without
    chain records, or too many segments for one texture or one library call, get textures of
    their own."""
    out = [{} for _ in per_instance]
    kinds = list(dict.fromkeys(k for segs in per_instance for k in segs))
    for kind in kinds:
        parts = [(i, segs[kind]) for i, segs in enumerate(per_instance) if kind in segs and len(segs[kind])]
        total = sum(len(s) for _, s in parts)
        rows = -(-total // NODES_PER_ROW)
        # el_line_nodes takes under 2^24 segments a call (places exact as floats).
        if len(parts) < 2 or any(s.chain_links is None for _, s in parts) or total >= 1 << 24 \
                or rows > gpu.capabilities.max_texture_size_get():
            for i, s in parts:
                out[i][kind] = LineSet(s, chunk, chain_spheres=False)
            continue
        links = np.concatenate([s.chain_links for _, s in parts])
        # Each instance's chains after the last one's: chain order keeps each instance's
        # segments together, in instance order.
        ends = np.cumsum([len(s) for _, s in parts])
        chains = np.array([int(s.chain_links["chain"].max()) + 1 for _, s in parts], np.int64)
        links["chain"] += np.repeat(np.cumsum(chains) - chains, [len(s) for _, s in parts]).astype(np.uint32)
        cat = lambda name: np.concatenate([getattr(s, name) for _, s in parts])  # noqa: E731
        faces = [s.faces if s.faces is not None else np.zeros((len(s), 2), np.float32) for _, s in parts]
        nodes, order = native.line_nodes(cat("p0"), cat("p1"), cat("taper"), links, False)
        part_of = np.repeat(np.arange(len(parts)), [len(s) for _, s in parts])
        if np.any(np.diff(part_of[order]) < 0):  # chain order that mixed instances: not shared
            for i, s in parts:
                out[i][kind] = LineSet(s, chunk, chain_spheres=False)
            continue
        nodes_tex, faces_tex = _textures(nodes.reshape(-1, NODE_TEXELS, 4),
                                         np.ascontiguousarray(np.concatenate(faces).astype(np.float32)[order]))
        for (i, _), start, stop in zip(parts, ends - [len(s) for _, s in parts], ends):
            out[i][kind] = LineSet.shared(nodes_tex, faces_tex, int(start), int(stop), chunk)
    return out


def _mat(m):
    return np.asarray(m, dtype=np.float32).T.reshape(-1)


def _stretches(matrices):
    """{id(m): the largest factor by which the linear part of model matrix m stretches a
    length}, for all of them at once (one batched SVD, not one per instance)."""
    by_id = {id(m): m for m in matrices}
    if not by_id:
        return {}
    lin = np.stack([np.asarray(m, np.float64)[:3, :3] for m in by_id.values()])
    return dict(zip(by_id, np.linalg.svd(lin, compute_uv=False)[:, 0].tolist()))


def draw_lines(targets, instances, settings, ubo, stats, checkpoint=None, rounded=False):
    """instances: [(model matrix, {type: LineSet}, surface id of the instance)];
    types drawn in settings' order. checkpoint(), when given, runs after each batch; True stops the pass (a cancel):
    returns whether it stopped. `rounded`: the surface pass drew the fillets' outline; with the
    silhouettes drawn (on it), ink of the types that lie between faces is not drawn past it
    (line.frag.glsl)."""
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
        shader_lib.set_sampler(shader, "surface_depth", targets.surface_depth)
        shader_lib.set_sampler(shader, "surface_id", targets.surface_id)
        stretch = _stretches(matrix for matrix, _, _ in instances)
        # Ink of the types between faces past the fillets' outline is left out where the
        # silhouettes, moved onto that outline, ink it instead (line.frag.glsl).
        past = rounded and "silhouette" in settings.types
        for kind, style in settings.styles:
            shader_lib.set_uniform(shader, "line_color", (*style.color, style.opacity))
            shader_lib.set_uniform(shader, "line_style", (style.width, 1.0 if style.scene_units else 0.0, style.min_pixels, style.taper))
            for matrix, sets, instance_id in instances:
                entry = sets.get(kind)
                if entry is None:
                    continue
                shader_lib.set_uniform(shader, "model", _mat(matrix))
                shader_lib.set_uniform(shader, "line_vis", (settings.hidden_opacity, REL_BIAS, float(instance_id),
                                                            1.0 if kind in OUTLINE_TYPES else (-1.0 if past else 0.0)))
                # A chord's width is interpolated between its ends: a taper, whose peak a chord
                # could span, is drawn segment by segment.
                shader_lib.set_uniform(shader, "line_lod", (TOLERANCE_PX if style.taper <= 0.0 else -1.0,
                                                            SUBPIXEL_PX if kind == "crease" else 0.0,
                                                            stretch[id(matrix)], 1.0 if CULL_HIDDEN else 0.0))
                shader_lib.set_sampler(shader, "line_nodes", entry.nodes)
                shader_lib.set_sampler(shader, "line_faces", entry.faces)
                stats.lines_drawn += entry.count
                for batch in entry.batches:
                    batch.draw(shader)
                    if checkpoint is not None and checkpoint():
                        gpu.state.depth_test_set('NONE')
                        gpu.state.depth_mask_set(False)
                        return True
        gpu.state.depth_test_set('NONE')
        gpu.state.depth_mask_set(False)
    return False
