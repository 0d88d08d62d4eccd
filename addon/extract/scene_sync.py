"""Evaluated depsgraph -> plain arrays the passes draw: meshes, chosen edges, lights, world.

Reads with foreach_get into numpy; hands topology to the native library for classification.
Never draws, never modifies the user's data (evaluated meshes are temporary copies).
"""
import dataclasses
import math
from dataclasses import dataclass, field

import bpy
import numpy as np

from .. import compat
from ..bridge import native, shader_specs
from ..geometry import closed_surfaces, radius_clamp
from ..geometry.edge_choice import choice_key, choose, same_edges
from ..geometry.edge_data import EdgeData, first_two_faces
from ..linework.lines import static_lines
from . import render_cache, world_light
from .materials import shading_of

GEOMETRY_TYPES = {'MESH', 'CURVE', 'SURFACE', 'FONT', 'META'}


@dataclass
class MeshExtract:
    name: str
    corner_pos: np.ndarray            # (3T, 3) surface vertices, non-indexed
    corner_nor: np.ndarray            # (3T, 3) Blender's corner normals
    slot_triangles: dict              # slot -> triangle indices
    slot_shading: list                # slot -> materials.Shading
    edges: dict = field(default_factory=dict)  # slot -> edge_choice.EdgeSet
    clamps: tuple = ()                          # radius_clamp_notes.RadiusClamps of `edges`' choice
    cache_key: object = None                    # the render cache's key it is kept under (render_cache.py)
    info: dict = field(default_factory=dict)
    edge_data: object = None                    # edge_data.EdgeData
    native: object = None                       # native.Mesh, kept for chains and views
    lines: dict = field(default_factory=dict)   # line type -> lines.LineSegments (static types)
    lines_key: object = None                    # the LineSettings.static_key() of `lines`
    views: dict = field(default_factory=dict)   # instance index -> native.View
    _face_normals: object = None
    smooth_faces: np.ndarray = None             # per triangle: shaded smooth (a corner normal not the face's)
    flips: np.ndarray = None                    # per triangle: the library reversed its winding (closed_surfaces)
    closed: bool = False                        # closed and consistently oriented: back faces hide (closed_surfaces)
    box: np.ndarray = None                      # (2, 3) object-space bounds of its surface
    corner_uv: dict = field(default_factory=dict)  # UV map name ("": active render) -> (3T, 2), for textured slots
    missing_uv: frozenset = frozenset()         # UV map names a slot's image asked for that the mesh lacks
    corner_color: dict = field(default_factory=dict)  # colour attribute name ("": render) -> (3T, 4), for node programs
    corner_tangent: dict = field(default_factory=dict)  # UV map name ("": render) -> (3T, 4) tangent, bitangent sign
    # What is computed from the chosen edges (rounded_outline.from_edges: the fillets' outline
    # records), by name: (the edges it was computed from, the value). One dict shared by the
    # copies a render cache makes, so a reused extraction whose edges were not chosen again does
    # not compute it again.
    derived: dict = field(default_factory=dict, repr=False)

    def notes(self):
        """Report lines about this geometry: what was drawn differently from the file and why."""
        out = [self.info[k] for k in ("non-finite", "note", "winding") if self.info.get(k)]
        out += [s.note for s in self.slot_shading if getattr(s, "note", "")]
        return list(dict.fromkeys(out))

    def surface_pass_indices(self):
        """Per surface id (what the surface pass writes for a triangle; 0: none), the Pass Index
        of its slot's material (the Material Index render pass)."""
        d = self.edge_data
        table = np.zeros(int(d.surface_id.max(initial=0)) + 1, np.float32)
        if len(d.surface_id):
            by_slot = np.array([s.pass_index for s in self.slot_shading] or [0], np.float32)
            table[d.surface_id] = by_slot[np.clip(d.tri_slot, 0, len(by_slot) - 1)]
        return table

    def face_normals(self):
        if self._face_normals is None:
            self._face_normals = self.native.face_normals()
        return self._face_normals

    def update_lines(self, settings):
        """Re-chooses the static line sets if the settings they depend on changed; True if so."""
        key = settings.static_key() if settings else None
        if key == self.lines_key:
            return False
        self.lines = static_lines(self.edge_data, self.native, settings)
        self.lines_key = key
        return True


@dataclass
class Light:
    kind: int                          # EL_LIGHT value (shaders/frame_data.json)
    color: tuple                       # colour x strength
    position: tuple
    direction: tuple                   # where the light points
    spot_cos: float = -1.0
    spot_blend: float = 0.0
    shadow: bool = False               # casts shadows (the light's Shadow setting)
    radius: float = 0.0                # its size for soft shadows (a sun: tan of its angular radius)


