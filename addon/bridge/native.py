"""ctypes binding of libedgelight's C ABI (native/include/edgelight/edgelight.h).

The only module that touches ctypes, and it imports no bpy: it can be used and tested in plain
Python. Every call checks its status and raises NativeError with the library's message.
"""
import ctypes
import os

import numpy as np

from . import library_check, platforms

ABI_VERSION = 12

# Edge flags and marks (edgelight.h).
EDGE_LOOSE = 1 << 0
EDGE_BORDER = 1 << 1
EDGE_MANIFOLD = 1 << 2
EDGE_NON_MANIFOLD = 1 << 3
EDGE_CREASE = 1 << 4
EDGE_CONVEX = 1 << 5
EDGE_CONCAVE = 1 << 6
EDGE_DEGENERATE = 1 << 7
EDGE_MATERIAL_BOUNDARY = 1 << 8
EDGE_FLIPPED_WINDING = 1 << 9
MARK_SHARP = 1 << 16
MARK_SEAM = 1 << 17
MARK_FREESTYLE = 1 << 18
MARK_BEVEL = 1 << 19
MARK_ALL = MARK_SHARP | MARK_SEAM | MARK_FREESTYLE | MARK_BEVEL
NO_EDGE = 0xFFFFFFFF
MAX_COORDINATE = 1e15  # EL_MAX_COORDINATE

PERSPECTIVE = 0
ORTHOGRAPHIC = 1
VIEW_SILHOUETTES = 1 << 0
VIEW_CONTOURS = 1 << 1

CHAIN_CLOSED = 1 << 0
CHAIN_START_FREE = 1 << 1
CHAIN_END_FREE = 1 << 2

LINE_GROUP = 8
LINE_NODE_FLOATS = 20
LINE_NODES_CHAIN_SPHERES = 1 << 0

# The outline's records (el_outline_desc; the layout: shaders/outline_layout.json).
OUTLINE_EDGE_TEXELS = 6
OUTLINE_CORNER_TEXELS = 5
OUTLINE_ARC_MAX_PIECES = 8
# View lines of many instances (el_view_lines_desc).
NO_TAPER = 1.0e9  # the taper value of an end with no free end on its chain
VIEW_LINES_TAPER = 1 << 0
OUTLINE_FANS_OWN_SIDES = 1 << 0
# Which edges a material slot rounds (el_slot_rules.rules).
RULE_ANGLE = 1 << 0
RULE_SHARP = 1 << 1
RULE_BEVEL = 1 << 2

TABLE_PAPER = 0
TABLE_WARPED = 1
TABLE_BICUBIC = 2

_u32p = ctypes.POINTER(ctypes.c_uint32)
_f32p = ctypes.POINTER(ctypes.c_float)
_u8p = ctypes.POINTER(ctypes.c_uint8)


class NativeError(RuntimeError):
    """A failed library call: `status` is the el_status name, the message says what was wrong."""

    def __init__(self, status, message):
        super().__init__(f"{status}: {message}")
        self.status = status
        self.message = message


class LibraryUnavailable(NativeError):
    """The library is missing, unloadable, or of another ABI version."""


class MeshDesc(ctypes.Structure):
    _fields_ = [
        ("positions", _f32p), ("vertex_count", ctypes.c_uint32),
        ("triangles", _u32p), ("triangle_count", ctypes.c_uint32),
        ("edges", _u32p), ("edge_count", ctypes.c_uint32),
        ("triangle_edges", _u32p),
        ("edge_marks", _u32p), ("edge_bevel_weights", _f32p),
        ("triangle_materials", _u32p),
        ("vertex_normals", _f32p),
        ("triangle_normals", _f32p),
    ]


class MeshInfo(ctypes.Structure):
    _fields_ = [(name, ctypes.c_uint32) for name in (
        "vertex_count", "triangle_count", "edge_count", "loose_edges", "border_edges",
        "manifold_edges", "non_manifold_edges", "crease_edges", "convex_edges", "concave_edges",
        "marked_edges", "material_boundary_edges", "flipped_winding_edges", "reoriented_triangles",
        "degenerate_triangles", "degenerate_edges", "host_edges")] + [("crease_angle_deg", ctypes.c_float)]


class Camera(ctypes.Structure):
    _fields_ = [("projection", ctypes.c_int32), ("eye", ctypes.c_float * 3),
                ("view_dir", ctypes.c_float * 3), ("object_to_world", ctypes.c_float * 16)]


class ViewStats(ctypes.Structure):
    _fields_ = [(name, ctypes.c_uint64) for name in (
        "updates", "cache_hits", "facing_passes", "faces_flipped", "silhouette_rebuilds",
        "contour_passes")] + [("silhouette_edges", ctypes.c_uint32), ("contour_segments", ctypes.c_uint32)]


class TableDesc(ctypes.Structure):
    _fields_ = [("layout", ctypes.c_int32), ("phi_count", ctypes.c_uint32),
                ("m_count", ctypes.c_uint32), ("m_max", ctypes.c_float)]


class TableInfo(ctypes.Structure):
    _fields_ = [("layout", ctypes.c_int32), ("phi_count", ctypes.c_uint32),
                ("m_count", ctypes.c_uint32), ("m_max", ctypes.c_float), ("warp_c", ctypes.c_float)]


class HighlightInput(ctypes.Structure):
    _fields_ = [("point", ctypes.c_float * 3), ("edge_dir", ctypes.c_float * 3),
                ("n1", ctypes.c_float * 3), ("n2", ctypes.c_float * 3),
                ("eye", ctypes.c_float * 3), ("view_dir", ctypes.c_float * 3),
                ("projection", ctypes.c_int32), ("light", ctypes.c_float * 3),
                ("light_is_point", ctypes.c_int32), ("shininess", ctypes.c_float),
                ("radius", ctypes.c_float), ("K", ctypes.c_float), ("ortho_scale", ctypes.c_float)]


class HighlightResult(ctypes.Structure):
    _fields_ = [("specular", ctypes.c_float), ("diffuse", ctypes.c_float), ("weight", ctypes.c_float),
                ("r_max", ctypes.c_float), ("visible_fraction", ctypes.c_float)]


class OutlineDesc(ctypes.Structure):
    _fields_ = [("edges", _f32p), ("edge_vertices", _u32p), ("edge_count", ctypes.c_uint32),
                ("corners", _f32p), ("corner_vertices", _u32p), ("corner_count", ctypes.c_uint32)]


