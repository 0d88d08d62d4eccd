"""GPU batches of one extracted mesh: surface triangles, edge quads and corner squares, per material
slot."""
import copy

import gpu
import numpy as np

from .. import compat
from ..geometry import band_ends, rounded_outline
from . import shader_lib


def _vertbuf(attrs):
    fmt = gpu.types.GPUVertFormat()
    for name, array in attrs.items():
        fmt.attr_add(id=name, comp_type='F32', len=array.shape[1], fetch_mode='FLOAT')
    count = len(next(iter(attrs.values())))
    vbo = gpu.types.GPUVertBuf(fmt, count)
    for name, array in attrs.items():
        vbo.attr_fill(name, np.ascontiguousarray(array, dtype=np.float32))
    return vbo


def surface_buffers(extract):
    """slot -> its triangles' vertex buffer, three vertices per triangle in order: a triangle's
    number is gl_VertexID / 3 however its vertices are drawn (shaders/surface.vert.glsl). Each
    triangle is wound as the library oriented it (outwards on a closed surface), so that
    culling back faces leaves a closed surface's outside (closed_surfaces.py); a triangle wound
    the other way round takes its corner normals negated, which keeps it shaded as it is seen
    (surface.frag's front and back)."""
    out = {}
    flips = extract.flips if extract.flips is not None else np.zeros(len(extract.corner_pos) // 3, bool)
    for slot, tris in extract.slot_triangles.items():
        flipped = flips[tris]
        order = np.where(flipped[:, None], np.array([0, 2, 1]), np.arange(3))
        corners = (tris[:, None] * 3 + order).reshape(-1)
        sign = np.where(np.repeat(flipped, 3), -1.0, 1.0).astype(np.float32)[:, None]
        out[slot] = _vertbuf({"pos": extract.corner_pos[corners], "nor": extract.corner_nor[corners] * sign,
                              "uv": slot_uv(extract, slot, corners), "col": slot_colors(extract, slot, corners),
                              "tan": slot_tangents(extract, slot, corners, flipped)})
    return out


def slot_uv(extract, slot, corners):
    """The UVs of a slot's corners for its image (MeshExtract.corner_uv), zero without one: every
    surface buffer has the attribute the surface program declares."""
    uv = _slot_uv(extract, slot)
    return uv[corners] if uv is not None else np.zeros((len(corners), 2), np.float32)


def slot_tangents(extract, slot, corners, flipped):
    """The tangents its Normal Map follows at a slot's corners (MeshExtract.corner_tangent), zero
    without one. A triangle wound the other way round has its normals negated (surface_buffers),
    so it is seen from the other side: its tangent and sign are negated too, as EEVEE negates
    them for a face seen from behind, which gives back Blender's frame (el_normal_map)."""
    texture = extract.slot_shading[slot].texture
    uv = texture.program.normal_uv if texture is not None else None
    tan = extract.corner_tangent.get(uv) if uv is not None else None
    if tan is None:
        return np.zeros((len(corners), 4), np.float32)
    return tan[corners] * np.where(np.repeat(flipped, 3), -1.0, 1.0).astype(np.float32)[:, None]


def slot_colors(extract, slot, corners):
    """The colour attribute its node program reads at a slot's corners (MeshExtract.corner_color),
    zero without one."""
    col = _slot_colors(extract, slot)
    return col[corners] if col is not None else np.zeros((len(corners), 4), np.float32)


def _triangles_batch(vbo, triangles):
    """The given triangles of a surface vertex buffer, indexed; None for none."""
    if not len(triangles):
        return None
    idx = (np.asarray(triangles, np.int64)[:, None] * 3 + np.arange(3)).astype(np.int32)
    return gpu.types.GPUBatch(type='TRIS', buf=vbo, elem=gpu.types.GPUIndexBuf(type='TRIS', seq=idx))


def _float_rows(items, per_row, limit):
    """(N, texels, 4) float32 -> an RGBA32F texture of per_row items a row, zero-padded; None
    past `limit` rows."""
    rows = max(1, -(-len(items) // per_row))
    if rows > limit:
        return None
    flat = np.zeros((rows * per_row, items.shape[1] * 4), np.float32)
    flat[:len(items)] = items.reshape(len(items), -1)
    flat = flat.reshape(-1)
    return compat.texture((per_row * items.shape[1], rows), 'RGBA32F', gpu.types.Buffer('FLOAT', flat.size, flat))


def outline_textures(extract):
    """slot -> ((edge, corner, triangle textures) of rounded_outline.records, which of the
    slot's triangles list anything, which of those more edges than the vertex shader judges),
    for the slots a strip or a corner may cross. Past what a texture holds, the outline stays
    the sharp mesh's."""
    recs = rounded_outline.from_edges(extract, "outline", rounded_outline.records)  # once per edge choice
    if recs is None:
        return {}
    limit = gpu.capabilities.max_texture_size_get()
    edges = _float_rows(recs[0], rounded_outline.EDGES_PER_ROW, limit)
    corners = _float_rows(recs[1] if len(recs[1]) else np.zeros((1, rounded_outline.CORNER_TEXELS, 4), np.float32),
                          rounded_outline.CORNERS_PER_ROW, limit)
    out = {}
    for slot, lists in recs[2].items():
        texels = np.zeros((len(lists), rounded_outline.TRIANGLE_TEXELS * 4), np.float32)
        texels[:, :lists.shape[1]] = lists
        tris = _float_rows(texels.reshape(len(lists), rounded_outline.TRIANGLE_TEXELS, 4),
                           rounded_outline.TRIANGLES_PER_ROW, limit)
        if edges is not None and corners is not None and tris is not None:
            out[slot] = ((edges, corners, tris), np.flatnonzero(np.any(lists > 0.0, axis=1)),
                         np.flatnonzero(lists[:, rounded_outline.VERTEX_EDGES] > 0.0))
    return out


# Corner table of an edge quad: (end, side). Corner 0 is the edge's shading vertex (corner.w =
# 1): under the benchmarks' whole-arc methods it alone integrates a short edge's arc
# (bench/shaders/edge_methods.vert.glsl) and both triangles take their flat varyings from it, so
# it starts both (first-vertex backends) or ends both (last-vertex ones).
# All shading vertices come first in the buffer: vertex SIMD groups then either all shade or
# none do.
_QUAD_CORNERS = np.array([[0, -1], [0, 1], [1, -1], [1, 1]], dtype=np.float32)
_TRIS_FIRST = np.array([0, 1, 3, 0, 3, 2], dtype=np.int64)
_TRIS_LAST = np.array([1, 3, 0, 3, 2, 0], dtype=np.int64)


def edge_batches(extract):
    from .provoking import first_vertex
    tris = _TRIS_FIRST if first_vertex() else _TRIS_LAST
    out = {}
    for slot, e in extract.edges.items():
        n = len(e)
        if n == 0:
            continue
        # Vertex of (edge i, corner c): the shading corners first, then the others edge by edge.
        def vid(i, c):
            return np.where(c == 0, i, n + 3 * i + (c - 1))
        # order[k]: the (4 * edge + corner) stored at buffer position k.
        order = np.r_[np.arange(n) * 4, (np.arange(n)[:, None] * 4 + np.arange(1, 4)).reshape(-1)]
        edge_of = order // 4
        rep = lambda a: a[edge_of]  # noqa: E731 - the edge's value at each stored corner
        corner = np.zeros((n * 4, 4), dtype=np.float32)
        corner[:, :2] = np.tile(_QUAD_CORNERS, (n, 1))
        corner[:, 2] = np.repeat(e.radius, 4)
        corner[::4, 3] = 1.0  # the shading vertex
        corner = corner[order]
        faces = e.faces if e.faces is not None else np.zeros((n, 2), np.float32)
        ends = e.ends if e.ends is not None else np.full((n, 4), band_ends.SQUARE, np.float32)
        turn = e.turn if e.turn is not None else np.zeros((n, 6), np.float32)
        vbo = _vertbuf({"p0": rep(e.p0), "p1": rep(e.p1), "n1": rep(e.n1), "n2": rep(e.n2), "faces": rep(faces),
                        "corner": corner, "ends": rep(ends), "turn1": rep(turn[:, :3]), "turn2": rep(turn[:, 3:]),
                        "uv": rep(edge_uv(extract, slot, e)), **_edge_attribute_colors(extract, slot, e, rep)})
        edge = np.repeat(np.arange(n), 6)
        idx = vid(edge, np.tile(tris, n)).astype(np.int32).reshape(-1, 3)
        out[slot] = gpu.types.GPUBatch(type='TRIS', buf=vbo, elem=gpu.types.GPUIndexBuf(type='TRIS', seq=idx))
    return out


def _slot_uv(extract, slot):
    """The corner UVs of the slot's image (MeshExtract.corner_uv), or None."""
    texture = extract.slot_shading[slot].texture
    if texture is None or texture.source is None:
        return None
    return extract.corner_uv.get(texture.source.uv_map)


def _slot_colors(extract, slot):
    """The corner colours of the attribute the slot's node program reads (MeshExtract.corner_color),
    or None."""
    texture = extract.slot_shading[slot].texture
    if texture is None or texture.program.attribute is None:
        return None
    return extract.corner_color.get(texture.program.attribute)


def _uv_at(extract, uv, tri, verts):
    """(N, k) the per-corner value `uv` (a UV, a colour) at mesh vertex verts[i] on triangle
    tri[i] (one of its corners)."""
    c = np.argmax(extract.edge_data.tri_verts[tri] == np.asarray(verts)[:, None], axis=1)
    return uv[3 * tri + c]


def _face_triangles(extract, slot, ids):
    """Per row of surface ids (N, k >= 2): the triangle of its first id when that face is the
    slot's, else of its second."""
    d = extract.edge_data
    tri_of = np.zeros(int(d.surface_id.max(initial=0)) + 1, np.int64)
    tri_of[d.surface_id] = np.arange(len(d.surface_id))
    ids = np.clip(np.asarray(ids, np.int64), 0, len(tri_of) - 1)
    first = tri_of[ids[:, 0]]
    return np.where((ids[:, 0] > 0) & (d.tri_slot[first] == slot), first, tri_of[ids[:, 1]])


def _has_uv(extract, slot, faces, verts):
    return _has_values(extract, _slot_uv(extract, slot), faces, verts)


def _has_values(extract, values, faces, verts):
    """Whether per-corner `values` (UVs, colours) can be taken at edges' or corners' vertices."""
    d = extract.edge_data
    return (values is not None and faces is not None and verts is not None and d is not None
            and d.tri_verts is not None and d.surface_id is not None)


def _edge_attribute_colors(extract, slot, e, rep):
    """The edge batch's col0 and col1: the colour attribute at each edge's p0 and p1 on its face
    of the slot, as edge_uv takes the UVs; zero without one."""
    col = _slot_colors(extract, slot)
    if not _has_values(extract, col, e.faces, e.verts):
        zero = np.zeros((len(e), 4), np.float32)
        return {"col0": rep(zero), "col1": rep(zero)}
    tri = _face_triangles(extract, slot, e.faces)
    return {"col0": rep(_uv_at(extract, col, tri, e.verts[:, 0])), "col1": rep(_uv_at(extract, col, tri, e.verts[:, 1]))}


def corner_colors(extract, slot, c):
    """(K, 4) the colour attribute at each corner patch's vertex, as corner_uv takes the UV."""
    col = _slot_colors(extract, slot)
    if not _has_values(extract, col, c.faces, c.vertex):
        return np.zeros((len(c), 4), np.float32)
    return _uv_at(extract, col, _face_triangles(extract, slot, c.faces), c.vertex)


def edge_uv(extract, slot, e):
    """(N, 4) the UV of the slot's image at each edge's p0 and p1, on its face of the slot (its
    first face, else its second): the band takes the image's colour along the edge
    (edge_shading.glsl's el_albedo). Zero when the slot draws no image."""
    if not _has_uv(extract, slot, e.faces, e.verts):
        return np.zeros((len(e), 4), np.float32)
    uv, tri = _slot_uv(extract, slot), _face_triangles(extract, slot, e.faces)
    return np.concatenate([_uv_at(extract, uv, tri, e.verts[:, 0]), _uv_at(extract, uv, tri, e.verts[:, 1])], axis=1)


def corner_uv(extract, slot, c):
    """(K, 2) the UV of the slot's image at each corner patch's vertex, on the first of its
    edges' faces that is the slot's; zero when the slot draws no image."""
    if not _has_uv(extract, slot, c.faces, c.vertex):
        return np.zeros((len(c), 2), np.float32)
    uv = _slot_uv(extract, slot)
    return _uv_at(extract, uv, _face_triangles(extract, slot, c.faces), c.vertex)


_SQUARE = np.array([[-1, -1], [1, -1], [-1, 1], [1, 1]], dtype=np.float32)


def corner_batches(extract):
    """A square per corner patch (corner_patches.py), drawn by shaders/edge_corner.*."""
    out = {}
    for slot, e in extract.edges.items():
        c = e.corners
        if c is None or not len(c):
            continue
        n = len(c)
        rep = lambda a: np.repeat(a, 4, axis=0)  # noqa: E731 - the corner's value at each of its four
        corner = np.zeros((n * 4, 4), dtype=np.float32)
        corner[:, :2] = np.tile(_SQUARE, (n, 1))
        corner[:, 2] = rep(c.radius)
        corner[:, 3] = rep(c.fold)
        vbo = _vertbuf({"v": rep(c.position), "m1": rep(c.normals[:, 0]), "m2": rep(c.normals[:, 1]),
                        "m3": rep(c.normals[:, 2]), "corner": corner, "faces_a": rep(c.faces[:, :3]),
                        "faces_b": rep(c.faces[:, 3:]), "uv": rep(corner_uv(extract, slot, c)),
                        "col": rep(corner_colors(extract, slot, c))})
        idx = (np.arange(n)[:, None] * 4 + np.array([0, 1, 3, 0, 3, 2])).astype(np.int32).reshape(-1, 3)
        out[slot] = gpu.types.GPUBatch(type='TRIS', buf=vbo, elem=gpu.types.GPUIndexBuf(type='TRIS', seq=idx))
    return out


class GpuMesh:
    """Everything the passes draw for one extracted mesh, built in the GPU context."""

    def __init__(self, extract, line_chunk=None):
        self.extract = extract
        self.line_chunk = line_chunk  # segments per line batch (line_pass.line_batches)
        self.surface_vbo = surface_buffers(extract)
        self.surface = {slot: gpu.types.GPUBatch(type='TRIS', buf=vbo) for slot, vbo in self.surface_vbo.items()}
        self.rebuild_edges()
        self.rebuild_lines()

    def drawing(self, extract):
        """This GpuMesh's batches drawing `extract` (of the same content_key), whose shading
        the passes read."""
        out = copy.copy(self)
        out.extract = extract
        return out

    def rebuild_lines(self):
        """The static line types (view-independent), type -> ([batch, ...], count)."""
        from .line_pass import line_batches
        self.lines = line_batches(self.extract.lines, self.line_chunk)

    def rebuild_edges(self):
        self.edges = edge_batches(self.extract)
        self.corners = corner_batches(self.extract)
        # The slots a rounded silhouette may pull in: their textures, and their triangles in
        # three batches over the slot's vertex buffer: those that list a strip or a corner
        # (drawn by the program that walks the lists), those of them that list more edges than
        # its vertex shader judges (by its variant that judges the rest per pixel) and the rest
        # (by the plain one). Mixed in one batch, every vertex group or fragment on llvmpipe
        # would pay for the walk.
        self.outline = {}
        for slot, (textures, listed, more) in outline_textures(self.extract).items():
            vbo = self.surface_vbo[slot]
            rest = np.setdiff1d(np.arange(len(self.extract.slot_triangles[slot])), listed)
            self.outline[slot] = (textures, _triangles_batch(vbo, np.setdiff1d(listed, more)),
                                  _triangles_batch(vbo, rest), _triangles_batch(vbo, more))
        self.edge_count = sum(len(e) for e in self.extract.edges.values())


def slot_corner_inputs(shading, missing=frozenset()):
    """Per slot, the UV map its image reads (None without one, or where it is among `missing`,
    the maps the mesh lacked), the colour attribute its node program reads and the UV map its
    Normal Map's tangents follow (None without): what its batches' UVs, colours and tangents
    are."""
    def uv(s):
        source = s.texture.source if s.texture is not None else None
        return source.uv_map if source is not None and source.uv_map not in missing else None
    return tuple((uv(s), s.texture.program.attribute if s.texture is not None else None,
                  s.texture.program.normal_uv if s.texture is not None else None) for s in shading)


def content_key(extract):
    """What a GpuMesh of `extract` is built from: its surface (corner arrays), its chosen edges,
    its static lines (each by identity: the copies a render cache or a material change makes
    share them until they are made anew) and what each slot's batches read besides
    (slot_corner_inputs). Equal keys build equal batches."""
    return (id(extract.corner_pos), id(extract.edges), id(extract.lines),
            slot_corner_inputs(extract.slot_shading, extract.missing_uv))


class GpuCache:
    """GpuMeshes kept from one frame of a render job to the next, by content_key: a frame of
    unchanged meshes builds no batch. The engine keeps one per view layer for as long as Blender
    keeps the engine and the GPU context the batches live in (one render job). A frame takes
    the meshes it draws (mesh) and then drops the ones it did not (end_render)."""

    def __init__(self):
        self._kept = {}        # content key -> GpuMesh (its extract keeps the key's arrays alive)
        self._used = set()
        self.built = 0         # GpuMeshes built (the tests' counter)

    def mesh(self, extract, line_chunk):
        """The GpuMesh that draws `extract`: kept batches where its content_key has some. Its
        own copy: two objects of one content may differ in their materials, whose shading the
        passes read from the GpuMesh's extract."""
        key = content_key(extract)
        gm = self._kept.get(key)
        if gm is None or gm.line_chunk != line_chunk:
            gm = self._kept[key] = GpuMesh(extract, line_chunk)
            self.built += 1
        self._used.add(key)
        return gm.drawing(extract)

    def end_render(self):
        self._kept = {k: v for k, v in self._kept.items() if k in self._used}
        self._used = set()

    def __len__(self):
        return len(self._kept)


_fullscreen = {}


def fullscreen_batch():
    """One triangle covering the viewport, built once (not per frame)."""
    if "batch" not in _fullscreen:
        from gpu_extras.batch import batch_for_shader
        _fullscreen["batch"] = batch_for_shader(shader_lib.get("composite"), 'TRIS',
                                                {"pos": [(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)]})
    return _fullscreen["batch"]