@dataclass
class Instance:
    mesh: MeshExtract
    matrix: np.ndarray                 # object -> world, 4x4 row-major
    pass_index: int = 0                # its object's Pass Index (the Object Index render pass)
    holdout: bool = False              # masked out of the view layer: a hole in the image
    casts_shadow: bool = True          # its object's Ray Visibility > Shadow


@dataclass
class SceneData:
    instances: list
    lights: list
    ambient: tuple
    reports: list                      # what was skipped and why
    failed: list = field(default_factory=list)  # the objects skipped for an error in their data
    environment: object = None         # world_light.Environment: an image lights the scene
    extracts: dict = field(default_factory=dict)  # geometry_key -> MeshExtract (None: skipped): collect's `kept`


class SkipObject(Exception):
    """This object cannot be drawn; the message says why. The render goes on. `failed`: for an
    error in its data (an object with nothing to shade has none)."""

    def __init__(self, message, failed=True):
        super().__init__(message)
        self.failed = failed


def _foreach(collection, prop, dtype, width=1):
    out = np.empty(len(collection) * width, dtype=dtype)
    collection.foreach_get(prop, out)
    return out.reshape(-1, width) if width > 1 else out


def triangle_edge_map(mesh, tri_loops):
    """Loop triangle side s (corner s -> s+1) -> Blender edge, or NO_EDGE for n-gon diagonals."""
    loop_edge = _foreach(mesh.loops, "edge_index", np.uint32)
    start = _foreach(mesh.polygons, "loop_start", np.int64)
    total = _foreach(mesh.polygons, "loop_total", np.int64)
    poly_of_loop = np.repeat(np.arange(len(start)), total)
    loops = np.arange(len(loop_edge))
    end = start[poly_of_loop] + total[poly_of_loop]
    next_loop = np.where(loops + 1 < end, loops + 1, start[poly_of_loop])
    out = np.empty(tri_loops.shape, dtype=np.uint32)
    for s in range(3):
        a, b = tri_loops[:, s], tri_loops[:, (s + 1) % 3]
        out[:, s] = np.where(next_loop[a] == b, loop_edge[a], native.NO_EDGE)
    return out


def polygon_unit_normals(mesh, positions):
    """Blender's polygon normals, exactly unit, or zero for a polygon without area (Blender gives
    those a made-up unit normal; the library then treats their faces as degenerate). Without
    area is relative to the polygon's own longest side, as the library judges a triangle: one
    stray vertex far away must not make the rest of the mesh's faces look flat."""
    n = compat.polygon_normals(mesh).astype(np.float64)
    area = _foreach(mesh.polygons, "area", np.float64)
    length = np.linalg.norm(n, axis=1)
    ok = np.isfinite(length) & (length > 0.5)
    # A polygon has area by the rule below wherever its area is large against the whole mesh:
    # only the others (usually none) need their sides measured.
    extent = float(np.ptp(positions, axis=0).max()) if len(positions) else 0.0
    doubt = np.flatnonzero(ok & ~(2.0 * area > 3e-7 * extent * extent))  # a side is at most sqrt(3) extents
    if len(doubt):
        ok[doubt] &= 2.0 * area[doubt] > 1e-7 * _longest_sides(mesh, positions, doubt)
    ok = ok[:, None]
    return np.where(ok, n / np.where(ok, length[:, None], 1.0), 0.0).astype(np.float32)


def _longest_sides(mesh, positions, polys):
    """The longest side, squared, of each polygon in `polys`."""
    start = _foreach(mesh.polygons, "loop_start", np.int64)[polys]
    total = _foreach(mesh.polygons, "loop_total", np.int64)[polys]
    loop_vert = _foreach(mesh.loops, "vertex_index", np.int64)
    first = np.repeat(start, total)
    k = np.arange(int(total.sum())) - np.repeat(np.cumsum(total) - total, total)  # corner within its polygon
    here = first + k
    after = first + (k + 1) % np.repeat(total, total)
    p = positions.astype(np.float64)
    d = p[loop_vert[after]] - p[loop_vert[here]]
    side = np.einsum("ij,ij->i", d, d)
    return np.maximum.reduceat(side, np.cumsum(total) - total)


# Farther from the origin than this a vertex has no usable position: its squared distances
# overflow single precision, where the shaders compute (Blender stores an infinite coordinate
# as the largest float). The library refuses such positions.
FARTHEST = native.MAX_COORDINATE


def unusable_vertices(positions):
    """Vertices at no usable position: NaN, infinite, or farther than FARTHEST on an axis."""
    return ~(np.abs(positions) <= FARTHEST).all(axis=1)