class OutlineView(ctypes.Structure):
    _fields_ = [("projection", ctypes.c_int32), ("eye", ctypes.c_float * 3), ("view_dir", ctypes.c_float * 3),
                ("object_to_world", ctypes.c_float * 16), ("world_to_view", ctypes.c_float * 16),
                ("view_to_clip", ctypes.c_float * 16), ("width", ctypes.c_float), ("height", ctypes.c_float)]


class SlotRules(ctypes.Structure):
    _fields_ = [("enabled", ctypes.c_uint32), ("radius", ctypes.c_float), ("K", ctypes.c_float),
                ("rules", ctypes.c_uint32), ("angle_deg", ctypes.c_float)]


class Polygons(ctypes.Structure):
    _fields_ = [("start", _u32p), ("total", _u32p), ("polygon_count", ctypes.c_uint32), ("loop_vert", _u32p),
                ("loop_edge", _u32p), ("loop_count", ctypes.c_uint32), ("tri_poly", _u32p),
                ("triangle_count", ctypes.c_uint32), ("normal", _f32p)]


class ViewLinesDesc(ctypes.Structure):
    _fields_ = [(name, ctypes.c_void_p) for name in ("mesh", "outline", "edge_faces", "views")] \
        + [("view_count", ctypes.c_uint32), ("flags", ctypes.c_uint32)]


# el_outline_view as a numpy record, for many instances' views at once (pinned to OutlineView
# by tests/addon/test_native_binding.py).
OUTLINE_VIEW = np.dtype([("projection", np.int32), ("eye", np.float32, 3), ("view_dir", np.float32, 3),
                         ("object_to_world", np.float32, 16), ("world_to_view", np.float32, 16),
                         ("view_to_clip", np.float32, 16), ("width", np.float32), ("height", np.float32)])


# Per instance and view: plain addresses (numpy's .ctypes.data), cheaper than typed pointers.
class OutlineSegments(ctypes.Structure):
    _fields_ = [(name, ctypes.c_void_p) for name in ("vertices", "p0", "p1", "n1", "n2", "taper", "faces", "links")] \
        + [("count", ctypes.c_uint32)]


class OutlineOut(ctypes.Structure):
    _fields_ = [(name, ctypes.c_void_p) for name in ("p0", "p1", "n1", "n2", "taper", "faces", "links")] \
        + [("capacity", ctypes.c_uint32)]


# el_chain_link and el_chain as numpy records (both 12 bytes, no padding).
CHAIN_LINK = np.dtype([("chain", np.uint32), ("s0", np.float32), ("s1", np.float32)])
CHAIN = np.dtype([("item_count", np.uint32), ("length", np.float32), ("flags", np.uint32)])

_P = ctypes.c_void_p
_SIGNATURES = {
    "el_mesh_create": [ctypes.POINTER(MeshDesc), ctypes.POINTER(_P)],
    "el_mesh_classify": [_P, ctypes.c_float],
    "el_mesh_get_info": [_P, ctypes.POINTER(MeshInfo)],
    "el_mesh_get_edges": [_P, _u32p, ctypes.c_uint32],
    "el_mesh_get_edge_flags": [_P, _u32p, ctypes.c_uint32],
    "el_mesh_get_edge_face_counts": [_P, _u32p, ctypes.c_uint32],
    "el_mesh_get_edge_normals": [_P, _f32p, ctypes.c_uint32],
    "el_mesh_get_edge_angles": [_P, _f32p, ctypes.c_uint32],
    "el_mesh_get_face_normals": [_P, _f32p, ctypes.c_uint32],
    "el_mesh_get_degenerate_triangles": [_P, _u8p, ctypes.c_uint32],
    "el_mesh_get_triangle_flips": [_P, _u8p, ctypes.c_uint32],
    "el_mesh_select_edges": [_P, ctypes.c_uint32, ctypes.c_uint32, _u32p, ctypes.c_uint32, _u32p],
    "el_view_create": [_P, ctypes.POINTER(_P)],
    "el_view_update": [_P, ctypes.POINTER(Camera), ctypes.c_uint32, _u32p],
    "el_view_get_silhouettes": [_P, _u32p, ctypes.c_uint32, _u32p],
    "el_view_get_contours": [_P, _f32p, _u32p, ctypes.c_uint32, _u32p],
    "el_view_get_stats": [_P, ctypes.POINTER(ViewStats)],
    "el_mesh_chain_edges": [_P, _u32p, ctypes.c_uint32, _P, _P, ctypes.c_uint32, _u32p],
    "el_view_chain_contours": [_P, _P, ctypes.c_uint32, _P, ctypes.c_uint32, _u32p],
    "el_line_nodes": [_f32p, _f32p, _f32p, _P, ctypes.c_uint32, ctypes.c_uint32, _f32p, ctypes.c_uint32, _u32p],
    "el_outline_create": [ctypes.POINTER(OutlineDesc), ctypes.POINTER(_P)],
    "el_outline_lines": [_P, ctypes.POINTER(OutlineView), ctypes.POINTER(OutlineSegments), ctypes.POINTER(OutlineOut),
                         _u32p],
    "el_view_lines_create": [ctypes.POINTER(ViewLinesDesc), ctypes.POINTER(_P)],
    "el_view_lines_get_offsets": [_P, _u32p, ctypes.c_uint32, ctypes.POINTER(ctypes.c_int32)],
    "el_view_lines_copy": [_P, ctypes.POINTER(OutlineOut)],
    "el_view_lines_get_message": [_P, ctypes.c_uint32, ctypes.POINTER(ctypes.c_char_p)],
    "el_outline_fans": [_u32p, _f32p, ctypes.c_uint32, ctypes.POINTER(ctypes.c_int32), ctypes.c_uint32, _f32p,
                        ctypes.c_uint32, ctypes.c_uint32, ctypes.c_uint32, ctypes.c_float, ctypes.c_uint32, _f32p],
    "el_corner_patches": [_f32p, ctypes.c_uint32, _u32p, _f32p, _u8p, _u8p, _f32p, _u8p, ctypes.c_uint32,
                          ctypes.c_uint32, _u32p, _u32p, _f32p, _f32p, _f32p, _f32p, _u32p],
    "el_band_ends": [ctypes.POINTER(Polygons), _f32p, ctypes.c_uint32, _u32p, _f32p, _u8p, _u8p,
                     ctypes.POINTER(ctypes.c_int32), ctypes.c_uint32, _u32p, ctypes.POINTER(ctypes.c_int32),
                     ctypes.c_uint32, _f32p],
    "el_edge_rules": [_u32p, _f32p, ctypes.POINTER(ctypes.c_int32), ctypes.POINTER(ctypes.c_int32), _u8p, _f32p,
                      ctypes.c_uint32, _u32p, ctypes.c_uint32, ctypes.POINTER(SlotRules), ctypes.c_uint32, _u8p, _f32p,
                      _u32p, _u32p, _u8p, _u8p, _f32p, _f32p],
    "el_width_bounds": [ctypes.POINTER(Polygons), _f32p, ctypes.c_uint32, _u32p, ctypes.POINTER(ctypes.c_int32),
                        ctypes.c_uint32, ctypes.POINTER(ctypes.c_double)],
    "el_shading_normals": [_f32p, ctypes.c_uint32, _u32p, _f32p, ctypes.POINTER(ctypes.c_int32), ctypes.c_uint32,
                           _u32p, _f32p, ctypes.c_uint32, _u32p, ctypes.c_uint32, ctypes.c_float, _f32p],
    "el_fillet_outline": [_f32p, _f32p, _f32p, ctypes.c_uint32, _f32p, _f32p, _u8p],
    "el_highlight_table_create": [ctypes.POINTER(TableDesc), ctypes.POINTER(_P)],
    "el_highlight_table_get_info": [_P, ctypes.POINTER(TableInfo)],
    "el_highlight_table_copy": [_P, _f32p, ctypes.c_uint64],
    "el_highlight_eval_batch": [_P, ctypes.POINTER(HighlightInput), ctypes.c_uint32, ctypes.POINTER(HighlightResult)],
    "el_highlight_reference": [ctypes.POINTER(HighlightInput), ctypes.POINTER(HighlightResult)],
}
_DESTROY = ("el_mesh_destroy", "el_view_destroy", "el_outline_destroy", "el_view_lines_destroy",
            "el_highlight_table_destroy")