def extract_mesh(name, mesh, materials, lib=None, line_settings=None, cache=None, same_content=None):
    """Arrays and chosen edges of an evaluated mesh. Raises SkipObject with a reason. With
    `cache` (render_cache.ExtractCache), an extraction of the same object with the same content
    is reused: its shading and lines set afresh, nothing classified again. With `same_content`
    (a dict of this render's extractions by content and materials), a mesh equal to one already
    extracted, as separate copies of one part are, is that extraction: one native mesh and one
    set of GPU batches for all of them, as for linked duplicates (its notes name the first)."""
    mesh.calc_loop_triangles()
    tri_count = len(mesh.loop_triangles)
    if tri_count == 0:
        raise SkipObject(f"{name}: no faces ({len(mesh.edges)} loose edges), nothing to shade", failed=False)
    positions = _foreach(mesh.vertices, "co", np.float32, 3)
    tri_verts = _foreach(mesh.loop_triangles, "vertices", np.uint32, 3)
    tri_loops = _foreach(mesh.loop_triangles, "loops", np.int64, 3)
    edges = _foreach(mesh.edges, "vertices", np.uint32, 2)
    tri_edges = triangle_edge_map(mesh, tri_loops)
    tri_slot = np.clip(compat.triangle_material_index(mesh), 0, max(len(materials) - 1, 0))
    tri_poly = _foreach(mesh.loop_triangles, "polygon_index", np.int64)
    bad = unusable_vertices(positions)
    dropped, cut = None, None
    if bad.any():
        # Not drawn, as a GPU leaves them: the faces with a vertex at no usable position (the
        # whole polygon, from its triangles: the loops' order is not relied on).
        broken = np.zeros(len(mesh.polygons), bool)
        broken[tri_poly[bad[tri_verts].any(axis=1)]] = True
        keep = ~broken[tri_poly]
        if not keep.any():
            raise SkipObject(f"{name}: every face has a vertex at no usable position (NaN, infinite, "
                             f"or farther than {FARTHEST:g} units)")
        if broken.any():
            dropped = (int(broken.sum()), int(bad.sum()))
        tri_verts, tri_loops, tri_edges = tri_verts[keep], tri_loops[keep], tri_edges[keep]
        tri_slot, tri_poly = tri_slot[keep], tri_poly[keep]
        tri_count = len(tri_verts)
        # The library takes finite positions only; no face left uses these. An edge that reaches
        # one ends instead at a copy of its other end, with no marks: a point, which no line
        # type draws (it ran to wherever the vertex was put).
        positions = np.where(bad[:, None], 0.0, positions).astype(np.float32)
        touch = bad[edges]
        cut = np.flatnonzero(touch.any(axis=1))
        if len(cut):
            edges = edges.copy()
            stays = np.where(touch[cut, 0], edges[cut, 1], edges[cut, 0])
            edges[cut] = np.c_[stays, len(positions) + np.arange(len(cut))].astype(edges.dtype)
            positions = np.concatenate([positions, positions[stays]])
    sharp = compat.edge_sharp(mesh)
    marks = (sharp.astype(np.uint32) * native.MARK_SHARP
             | compat.edge_seam(mesh).astype(np.uint32) * native.MARK_SEAM
             | compat.edge_freestyle(mesh).astype(np.uint32) * native.MARK_FREESTYLE)
    bevel = np.clip(compat.edge_bevel_weight(mesh), 0.0, 1.0).astype(np.float32)
    if cut is not None and len(cut):
        sharp, marks, bevel = sharp.copy(), marks.copy(), bevel.copy()
        sharp[cut], marks[cut], bevel[cut] = False, 0, 0.0
    # Each triangle classifies by its polygon's normal: a sliver's own normal is noise, and a
    # zero-area piece along a polygon's side (collinear corners) would drop that side's edge.
    polygons = radius_clamp.Polygons(_foreach(mesh.polygons, "loop_start", np.int64),
                                     _foreach(mesh.polygons, "loop_total", np.int64),
                                     _foreach(mesh.loops, "vertex_index", np.int64), tri_poly,
                                     _foreach(mesh.loops, "edge_index", np.int64), None)
    corner_nor = compat.corner_normals(mesh)[tri_loops.reshape(-1)]
    if dropped is not None:  # a smooth corner next to a dropped face may have taken its NaN
        flat = np.repeat(polygon_unit_normals(mesh, positions)[tri_poly], 3, axis=0)
        corner_nor = np.where(np.isfinite(corner_nor).all(axis=1, keepdims=True), corner_nor, flat)
    shading = [shading_of(mat) for mat in materials] or [shading_of(None)]
    shading, corner_uv, missing_uv = textured_corners(name, mesh, shading, tri_loops)
    shading, corner_color = colored_corners(name, mesh, shading, tri_loops)
    shading, corner_tangent = tangent_corners(name, mesh, shading, tri_loops, positions[tri_verts.reshape(-1)], corner_nor)
    key = content = None
    if cache is not None or same_content is not None:
        digest = render_cache.fingerprint((positions, tri_verts, tri_loops, edges, tri_edges, tri_slot, marks, bevel,
                                           tri_poly, polygons.start, polygons.total, polygons.loop_vert,
                                           polygons.loop_edge, corner_nor, *(corner_uv[k] for k in sorted(corner_uv)),
                                           *(corner_color[k] for k in sorted(corner_color)),
                                           *(corner_tangent[k] for k in sorted(corner_tangent)),
                                           np.frombuffer(repr((sorted(corner_uv), sorted(corner_color),
                                                               sorted(corner_tangent))).encode(), np.uint8)))
        # Shading follows from the materials alone within a render: their names decide.
        content = (id(lib), digest, tuple(s.material for s in shading))
        if same_content is not None and content in same_content:
            return same_content[content]
    if cache is not None:
        # Keyed by the content alone: a Geometry Nodes host's own mesh and the meshes it
        # generates share its label, and copies of one part under other names are one mesh
        # (whichever of them the depsgraph lists first this time).
        key = (id(lib), digest)
        kept = cache.get(key)
        if kept is not None:
            out = _reused(cache, key, kept, shading, line_settings)
            if same_content is not None:
                same_content[content] = out
            return out
    polygons.normal = polygon_unit_normals(mesh, positions)
    tri_normals = polygons.normal[tri_poly]
    try:
        m = native.Mesh(positions, tri_verts, edges=edges, triangle_edges=tri_edges, edge_marks=marks,
                        bevel_weights=bevel, triangle_materials=tri_slot.astype(np.uint32),
                        triangle_normals=tri_normals, lib=lib)
    except native.NativeError as e:
        raise SkipObject(f"{name}: {e.message}") from None
    info = m.info()
    order = np.argsort(tri_slot, kind="stable")
    slot_triangles = {int(s): order[tri_slot[order] == s] for s in np.unique(tri_slot)}
    out = MeshExtract(name, positions[tri_verts.reshape(-1)], np.ascontiguousarray(corner_nor, np.float32),
                      slot_triangles, shading, info=info, corner_uv=corner_uv, missing_uv=frozenset(missing_uv),
                      corner_color=corner_color, corner_tangent=corner_tangent)
    # The classification, kept so a material change can re-choose edges without a native call.
    # The id the surface pass writes for each triangle (passes/frame.py): its batch's first id
    # plus its place in the batch, since the slots' batches are drawn in this order.
    surface_id = np.empty(tri_count, np.uint32)
    surface_id[order] = np.arange(1, tri_count + 1, dtype=np.uint32)
    # Smooth contours exist only where the surface is shaded smooth: a flat face has one normal.
    nor = out.corner_nor.reshape(-1, 3, 3)
    out.smooth_faces = np.any(np.einsum("tck,tk->tc", nor, tri_normals) < 1.0 - 1e-5, axis=1)
    out.flips = m.triangle_flips().astype(bool)
    out.closed = closed_surfaces.is_closed(tri_verts, out.flips)
    out.box = closed_surfaces.bounds(positions)  # loose vertices too: a larger box culls less, never wrongly
    out.edge_data = EdgeData(m.edge_flags(), m.edge_angles(), m.edge_normals(), edges, positions,
                             *first_two_faces(tri_edges, len(edges)), tri_slot, sharp, bevel, surface_id, polygons,
                             tri_verts=tri_verts, corner_nor=nor)
    out.edges, out.clamps = choose(out.edge_data, shading)
    out.native = m
    out.update_lines(line_settings)
    if info["flipped_winding_edges"]:
        out.info["winding"] = (f"{name}: {info['flipped_winding_edges']} edges join faces wound against each other; "
                               f"{info['reoriented_triangles']} faces were re-oriented (for highlights, creases "
                               f"and silhouettes only, the mesh is unchanged)")
    if dropped is not None:
        out.info["non-finite"] = (f"{name}: {dropped[1]} vertices at no usable position (NaN, infinite, or farther "
                                  f"than {FARTHEST:g} units); the {dropped[0]} faces using them are not drawn")
    if info["degenerate_triangles"]:
        out.info["note"] = f"{name}: {info['degenerate_triangles']} zero-area faces drawn without edge highlights"
    out.cache_key = key
    if cache is not None:
        _keep(cache, key, out, shading)
    if same_content is not None:
        same_content[content] = out
    return out


def _keep(cache, key, extract, shading):
    """Keeps a copy without what belongs to this render alone: its views (native handles) and
    its shading (which may hold this render's images), with the edge choice's key instead."""
    cache.put(key, (dataclasses.replace(extract, views={}, slot_shading=[]), choice_key(shading)))


def _reused(cache, key, kept, shading, line_settings):
    """A kept extraction with this render's shading and lines, as a copy: edges chosen again
    only where what the choice reads of the shading changed (and kept so for the next frame),
    no per-view state."""
    extract, chosen_with = kept
    if choice_key(shading) != chosen_with:
        chosen = choose(extract.edge_data, shading)
        extract = dataclasses.replace(extract, edges=extract.edges if same_edges(chosen.edges, extract.edges)
                                      else chosen.edges, clamps=chosen.clamps)
        _keep(cache, key, extract, shading)
    out = dataclasses.replace(extract, slot_shading=shading, views={})
    out.update_lines(line_settings)
    return out


def render_uv_layer(mesh):
    """The UV map an Image Texture reads when nothing says which: the active render one."""
    layers = mesh.uv_layers
    return next((uv for uv in layers if uv.active_render), layers.active)


def textured_corners(name, mesh, shading, tri_loops):
    """(shading, {UV map name: (3T, 2) corner UVs}, {the UV map names the mesh lacks}) for the
    slots that draw an image (materials.BaseTexture). A slot whose UV map the mesh lacks draws
    without its image, and its note says so."""
    corner_uv, out, missing = {}, [], set()
    for s in shading:
        if s.texture is not None and s.texture.source is not None:
            uv_name = s.texture.source.uv_map
            if uv_name not in corner_uv:
                layer = mesh.uv_layers.get(uv_name) if uv_name else render_uv_layer(mesh)
                if layer is not None:
                    corner_uv[uv_name] = _foreach(layer.data, "uv", np.float32, 2)[tri_loops.reshape(-1)]
            if uv_name not in corner_uv:
                missing.add(uv_name)
                which = f"UV map '{uv_name}'" if uv_name else "UV map"
                note = (f"{name}: material '{s.material}' maps image '{s.texture.source.image.name}' by a {which} the "
                        f"mesh does not have; it is drawn as if the image were its mean colour")
                s = dataclasses.replace(s, texture=None, note="; ".join(n for n in (s.note, note) if n))
        out.append(s)
    return out, corner_uv, missing