# Every function the binding calls besides el_abi_version: name -> (argtypes, restype). A library
# lacking any is refused when loaded.
_FUNCTIONS = {
    "el_last_error": ([], ctypes.c_char_p),
    "el_status_name": ([ctypes.c_int], ctypes.c_char_p),
    **{name: (args, ctypes.c_int) for name, args in _SIGNATURES.items()},
    **{name: ([_P], None) for name in _DESTROY},
}


def default_library_path():
    """EDGELIGHT_LIBRARY, else the platform's library at the package's root, beside its
    __init__.py (the packaged add-on's layout: libedgelight.so, edgelight.dll or
    libedgelight.dylib, platforms.py)."""
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return os.environ.get("EDGELIGHT_LIBRARY") or os.path.join(package, platforms.library_file())


class Library:
    """The loaded shared library with its C signatures declared; refuses a damaged file (before
    mapping it: see library_check), another ABI version, and a library lacking a function."""

    def __init__(self, path=None):
        path = path or default_library_path()
        if not os.path.isfile(path):
            raise LibraryUnavailable("EL_LIBRARY_MISSING", f"cannot load {path}: no such file")
        try:
            library_check.check(path)
        except library_check.Corrupt as e:
            raise LibraryUnavailable("EL_LIBRARY_CORRUPT", str(e)) from None
        except OSError as e:
            raise LibraryUnavailable("EL_LIBRARY_MISSING", f"cannot load {path}: {e}") from None
        try:
            lib = ctypes.CDLL(path)
        except OSError as e:
            raise LibraryUnavailable("EL_LIBRARY_MISSING", f"cannot load {path}: {e}") from None
        try:
            lib.el_abi_version.restype = ctypes.c_uint32
            version = lib.el_abi_version()
        except AttributeError:
            raise LibraryUnavailable("EL_ABI_MISMATCH", f"{path} is not libedgelight (no el_abi_version)") from None
        if version != ABI_VERSION:
            raise LibraryUnavailable("EL_ABI_MISMATCH", f"{path} has ABI version {version}, this add-on needs {ABI_VERSION}")
        missing = [name for name in _FUNCTIONS if not hasattr(lib, name)]
        if missing:
            shown = ", ".join(missing[:5]) + (f" and {len(missing) - 5} more" if len(missing) > 5 else "")
            raise LibraryUnavailable("EL_ABI_MISMATCH", f"{path} has ABI version {version} but lacks "
                                     f"functions this add-on calls: {shown}")
        for name, (args, restype) in _FUNCTIONS.items():
            fn = getattr(lib, name)
            fn.argtypes = args
            fn.restype = restype
        self.lib = lib
        self.path = path

    def call(self, name, *args):
        status = getattr(self.lib, name)(*args)
        if status != 0:
            raise NativeError(self.lib.el_status_name(status).decode(), self.lib.el_last_error().decode())


_loaded = {}


def load(path=None):
    """The library at `path` (default_library_path()), loaded once per path."""
    path = path or default_library_path()
    if path not in _loaded:
        _loaded[path] = Library(path)
    return _loaded[path]


def _ptr(array, ctype):
    return array.ctypes.data_as(ctypes.POINTER(ctype)) if array is not None else None


def _address(array):
    """A C-contiguous array's address (None: NULL), for c_void_p fields."""
    return array.ctypes.data if array is not None else None


def _contiguous(array, dtype, columns=None):
    if array is None:
        return None
    a = np.ascontiguousarray(array, dtype=dtype)
    return a.reshape(-1, columns) if columns else a.reshape(-1)


class _Handle:
    _destroy = ""
    _h = None  # stays None when the constructor fails, so __del__ has nothing to free

    def __init__(self, lib, handle):
        self._lib = lib
        self._h = handle

    def close(self):
        if self._h:
            getattr(self._lib.lib, self._destroy)(self._h)
            self._h = None

    def __del__(self):
        self.close()


class Mesh(_Handle):
    """A mesh's topology and static edge classification (el_mesh)."""
    _destroy = "el_mesh_destroy"

    def __init__(self, positions, triangles, *, edges=None, triangle_edges=None, edge_marks=None,
                 bevel_weights=None, triangle_materials=None, vertex_normals=None, triangle_normals=None,
                 lib=None):
        lib = lib or load()
        keep = {
            "positions": _contiguous(positions, np.float32, 3),
            "triangles": _contiguous(triangles, np.uint32, 3) if triangles is not None else np.zeros((0, 3), np.uint32),
            "edges": _contiguous(edges, np.uint32, 2),
            "triangle_edges": _contiguous(triangle_edges, np.uint32, 3),
            "edge_marks": _contiguous(edge_marks, np.uint32),
            "bevel_weights": _contiguous(bevel_weights, np.float32),
            "triangle_materials": _contiguous(triangle_materials, np.uint32),
            "vertex_normals": _contiguous(vertex_normals, np.float32, 3),
            "triangle_normals": _contiguous(triangle_normals, np.float32, 3),
        }
        d = MeshDesc()
        d.positions = _ptr(keep["positions"], ctypes.c_float)
        d.vertex_count = len(keep["positions"])
        d.triangles = _ptr(keep["triangles"], ctypes.c_uint32) if len(keep["triangles"]) else None
        d.triangle_count = len(keep["triangles"])
        if keep["edges"] is not None:
            d.edges = _ptr(keep["edges"], ctypes.c_uint32)
            d.edge_count = len(keep["edges"])
            d.triangle_edges = _ptr(keep["triangle_edges"], ctypes.c_uint32) if d.triangle_count else None
        d.edge_marks = _ptr(keep["edge_marks"], ctypes.c_uint32)
        d.edge_bevel_weights = _ptr(keep["bevel_weights"], ctypes.c_float)
        d.triangle_materials = _ptr(keep["triangle_materials"], ctypes.c_uint32)
        d.vertex_normals = _ptr(keep["vertex_normals"], ctypes.c_float)
        d.triangle_normals = _ptr(keep["triangle_normals"], ctypes.c_float)
        handle = _P()
        lib.call("el_mesh_create", ctypes.byref(d), ctypes.byref(handle))
        super().__init__(lib, handle)

    def classify(self, crease_angle_deg):
        self._lib.call("el_mesh_classify", self._h, float(crease_angle_deg))

    def info(self):
        i = MeshInfo()
        self._lib.call("el_mesh_get_info", self._h, ctypes.byref(i))
        return {name: getattr(i, name) for name, _ in MeshInfo._fields_}

    def _per_edge(self, fn, dtype, columns):
        n = self.info()["edge_count"]
        out = np.empty((n, columns) if columns > 1 else n, dtype=dtype)
        self._lib.call(fn, self._h, _ptr(out, np.ctypeslib.as_ctypes_type(dtype)), n)
        return out

    def edges(self):
        return self._per_edge("el_mesh_get_edges", np.uint32, 2)

    def edge_flags(self):
        return self._per_edge("el_mesh_get_edge_flags", np.uint32, 1)

    def edge_normals(self):
        """(E, 6): N1 xyz, N2 xyz per edge."""
        return self._per_edge("el_mesh_get_edge_normals", np.float32, 6)

    def edge_angles(self):
        return self._per_edge("el_mesh_get_edge_angles", np.float32, 1)

    def face_normals(self):
        """(T, 3) unit face normals (zero for degenerate faces)."""
        n = self.info()["triangle_count"]
        out = np.empty((n, 3), dtype=np.float32)
        self._lib.call("el_mesh_get_face_normals", self._h, _ptr(out, ctypes.c_float), n)
        return out

    def triangle_flips(self):
        """(T,) uint8: 1 where the library reversed the triangle's winding to orient its component."""
        n = self.info()["triangle_count"]
        out = np.empty(n, dtype=np.uint8)
        self._lib.call("el_mesh_get_triangle_flips", self._h, _ptr(out, ctypes.c_uint8), n)
        return out

    def select_edges(self, all_of=0, any_of=0):
        count = ctypes.c_uint32()
        self._lib.call("el_mesh_select_edges", self._h, all_of, any_of, None, 0, ctypes.byref(count))
        out = np.empty(count.value, dtype=np.uint32)
        if count.value:
            self._lib.call("el_mesh_select_edges", self._h, all_of, any_of, _ptr(out, ctypes.c_uint32), count.value, ctypes.byref(count))
        return out


    def chain_edges(self, edges):
        """Chains of the given edge indices: (links per edge, chains) as CHAIN_LINK / CHAIN records."""
        edges = np.ascontiguousarray(edges, dtype=np.uint32)
        links = np.zeros(len(edges), CHAIN_LINK)
        chains = np.zeros(len(edges), CHAIN)
        count = ctypes.c_uint32()
        self._lib.call("el_mesh_chain_edges", self._h, _ptr(edges, ctypes.c_uint32), len(edges),
                       links.ctypes.data, chains.ctypes.data, len(chains), ctypes.byref(count))
        return links, chains[:count.value]


def make_camera(*, object_to_world, eye=None, view_dir=None):
    """An el_camera: perspective from `eye`, or orthographic along `view_dir` (world space)."""
    c = Camera()
    m = np.asarray(object_to_world, dtype=np.float32).reshape(4, 4)
    c.object_to_world[:] = m.ravel().tolist()  # row-major, column vectors: numpy's Matrix layout
    if eye is not None:
        c.projection = PERSPECTIVE
        c.eye[:] = [float(v) for v in eye]
    else:
        c.projection = ORTHOGRAPHIC
        c.view_dir[:] = [float(v) for v in view_dir]
    return c