def color_attribute(mesh, name):
    """The colour attribute a node program reads: the one named, or the mesh's render colour
    attribute for "" (Blender's default when a Color Attribute node names none); None when the
    mesh has no such colour attribute."""
    colors = getattr(mesh, "color_attributes", None)
    if colors is None:
        return None
    if name:
        attr = colors.get(name)
    else:
        index = getattr(colors, "render_color_index", -1)
        attr = colors[index] if 0 <= index < len(colors) else colors.active_color
    return attr if attr is not None and attr.domain in {'POINT', 'CORNER'} else None


def colored_corners(name, mesh, shading, tri_loops):
    """(shading, {attribute name: (3T, 4) corner colours, scene-linear}) for the slots whose node
    program reads a colour attribute. Where the mesh lacks it the program reads zero, as
    Blender's nodes read a missing attribute, and the slot's note says so."""
    corner_color, out = {}, []
    for s in shading:
        attr_name = s.texture.program.attribute if s.texture is not None else None
        if attr_name is not None and attr_name not in corner_color:
            attr = color_attribute(mesh, attr_name)
            if attr is not None:
                values = _foreach(attr.data, "color", np.float32, 4)
                if attr.domain == 'POINT':
                    index = _foreach(mesh.loops, "vertex_index", np.int64)[tri_loops.reshape(-1)]
                else:
                    index = tri_loops.reshape(-1)
                corner_color[attr_name] = np.ascontiguousarray(values[index])
            else:
                which = f"colour attribute '{attr_name}'" if attr_name else "colour attribute"
                note = f"{name}: material '{s.material}' reads a {which} the mesh does not have; it reads black"
                if attr_name and attr_name in mesh.attributes:
                    note = (f"{name}: material '{s.material}' reads attribute '{attr_name}', which is not a colour "
                            f"attribute; it reads black")
                s = dataclasses.replace(s, note="; ".join(n for n in (s.note, note) if n))
        out.append(s)
    return out, corner_color


def tangent_corners(name, mesh, shading, tri_loops, corner_pos, corner_nor):
    """(shading, {UV map name: (3T, 4) corner tangents and bitangent signs}) for the slots whose
    node program has a Normal Map: Blender's own (mikktspace, Mesh.calc_tangents, as EEVEE's),
    or on a mesh with n-gons, which it refuses, each triangle's from its UVs. A mesh without
    the UV map keeps its normals there, and the slot's note says so."""
    loops = tri_loops.reshape(-1)
    wanted = {s.texture.program.normal_uv for s in shading if s.texture is not None} - {None}
    layers = {uv: (mesh.uv_layers.get(uv) if uv else render_uv_layer(mesh)) for uv in wanted}
    # Every UV read before calc_tangents: on 5.0 a refused call leaves the layers' data unreadable.
    uvs = {uv: _foreach(layer.data, "uv", np.float32, 2)[loops] for uv, layer in layers.items() if layer is not None}
    out_tangent, out = {}, []
    for uv_name, layer in layers.items():
        if layer is None:
            continue
        try:
            mesh.calc_tangents(uvmap=layer.name)
            tangent = _foreach(mesh.loops, "tangent", np.float32, 3)[loops]
            sign = _foreach(mesh.loops, "bitangent_sign", np.float32)[loops]
        except RuntimeError:  # n-gons
            tangent, sign = triangle_tangents(corner_pos, uvs[uv_name], corner_nor)
        out_tangent[uv_name] = np.ascontiguousarray(np.concatenate([tangent, sign[:, None]], axis=1), np.float32)
    for s in shading:
        uv_name = s.texture.program.normal_uv if s.texture is not None else None
        if uv_name is not None and layers.get(uv_name) is None:
            which = f"UV map '{uv_name}'" if uv_name else "UV map"
            note = f"{name}: material '{s.material}' has a Normal Map on a {which} the mesh does not have; not drawn"
            s = dataclasses.replace(s, note="; ".join(n for n in (s.note, note) if n))
        out.append(s)
    return out, out_tangent


def triangle_tangents(corner_pos, corner_uv, corner_nor):
    """((3T, 3) unit tangents, (3T,) bitangent signs) per corner from each triangle's positions
    and UVs (the direction of increasing u), made orthogonal to the corner's normal; zero where
    the UVs are degenerate."""
    p = np.asarray(corner_pos, np.float64).reshape(-1, 3, 3)
    uv = np.asarray(corner_uv, np.float64).reshape(-1, 3, 2)
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d1, d2 = uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    ok = np.abs(det) > 1e-20
    r = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)[:, None]
    t = (e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) * r
    b = (e2 * d1[:, 0:1] - e1 * d2[:, 0:1]) * r
    t, b = np.repeat(t, 3, axis=0), np.repeat(b, 3, axis=0)
    n = np.asarray(corner_nor, np.float64)
    t = t - n * np.sum(n * t, axis=1, keepdims=True)
    length = np.linalg.norm(t, axis=1, keepdims=True)
    t = np.where(length > 1e-20, t / np.where(length > 1e-20, length, 1.0), 0.0)
    sign = np.where(np.sum(np.cross(n, t) * b, axis=1) < 0.0, -1.0, 1.0)
    return t.astype(np.float32), sign.astype(np.float32)


def light_of(ob, matrix):
    """The Light of a light object, or None for a type FrameData has no kind for. Kinds are the
    shaders' (shaders/frame_data.json, EL_LIGHT), keyed by Blender's light types."""
    data = ob.data
    kind = shader_specs.load("frame_data.json")["enums"]["EL_LIGHT"].get(data.type)
    if kind is None:
        return None
    m = np.array(matrix, dtype=np.float64)
    direction = -m[:3, 2] / max(np.linalg.norm(m[:3, 2]), 1e-12)
    color = tuple(float(c) * float(data.energy) for c in data.color)
    light = Light(kind, color, tuple(m[:3, 3]), tuple(direction))
    if data.type == 'SPOT':
        light.spot_cos = math.cos(data.spot_size / 2.0)
        light.spot_blend = float(data.spot_blend)
    light.shadow = bool(getattr(data, "use_shadow", False))
    # An area light's size scales with its object, as Blender draws it; a point light's Radius does not.
    scale = float(np.mean(np.linalg.norm(m[:3, :2], axis=0))) if data.type == 'AREA' else 1.0
    light.radius = light_radius(data) * scale
    return light