class View(_Handle):
    """Per-view silhouettes and contours of one mesh, cached on the camera (el_view)."""
    _destroy = "el_view_destroy"

    def __init__(self, mesh):
        handle = _P()
        mesh._lib.call("el_view_create", mesh._h, ctypes.byref(handle))
        super().__init__(mesh._lib, handle)
        self.mesh = mesh

    def update(self, camera, what=VIEW_SILHOUETTES | VIEW_CONTOURS):
        """Returns True when the outputs changed (so the caller re-uploads only then)."""
        changed = ctypes.c_uint32()
        self._lib.call("el_view_update", self._h, ctypes.byref(camera), what, ctypes.byref(changed))
        return bool(changed.value)

    def silhouettes(self):
        count = ctypes.c_uint32()
        self._lib.call("el_view_get_silhouettes", self._h, None, 0, ctypes.byref(count))
        out = np.empty(count.value, dtype=np.uint32)
        self._lib.call("el_view_get_silhouettes", self._h, _ptr(out, ctypes.c_uint32), count.value, ctypes.byref(count))
        return out

    def contours(self):
        """(S, 2, 3) object-space segment endpoints and (S,) triangles."""
        count = ctypes.c_uint32()
        self._lib.call("el_view_get_contours", self._h, None, None, 0, ctypes.byref(count))
        pts = np.empty((count.value, 2, 3), dtype=np.float32)
        tris = np.empty(count.value, dtype=np.uint32)
        self._lib.call("el_view_get_contours", self._h, _ptr(pts, ctypes.c_float), _ptr(tris, ctypes.c_uint32), count.value, ctypes.byref(count))
        return pts, tris

    def contour_chains(self):
        """Chains of the current contour segments (in contours() order)."""
        n = self.stats()["contour_segments"]
        links = np.zeros(n, CHAIN_LINK)
        chains = np.zeros(n, CHAIN)
        count = ctypes.c_uint32()
        self._lib.call("el_view_chain_contours", self._h, links.ctypes.data, n, chains.ctypes.data, n, ctypes.byref(count))
        return links, chains[:count.value]

    def stats(self):
        s = ViewStats()
        self._lib.call("el_view_get_stats", self._h, ctypes.byref(s))
        return {name: getattr(s, name) for name, _ in ViewStats._fields_}


def _matrix16(m):
    return (ctypes.c_float * 16)(*np.asarray(m, np.float64).reshape(16))


class Outline(_Handle):
    """A mesh's convex rounded edges and corner patches (el_outline), from which the library moves
    each view's silhouettes onto the fillets' outline (el_outline_lines)."""
    _destroy = "el_outline_destroy"

    def __init__(self, edges, edge_vertices, corners, corner_vertices, lib=None):
        lib = lib or load()
        self._edges = _contiguous(edges, np.float32, 4 * OUTLINE_EDGE_TEXELS)
        self._edge_vertices = _contiguous(edge_vertices, np.uint32, 2)
        self._corners = _contiguous(corners, np.float32, 4 * OUTLINE_CORNER_TEXELS)
        self._corner_vertices = _contiguous(corner_vertices, np.uint32)
        if len(self._edges) != len(self._edge_vertices) or len(self._corners) != len(self._corner_vertices):
            raise ValueError(f"Outline: {len(self._edges)} edges with {len(self._edge_vertices)} vertex pairs, "
                             f"{len(self._corners)} corners with {len(self._corner_vertices)} vertices")
        d = OutlineDesc(_ptr(self._edges, ctypes.c_float), _ptr(self._edge_vertices, ctypes.c_uint32), len(self._edges),
                        _ptr(self._corners, ctypes.c_float), _ptr(self._corner_vertices, ctypes.c_uint32),
                        len(self._corners))
        handle = _P()
        lib.call("el_outline_create", ctypes.byref(d), ctypes.byref(handle))
        super().__init__(lib, handle)

    def __len__(self):
        return len(self._edges)

    def lines(self, vertices, p0, p1, n1, n2, taper, faces, links, matrix, camera):
        """el_outline_lines: segments along mesh edges (vertices (N, 2): p0's, p1's) seen by
        `camera` (passes.camera.Camera) through `matrix`, on the rounded outline: a dict of the
        arrays (p0, p1, n1, n2, taper, faces, links; faces and links None where given None)."""
        n = len(vertices)
        keep = [_contiguous(vertices, np.uint32, 2)] + [_contiguous(a, np.float32, 3) for a in (p0, p1, n1, n2)] + \
            [_contiguous(taper, np.float32, 2), _contiguous(faces, np.float32, 2)]
        links = np.ascontiguousarray(links, CHAIN_LINK) if links is not None else None
        if any(a is not None and len(a) != n for a in keep + [links]):
            raise ValueError(f"Outline.lines: arrays of {[None if a is None else len(a) for a in keep + [links]]} for {n} segments")
        ins = OutlineSegments(*(_address(a) for a in keep + [links]), n)
        cap = (2 + OUTLINE_ARC_MAX_PIECES) * n
        out = {k: np.empty((cap, c), np.float32) for k, c in (("p0", 3), ("p1", 3), ("n1", 3), ("n2", 3), ("taper", 2))}
        out["faces"] = np.empty((cap, 2), np.float32) if faces is not None else None
        out["links"] = np.empty(cap, CHAIN_LINK) if links is not None else None
        o = OutlineOut(*(_address(out[k]) for k in ("p0", "p1", "n1", "n2", "taper", "faces", "links")), cap)
        v = OutlineView(PERSPECTIVE if not camera.orthographic else ORTHOGRAPHIC)
        if camera.orthographic:
            v.view_dir[:] = [float(x) for x in camera.view_dir]
        else:
            v.eye[:] = [float(x) for x in camera.eye]
        v.object_to_world, v.world_to_view = _matrix16(matrix), _matrix16(camera.view)
        v.view_to_clip = _matrix16(camera.projection)
        v.width, v.height = float(camera.width), float(camera.height)
        count = ctypes.c_uint32()
        self._lib.call("el_outline_lines", self._h, ctypes.byref(v), ctypes.byref(ins), ctypes.byref(o), ctypes.byref(count))
        return {k: (a[:count.value] if a is not None else None) for k, a in out.items()}


def outline_views(matrices, camera):
    """OUTLINE_VIEW records of the instances' transforms `matrices` (N, 4, 4) seen by `camera`
    (passes.camera.Camera)."""
    m = np.asarray(matrices, np.float64).reshape(-1, 16)
    v = np.zeros(len(m), OUTLINE_VIEW)
    v["projection"] = ORTHOGRAPHIC if camera.orthographic else PERSPECTIVE
    if camera.orthographic:
        v["view_dir"] = np.asarray(camera.view_dir, np.float64)
    else:
        v["eye"] = np.asarray(camera.eye, np.float64)
    v["object_to_world"] = m
    v["world_to_view"] = np.asarray(camera.view, np.float64).reshape(16)
    v["view_to_clip"] = np.asarray(camera.projection, np.float64).reshape(16)
    v["width"], v["height"] = camera.width, camera.height
    return v


def view_lines(mesh, views, outline=None, edge_faces=None, taper=False):
    """el_view_lines: the silhouettes of instances of `mesh` (a Mesh) seen as `views`
    (outline_views), chained, on the rounded outline of `outline` (an Outline; None: on the
    sharp edges), carrying `edge_faces` ((E, 2) per mesh edge; None: no faces), tapered with
    `taper`: (offsets (N + 1,), {instance: the library's message} for those whose view failed
    (a singular transform, say: no segments), a dict of the concatenated arrays p0, p1, n1, n2,
    taper, faces (None without edge_faces), links)."""
    lib = mesh._lib
    views = np.ascontiguousarray(views, OUTLINE_VIEW)
    faces = _contiguous(edge_faces, np.float32, 2)
    if faces is not None and len(faces) != mesh.info()["edge_count"]:
        raise ValueError(f"view_lines: {len(faces)} face pairs for {mesh.info()['edge_count']} edges")
    desc = ViewLinesDesc(mesh._h.value, outline._h.value if outline is not None else None, _address(faces),
                         _address(views), len(views), VIEW_LINES_TAPER if taper else 0)
    handle = _P()
    lib.call("el_view_lines_create", ctypes.byref(desc), ctypes.byref(handle))
    try:
        offsets = np.empty(len(views) + 1, np.uint32)
        status = np.empty(len(views), np.int32)
        lib.call("el_view_lines_get_offsets", handle, _ptr(offsets, ctypes.c_uint32), len(offsets),
                 _ptr(status, ctypes.c_int32))
        total = int(offsets[-1])
        out = {k: np.empty((total, c), np.float32) for k, c in (("p0", 3), ("p1", 3), ("n1", 3), ("n2", 3), ("taper", 2))}
        out["faces"] = np.empty((total, 2), np.float32) if faces is not None else None
        out["links"] = np.empty(total, CHAIN_LINK)
        o = OutlineOut(*(_address(out[k]) for k in ("p0", "p1", "n1", "n2", "taper", "faces", "links")), total)
        lib.call("el_view_lines_copy", handle, ctypes.byref(o))
        failed = {}
        for i in np.flatnonzero(status):
            message = ctypes.c_char_p()
            lib.call("el_view_lines_get_message", handle, int(i), ctypes.byref(message))
            failed[int(i)] = f"{lib.lib.el_status_name(int(status[i])).decode()}: {message.value.decode()}"
    finally:
        lib.lib.el_view_lines_destroy(handle)
    return offsets.astype(np.int64), failed, out


def outline_fans(tri_verts, tri_normals, item_verts, item_normals, per, cos_max, own_sides=False, lib=None):
    """el_outline_fans: (T, per) float32, per triangle (tri_verts (T, 3), tri_normals (T, 3), in
    the surface batch's order) the items (item_verts (N, k), -1 none; item_normals (N, m, 3)) at
    its corners lying flat with it or, with own_sides, along its own sides, as item + 1."""
    lib = lib or load()
    tv = _contiguous(tri_verts, np.uint32, 3)
    tn = _contiguous(tri_normals, np.float32, 3)
    if len(tn) != len(tv):
        raise ValueError(f"outline_fans: {len(tv)} triangles with {len(tn)} normals")
    iv = np.ascontiguousarray(item_verts, np.int32)
    normals = np.ascontiguousarray(item_normals, np.float32)
    out = np.zeros((len(tv), per), np.float32)
    if not len(iv):
        return out
    iv = iv.reshape(len(iv), -1)
    normals = normals.reshape(len(iv), -1, 3)
    lib.call("el_outline_fans", _ptr(tv, ctypes.c_uint32), _ptr(tn, ctypes.c_float), len(tv),
             iv.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), iv.shape[1], _ptr(normals, ctypes.c_float),
             normals.shape[1], len(iv), OUTLINE_FANS_OWN_SIDES if own_sides else 0, float(cos_max), per,
             _ptr(out, ctypes.c_float))
    return out


def corner_patches(positions, edges, edge_normals, convex, chosen, radius, stop=None, lib=None):
    """el_corner_patches: a dict of the corners' vertex (K,), edges (K, 3), normals (K, 3, 3),
    radius (K,), centre (K, 3) and fold (K,). positions (V, 3), edges (E, 2), edge_normals (E, 6);
    convex, chosen, stop (E,) booleans (stop None: the chosen); radius (E,)."""
    lib = lib or load()
    p = _contiguous(positions, np.float32, 3)
    e = _contiguous(edges, np.uint32, 2)
    n = _contiguous(edge_normals, np.float32, 6)
    flags = [None if a is None else np.ascontiguousarray(a, np.uint8) for a in (convex, chosen, stop)]
    r = _contiguous(radius, np.float32)
    if len(n) != len(e) or len(r) != len(e) or any(a is not None and len(a) != len(e) for a in flags):
        raise ValueError(f"corner_patches: {len(e)} edges with {len(n)} normal pairs and {len(r)} radii")
    cap = len(p)
    out = {"vertex": np.empty(cap, np.uint32), "edges": np.empty((cap, 3), np.uint32),
           "normals": np.empty((cap, 3, 3), np.float32), "radius": np.empty(cap, np.float32),
           "centre": np.empty((cap, 3), np.float32), "fold": np.empty(cap, np.float32)}
    count = ctypes.c_uint32()
    lib.call("el_corner_patches", _ptr(p, ctypes.c_float), len(p), _ptr(e, ctypes.c_uint32), _ptr(n, ctypes.c_float),
             *(_ptr(a, ctypes.c_uint8) for a in flags[:2]), _ptr(r, ctypes.c_float), _ptr(flags[2], ctypes.c_uint8),
             len(e), cap, _ptr(out["vertex"], ctypes.c_uint32), _ptr(out["edges"], ctypes.c_uint32),
             *(_ptr(out[k], ctypes.c_float) for k in ("normals", "radius", "centre", "fold")), ctypes.byref(count))
    return {k: a[:count.value] for k, a in out.items()}