def light_radius(data):
    """The size of a light that softens its shadows (shaders/shadows.glsl): a point or spot
    light's Radius; an area light's, as a disk of its area; a sun's angle as tan of its half."""
    if data.type == 'SUN':
        return math.tan(0.5 * float(getattr(data, "angle", 0.0)))
    if data.type == 'AREA':
        a = float(data.size)
        b = float(data.size_y) if data.shape in {'RECTANGLE', 'ELLIPSE'} else a
        return math.sqrt(a * b) / 2.0 if data.shape in {'DISK', 'ELLIPSE'} else math.sqrt(a * b / math.pi)
    return float(getattr(data, "shadow_soft_size", 0.0))


# Types no engine draws as a surface: passed over without a word.
_SILENT_TYPES = {'EMPTY', 'CAMERA', 'LIGHT_PROBE', 'LIGHTPROBE', 'SPEAKER', 'ARMATURE', 'LATTICE'}
_TYPE_NAMES = {'VOLUME': "volume", 'POINTCLOUD': "point cloud", 'CURVES': "hair curves",
               'GPENCIL': "grease pencil", 'GREASEPENCIL': "grease pencil"}


def object_materials(ob, override=None):
    """The material of each slot, or the view layer's Material Override in every slot (as Cycles
    renders a layer with one)."""
    slots = [slot.material for slot in ob.material_slots]
    return [override] * max(1, len(slots)) if override is not None else slots


def geometry_key(ob, materials):
    """What an instance draws: its evaluated geometry and its materials. Instances of one
    geometry (Geometry Nodes, collection and particle instances, linked duplicates) share one
    key, so one extraction and one native mesh serve all of them; instances carry their host's
    name, so a name would not do."""
    data = ob.data
    materials = tuple(m.name_full if m else "" for m in materials)
    if ob.type == 'MESH' and data is not None:
        return ('MESH', data.as_pointer(), materials)
    # Curves, text, surfaces and metaballs become meshes per object (to_mesh).
    return (ob.type, ob.name_full, data.as_pointer() if data is not None else 0, materials)


def instance_label(inst):
    ob = inst.object
    parent = inst.parent if inst.is_instance else None
    return f"{ob.name} (instanced by {parent.name})" if parent is not None and parent.name != ob.name else ob.name


def instance_owners(inst):
    """Names whose geometry update makes this instance's extraction stale."""
    parent = inst.parent if inst.is_instance else None
    return (inst.object.name, parent.name) if parent is not None else (inst.object.name,)


def not_drawn_note(not_drawn):
    """One report line for the objects EdgeLight passes over, or None."""
    if not not_drawn:
        return None
    items = sorted(not_drawn.items())
    shown = ", ".join(f"'{name}' ({kind})" for name, kind in items[:6])
    more = f" and {len(items) - 6} more" if len(items) > 6 else ""
    return f"does not draw {len(items)} object{'s' if len(items) != 1 else ''}: {shown}{more}"


def walk_instances(depsgraph, lookup, shown=None):
    """Every drawn instance of the evaluated scene, with the extraction `lookup` gives its
    geometry. lookup(key, ob, inst, materials) runs while the temporary instance object is valid
    (only inside the depsgraph's iteration) and returns a MeshExtract or None. `shown(inst)`,
    when given, passes over the instances it says are hidden (viewport_shown).

    Returns (instances, lights, not_drawn: {label: type name})."""
    instances, lights, not_drawn = [], [], {}
    override = getattr(depsgraph.view_layer, "material_override", None)
    holdout = holdouts(depsgraph.view_layer)
    for inst in depsgraph.object_instances:
        if not inst.show_self:
            continue  # an instancer that shows only its instances (a particle emitter's Show Emitter off)
        if shown is not None and not shown(inst):
            continue
        ob = inst.object
        if ob.type == 'LIGHT':
            light = light_of(ob, inst.matrix_world)
            if light:
                lights.append(light)
            continue
        if ob.type not in GEOMETRY_TYPES:
            if ob.type not in _SILENT_TYPES:
                not_drawn[instance_label(inst)] = _TYPE_NAMES.get(ob.type, ob.type.lower())
            continue
        materials = object_materials(ob, override)
        extract = lookup(geometry_key(ob, materials), ob, inst, materials)
        if extract is not None:
            instances.append(Instance(extract, np.array(inst.matrix_world, dtype=np.float32), ob.pass_index,
                                      holdout(inst), bool(getattr(ob, "visible_shadow", True))))
    return instances, lights, not_drawn