def _polygons(polys):
    """(Polygons, the arrays it points into) of radius_clamp.Polygons `polys`."""
    keep = {k: _contiguous(getattr(polys, k), np.uint32) for k in ("start", "total", "loop_vert", "loop_edge", "tri_poly")
            if getattr(polys, k) is not None}
    keep["normal"] = _contiguous(polys.normal, np.float32, 3)
    n = {k: len(a) for k, a in keep.items() if a is not None}
    if n.get("total", 0) != n.get("start", 0) or ("normal" in n and n["normal"] != n["start"]) \
            or ("loop_edge" in n and n["loop_edge"] != n.get("loop_vert", 0)):
        raise ValueError(f"polygons of inconsistent lengths: {n}")
    pd = Polygons(_ptr(keep.get("start"), ctypes.c_uint32), _ptr(keep.get("total"), ctypes.c_uint32), n.get("start", 0),
                  _ptr(keep.get("loop_vert"), ctypes.c_uint32), _ptr(keep.get("loop_edge"), ctypes.c_uint32),
                  n.get("loop_vert", 0), _ptr(keep.get("tri_poly"), ctypes.c_uint32), n.get("tri_poly", 0),
                  _ptr(keep.get("normal"), ctypes.c_float))
    return pd, keep


def edge_rules(flags, angles, face_a, face_b, sharp, bevel, tri_slot, slots, lib=None):
    """el_edge_rules: which edges the material slots round. slots: per slot (enabled, radius, K,
    RULE_* bits, angle_deg). A dict of per-edge arrays: chosen (bool), radius (inf where no
    slot picks it), slot_a, slot_b, pick_a, pick_b (bool), rad_a, rad_b."""
    lib = lib or load()
    n = len(flags)
    f = _contiguous(flags, np.uint32)
    ang = _contiguous(angles, np.float32)
    fa, fb = (np.ascontiguousarray(a, np.int32) for a in (face_a, face_b))
    sh = np.ascontiguousarray(sharp, np.uint8)
    bv = _contiguous(bevel, np.float32)
    ts = _contiguous(tri_slot, np.uint32)
    if any(len(a) != n for a in (ang, fa, fb, sh, bv)):
        raise ValueError(f"edge_rules: arrays of {[len(a) for a in (f, ang, fa, fb, sh, bv)]} for {n} edges")
    rules = (SlotRules * max(len(slots), 1))(*(SlotRules(int(bool(e)), float(r), float(k), int(b), float(a))
                                               for e, r, k, b, a in slots))
    out = {"chosen": np.empty(n, np.uint8), "radius": np.empty(n, np.float32), "slot_a": np.empty(n, np.uint32),
           "slot_b": np.empty(n, np.uint32), "pick_a": np.empty(n, np.uint8), "pick_b": np.empty(n, np.uint8),
           "rad_a": np.empty(n, np.float32), "rad_b": np.empty(n, np.float32)}
    i32 = ctypes.POINTER(ctypes.c_int32)
    ptr = {np.dtype(np.uint8): ctypes.c_uint8, np.dtype(np.uint32): ctypes.c_uint32, np.dtype(np.float32): ctypes.c_float}
    lib.call("el_edge_rules", _ptr(f, ctypes.c_uint32), _ptr(ang, ctypes.c_float), fa.ctypes.data_as(i32),
             fb.ctypes.data_as(i32), _ptr(sh, ctypes.c_uint8), _ptr(bv, ctypes.c_float), n, _ptr(ts, ctypes.c_uint32),
             len(ts), rules, len(slots), *(_ptr(a, ptr[a.dtype]) for a in out.values()))
    for k in ("chosen", "pick_a", "pick_b"):
        out[k] = out[k].astype(bool)
    return out


def width_bounds(polys, positions, edges, edge_polys, lib=None):
    """el_width_bounds: (N, 2) float64, for edges (N, 2) vertex pairs whose polygons are
    edge_polys (N, 2) (-1: none, 0), the farthest of three of each polygon's corners from the
    edge's line."""
    lib = lib or load()
    pd, keep = _polygons(polys)
    p = _contiguous(positions, np.float32, 3)
    e = _contiguous(edges, np.uint32, 2)
    ep = np.ascontiguousarray(edge_polys, np.int32).reshape(-1, 2)
    if len(ep) != len(e):
        raise ValueError(f"width_bounds: {len(e)} edges with {len(ep)} polygon pairs")
    out = np.zeros((len(e), 2), np.float64)
    lib.call("el_width_bounds", ctypes.byref(pd), _ptr(p, ctypes.c_float), len(p), _ptr(e, ctypes.c_uint32),
             ep.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), len(e), out.ctypes.data_as(ctypes.POINTER(ctypes.c_double)))
    return out


def band_ends(polys, positions, edges, edge_normals, rounded, selected, faces, smooth=None, edge_polys=None,
              lib=None):
    """el_band_ends: (N, 4) float32 cut angles of the selected edges' bands. polys: the mesh's
    polygons (radius_clamp.Polygons: start, total, loop_vert, loop_edge, tri_poly, normal);
    positions (V, 3), edges (E, 2), edge_normals (E, 6), rounded (E,) bool; selected (N,), faces
    (N, 2) their triangles (-1 none); smooth (E,) bool and edge_polys (E, 2): faces as smooth
    patches."""
    lib = lib or load()
    pd, keep = _polygons(polys)
    p = _contiguous(positions, np.float32, 3)
    e = _contiguous(edges, np.uint32, 2)
    n = _contiguous(edge_normals, np.float32, 6)
    r = np.ascontiguousarray(rounded, np.uint8)
    sm = None if smooth is None else np.ascontiguousarray(smooth, np.uint8)
    ep = None if edge_polys is None else np.ascontiguousarray(edge_polys, np.int32).reshape(-1, 2)
    sel = _contiguous(selected, np.uint32)
    f = np.ascontiguousarray(faces, np.int32).reshape(-1, 2)
    if len(n) != len(e) or len(r) != len(e) or len(f) != len(sel) or any(a is not None and len(a) != len(e)
                                                                          for a in (sm, ep)):
        raise ValueError(f"band_ends: {len(e)} edges, {len(n)} normal pairs, {len(r)} flags, {len(sel)} selected "
                         f"with {len(f)} face pairs")
    out = np.empty((len(sel), 4), np.float32)
    i32 = ctypes.POINTER(ctypes.c_int32)
    lib.call("el_band_ends", ctypes.byref(pd), _ptr(p, ctypes.c_float), len(p), _ptr(e, ctypes.c_uint32),
             _ptr(n, ctypes.c_float), _ptr(r, ctypes.c_uint8), _ptr(sm, ctypes.c_uint8),
             ep.ctypes.data_as(i32) if ep is not None else None, len(e), _ptr(sel, ctypes.c_uint32),
             f.ctypes.data_as(i32), len(sel), _ptr(out, ctypes.c_float))
    return out