def viewport_shown(view_layer, space=None):
    """shown(inst) for walk_instances in a 3D view: whether the object, or for an instance its
    instancer, is visible there (Object.visible_get: a collection hidden with its eye in the
    view layer, local view). Blender 3.4's viewport depsgraph still lists the objects of a
    collection hidden with its eye. One question per instancer, however many instances; None
    (nothing to ask) when no collection is hidden so and there is no local view."""
    if getattr(space, "local_view", None) is None and not _any_layer_collection(view_layer, "hide_viewport"):
        return None
    known = {}

    def shown(inst):
        ob = (inst.parent if inst.is_instance and inst.parent is not None else inst.object).original
        key = ob.as_pointer()
        if key not in known:
            known[key] = ob.visible_get(view_layer=view_layer, viewport=space)
        return known[key]

    return shown


def _any_layer_collection(view_layer, flag):
    """Whether any layer collection of the view layer has `flag` set."""
    todo = list(view_layer.layer_collection.children)
    while todo:
        lc = todo.pop()
        if getattr(lc, flag):
            return True
        todo.extend(lc.children)
    return False


def holdouts(view_layer):
    """holdout(inst): whether the view layer masks the instance out, as Cycles and EEVEE do: the
    object's own Holdout (Object > Visibility), or a holdout collection holding it or its
    instancer. One question per object, however many instances; none at all in a file with no
    holdout."""
    if not _any_layer_collection(view_layer, "holdout") and not any(ob.is_holdout for ob in bpy.data.objects):
        return lambda inst: False
    known = {}

    def masked(ob):
        key = ob.original.as_pointer()
        if key not in known:
            known[key] = bool(ob.is_holdout or ob.original.holdout_get(view_layer=view_layer))
        return known[key]

    def holdout(inst):
        parent = inst.parent if inst.is_instance else None
        return masked(inst.object) or (parent is not None and masked(parent))

    return holdout


def read_object(ob, label, materials, lib=None, line_settings=None, cache=None, same_content=None):
    """The extraction of one evaluated object (raises SkipObject), or None when it has no
    geometry at all (a Geometry Nodes host whose output is only instances)."""
    mesh = None
    try:
        mesh = ob.to_mesh()
        if mesh is None or len(mesh.vertices) == 0:
            return None
        return extract_mesh(label, mesh, materials, lib=lib, line_settings=line_settings, cache=cache,
                            same_content=same_content)
    finally:
        if mesh is not None:
            ob.to_mesh_clear()


# What may change from one frame of a render job to the next with every extraction still what
# it was: where objects are, cameras and lights (walk_instances reads them every frame), and the
# animation that moves them.
_MOVES_ONLY = (bpy.types.Camera, bpy.types.Light, bpy.types.Action)


def only_moved(depsgraph):
    """Whether the depsgraph's updates since its last evaluation (within a render job: the last
    frame) leave every extraction as it was: objects moved, cameras and lights changed; no
    geometry, material, world or setting did. (A moved object's update says "shading" too; a
    material assigned in its place changes the object's geometry_key, so it is read anew.)"""
    for u in depsgraph.updates:
        if isinstance(u.id, bpy.types.Object):
            if u.is_updated_geometry:
                return False
        elif not isinstance(u.id, _MOVES_ONLY):
            return False
    return True


def collect(depsgraph, lib=None, line_settings=None, cache=None, kept=None):
    """Everything visible in the evaluated scene. Objects that fail are reported and skipped.
    `cache`: a render_cache.ExtractCache that extractions are kept in and reused from. `kept`:
    the last frame's SceneData.extracts, drawn again as they are, nothing read (only_moved says
    when they may be)."""
    reports, extracted, failed = [], {}, []
    same_content = {}  # this render's extractions by content and materials (extract_mesh)

    def lookup(key, ob, inst, materials):
        if key not in extracted and kept is not None and kept.get(key) is not None:
            extracted[key] = kept[key]
            if cache is not None and extracted[key].cache_key is not None:
                cache.get(extracted[key].cache_key)  # used this frame: kept past it (render_cache.py)
            reports.extend(extracted[key].notes())
        if key not in extracted:
            extracted[key] = None
            try:
                extracted[key] = read_object(ob, instance_label(inst), materials, lib=lib,
                                             line_settings=line_settings, cache=cache, same_content=same_content)
            except SkipObject as e:
                reports.append(str(e))
                if e.failed:
                    failed.append(instance_label(inst))
            if extracted[key] is not None:
                reports.extend(extracted[key].notes())
        return extracted[key]

    instances, lights, not_drawn = walk_instances(depsgraph, lookup)
    note = not_drawn_note(not_drawn)
    if note:
        reports.append(note)
    world = world_light.read(depsgraph.scene.world)
    if world.note:
        reports.append(world.note)
    return SceneData(instances, lights, world.ambient, reports, failed, world.environment, extracted)