def shading_normals(positions, edges, edge_normals, edge_faces, tri_verts, corner_normals, selected, max_turn_deg,
                    lib=None):
    """el_shading_normals: (N, 2, 6) float32, per selected edge at its first vertex and then its
    second, the normals (N1, N2) its band's arc runs between. positions (V, 3), edges (E, 2),
    edge_normals (E, 6), edge_faces (E, 2) each edge's first two triangles (-1: none), tri_verts
    (T, 3), corner_normals (T, 3, 3), selected (N,) edge indices."""
    lib = lib or load()
    p = _contiguous(positions, np.float32, 3)
    e = _contiguous(edges, np.uint32, 2)
    n = _contiguous(edge_normals, np.float32, 6)
    f = np.ascontiguousarray(edge_faces, np.int32).reshape(-1, 2)
    t = _contiguous(tri_verts, np.uint32, 3)
    c = _contiguous(corner_normals, np.float32, 9)
    sel = _contiguous(selected, np.uint32)
    if len(n) != len(e) or len(f) != len(e) or len(c) != len(t):
        raise ValueError(f"shading_normals: {len(e)} edges with {len(n)} normal pairs and {len(f)} face pairs, "
                         f"{len(t)} triangles with {len(c)} corner normal triples")
    out = np.empty((len(sel), 2, 6), np.float32)
    lib.call("el_shading_normals", _ptr(p, ctypes.c_float), len(p), _ptr(e, ctypes.c_uint32), _ptr(n, ctypes.c_float),
             f.ctypes.data_as(ctypes.POINTER(ctypes.c_int32)), len(e), _ptr(t, ctypes.c_uint32), _ptr(c, ctypes.c_float),
             len(t), _ptr(sel, ctypes.c_uint32), len(sel), float(max_turn_deg), _ptr(out, ctypes.c_float))
    return out


def fillet_outline(na, nb, v, lib=None):
    """el_fillet_outline: (P, C, silhouette) of convex fillets of radius 1 between faces of unit
    normals na, nb (N, 3) seen along v (unit, towards the eye)."""
    lib = lib or load()
    na, nb, v = (_contiguous(a, np.float32, 3) for a in (na, nb, v))
    n = len(na)
    if len(nb) != n or len(v) != n:
        raise ValueError(f"fillet_outline: {n}, {len(nb)} and {len(v)} vectors")
    p, c = np.empty((n, 3), np.float32), np.empty((n, 3), np.float32)
    sil = np.empty(n, np.uint8)
    lib.call("el_fillet_outline", *(_ptr(a, ctypes.c_float) for a in (na, nb, v)), n, _ptr(p, ctypes.c_float),
             _ptr(c, ctypes.c_float), _ptr(sil, ctypes.c_uint8))
    return p, c, sil.astype(bool)


class HighlightTable(_Handle):
    """The F(phi, m) table (el_highlight_table), ready to upload as an R32F texture."""
    _destroy = "el_highlight_table_destroy"

    # Recommended default, EL_TABLE_DEFAULT_DESC (docs/highlight_math.md, "Table study"): bicubic
    # 96 x 128, exponents 1..10001, max error 1.1e-6.
    def __init__(self, layout=TABLE_BICUBIC, phi_count=96, m_count=128, m_max=10001.0, lib=None):
        lib = lib or load()
        d = TableDesc(layout, phi_count, m_count, m_max)
        handle = _P()
        lib.call("el_highlight_table_create", ctypes.byref(d), ctypes.byref(handle))
        super().__init__(lib, handle)

    def info(self):
        i = TableInfo()
        self._lib.call("el_highlight_table_get_info", self._h, ctypes.byref(i))
        return {name: getattr(i, name) for name, _ in TableInfo._fields_}

    def data(self):
        """(m_count, phi_count) float32, row-major."""
        i = self.info()
        out = np.empty((i["m_count"], i["phi_count"]), dtype=np.float32)
        self._lib.call("el_highlight_table_copy", self._h, _ptr(out, ctypes.c_float), out.size)
        return out

    def evaluate(self, inputs):
        """Float32 path for an array of HighlightInput; returns an array of HighlightResult."""
        n = len(inputs)
        arr_in = (HighlightInput * n)(*inputs)
        arr_out = (HighlightResult * n)()
        self._lib.call("el_highlight_eval_batch", self._h, arr_in, n, arr_out)
        return arr_out


def line_nodes(p0, p1, taper, links=None, chain_spheres=False, lib=None):
    """The line pass's records of segments p0 -> p1 (N, 3) with taper values (N, 2) and their
    chain records (CHAIN_LINK, or None: each segment its own chain), el_line_nodes: (nodes (N,
    LINE_NODE_FLOATS) float32 in chain order, order (N,) the segment at each place)."""
    lib = lib or load()
    p0 = _contiguous(p0, np.float32, 3)
    p1 = _contiguous(p1, np.float32, 3)
    taper = _contiguous(taper, np.float32, 2)
    n = len(p0)
    if len(p1) != n or len(taper) != n:
        raise ValueError(f"line_nodes: {n} starts, {len(p1)} ends, {len(taper)} taper pairs")
    if links is not None:
        links = np.ascontiguousarray(links, CHAIN_LINK)
        if len(links) != n:
            raise ValueError(f"line_nodes: {len(links)} chain records for {n} segments")
    nodes = np.empty((n, LINE_NODE_FLOATS), np.float32)
    order = np.empty(n, np.uint32)
    lib.call("el_line_nodes", _ptr(p0, ctypes.c_float), _ptr(p1, ctypes.c_float), _ptr(taper, ctypes.c_float),
             links.ctypes.data if links is not None else None, n, LINE_NODES_CHAIN_SPHERES if chain_spheres else 0,
             _ptr(nodes, ctypes.c_float), n, _ptr(order, ctypes.c_uint32))
    return nodes, order


def highlight_reference(inp, lib=None):
    """Double-precision reference for one HighlightInput."""
    lib = lib or load()
    out = HighlightResult()
    lib.call("el_highlight_reference", ctypes.byref(inp), ctypes.byref(out))
    return out
