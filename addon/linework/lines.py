"""Ink lines, CPU side: which edges each line type draws, their chains (for tapering at free
ends), and the view-dependent types (silhouettes, smooth contours) per instance and view.

Produces plain arrays (LineSegments); passes/line_pass.py turns their chains into quads at the
screen's resolution and draws them.
"""
from dataclasses import dataclass

import numpy as np

from ..bridge import native
from ..geometry import outline_lines
from ..geometry.edge_data import surface_ids

# Draw order; where two types share an edge the first drawn wins a tie (line_pass.py).
TYPES = ("silhouette", "border", "crease", "contour", "material", "marked")
VIEW_TYPES = frozenset({"silhouette", "contour"})
# Debug colours (the Edge Types view, properties.py): one per line type.
DEBUG_COLORS = {
    "silhouette": (1.0, 0.0, 0.0), "crease": (1.0, 1.0, 0.0), "border": (1.0, 1.0, 0.0),
    "contour": (0.0, 1.0, 1.0), "marked": (1.0, 0.0, 1.0), "material": (0.0, 1.0, 0.0),
    "wire": (0.1, 0.3, 1.0),
}
_MARK_BITS = {"FREESTYLE": native.MARK_FREESTYLE, "SHARP": native.MARK_SHARP, "SEAM": native.MARK_SEAM}
NO_TAPER = native.NO_TAPER  # taper parameter of an end with no free end on its chain (EL_NO_TAPER)


@dataclass(frozen=True)
class Style:
    color: tuple
    opacity: float
    width: float
    scene_units: bool
    min_pixels: float
    taper: float


@dataclass(frozen=True)
class LineSettings:
    styles: tuple              # ((type, Style), ...) of the drawn types, in draw order
    crease_deg: float
    marks: int                 # EL_MARK_* bits the marked type draws
    hidden_opacity: float      # 0: hidden lines are not drawn
    whiteout: bool = False

    @property
    def types(self):
        return tuple(t for t, _ in self.styles)

    def style(self, kind):
        return dict(self.styles).get(kind)

    def static_key(self):
        """What the static (view-independent) line sets depend on."""
        return (self.crease_deg, self.marks,
                tuple((t, s.taper > 0.0) for t, s in self.styles if t not in VIEW_TYPES))


def settings_of(scene_settings):
    """The scene's line settings, or None when no line is drawn."""
    s = scene_settings
    debug = set(s.debug)
    styles = []
    if s.use_lines or 'EDGE_TYPES' in debug:
        for kind in TYPES:
            p = getattr(s, "line_" + kind)
            if 'EDGE_TYPES' in debug:
                # Every type, in its own colour, opaque and at least 1.5 px wide.
                styles.append((kind, Style(DEBUG_COLORS[kind], 1.0, max(float(p.width), 1.5) if p.unit == 'PIXELS' else 1.5,
                                           False, 0.0, float(p.taper))))
            elif p.enabled and p.opacity > 0.0 and p.width > 0.0:
                styles.append((kind, Style(tuple(p.color), float(p.opacity), float(p.width), p.unit == 'SCENE',
                                           float(p.min_pixels), float(p.taper))))
    if 'WIRE' in debug:
        styles.append(("wire", Style(DEBUG_COLORS["wire"], 1.0, 1.0, False, 0.0, 0.0)))
    if not styles and 'WHITEOUT' not in debug:
        return None
    marks = 0
    for m in s.marks:
        marks |= _MARK_BITS[m]
    hidden = float(s.hidden_opacity) if s.hidden_lines == 'DIMMED' else 0.0
    import math
    return LineSettings(tuple(styles), math.degrees(s.crease_angle), marks, hidden, 'WHITEOUT' in debug)


@dataclass
class LineSegments:
    """Object-space segments of one line type: ends, the two face normals, per end the distance
    to its chain's nearest free end over the chain's length, and the faces the segment lies on
    as surface ids (MeshExtract.surface_ids: what the surface pass writes; 0 for none), which
    decide its visibility (docs/lines.md)."""
    p0: np.ndarray
    p1: np.ndarray
    n1: np.ndarray
    n2: np.ndarray
    taper: np.ndarray
    faces: np.ndarray = None           # (N, 2) float32
    # The library's chain record of each segment (native.CHAIN_LINK: chain, arc length at p0
    # and p1), from which the line pass puts segments in chain order; None: each its own chain.
    chain_links: np.ndarray = None

    def __len__(self):
        return len(self.p0)



def taper_params(links, chains):
    """(N, 2) distance from each item end to its chain's nearest free end / chain length."""
    if len(links) == 0:
        return np.zeros((0, 2), np.float32)
    c = chains[links["chain"]]
    length = np.maximum(c["length"], 1e-30)
    out = np.full((len(links), 2), NO_TAPER, np.float32)
    for k, s in enumerate((links["s0"], links["s1"])):
        d = np.full(len(links), np.inf)
        d = np.where(c["flags"] & native.CHAIN_START_FREE, np.minimum(d, s), d)
        d = np.where(c["flags"] & native.CHAIN_END_FREE, np.minimum(d, c["length"] - s), d)
        out[:, k] = np.where(np.isfinite(d), np.maximum(d, 0.0) / length, NO_TAPER)
    return out


def _edge_segments(edge_data, mesh, selected, taper):
    sel = np.flatnonzero(selected).astype(np.uint32)
    e = edge_data.edges[sel]
    n = edge_data.normals[sel]
    # Chains always: tapering needs them, and the line pass draws chains at the screen's
    # resolution (passes/line_pass.py).
    links, chains = mesh.chain_edges(sel) if len(sel) else (None, None)
    if taper and len(sel):
        t = taper_params(links, chains)
    else:
        t = np.full((len(sel), 2), NO_TAPER, np.float32)
    faces = np.stack([edge_data.face_a[sel], edge_data.face_b[sel]], axis=1)
    return LineSegments(edge_data.positions[e[:, 0]], edge_data.positions[e[:, 1]],
                        np.ascontiguousarray(n[:, :3]), np.ascontiguousarray(n[:, 3:]), t,
                        surface_ids(edge_data, faces), links)


def crease_edges(mesh, crease_deg):
    """Per edge of native.Mesh `mesh`, whether it is a crease at `crease_deg`: the library's rule
    (EL_EDGE_CREASE, classify.cpp: a manifold edge whose face normals differ by more than the
    angle, never a degenerate one or one between faces wound against each other), asked of the
    library so that the add-on holds no copy of it."""
    mesh.classify(crease_deg)
    return (mesh.edge_flags() & native.EDGE_CREASE) != 0


def static_lines(edge_data, mesh, settings):
    """Line type -> LineSegments for the view-independent types of `settings`."""
    if settings is None:
        return {}
    d = edge_data
    flags = d.flags
    usable = (flags & native.EDGE_DEGENERATE) == 0
    pick = {
        "border": (flags & native.EDGE_BORDER) != 0,
        "material": (flags & native.EDGE_MATERIAL_BOUNDARY) != 0,
        "marked": (flags & settings.marks) != 0,
        "wire": np.ones(len(flags), bool),
    }
    if "crease" in settings.types:
        pick["crease"] = crease_edges(mesh, settings.crease_deg)
    out = {}
    for kind, style in settings.styles:
        if kind in pick:
            out[kind] = _edge_segments(d, mesh, pick[kind] & usable, style.taper > 0.0)
    return out


def edge_faces(extract):
    """(E, 2) float32: the surface ids of each mesh edge's first two faces, what a line segment
    along it carries (surface_ids), made once per extraction."""
    derived = getattr(extract, "derived", None)
    if derived is not None and "edge faces" in derived:
        return derived["edge faces"]
    d = extract.edge_data
    out = surface_ids(d, np.stack([d.face_a, d.face_b], axis=1))
    if derived is not None:
        derived["edge faces"] = out
    return out


def silhouettes(extract, matrices, camera, taper, rounded):
    """Per instance of `extract` (its transforms `matrices`, (N, 4, 4)) seen from `camera`, its
    silhouettes as LineSegments (chained; tapered with `taper`), or, where its view failed (a
    singular transform, say), the library's message. One library call serves all of them
    (el_view_lines, instances in parallel). With `rounded` (the edge pass draws the bands, and the
    surface pass the fillets' outline), those along convex rounded edges lie on their fillets'
    outline (outline_lines.py)."""
    outline = outline_lines.outline_of(extract) if rounded and extract.edges else None
    offsets, failed, a = native.view_lines(extract.native, native.outline_views(matrices, camera),
                                           outline if outline is not None and len(outline) else None,
                                           edge_faces(extract), taper)
    out = []
    for i in range(len(offsets) - 1):
        if i in failed:
            out.append(failed[i])
            continue
        at = slice(int(offsets[i]), int(offsets[i + 1]))
        out.append(LineSegments(a["p0"][at], a["p1"][at], a["n1"][at], a["n2"][at], a["taper"][at],
                                a["faces"][at], a["links"][at]))
    return out


def contours(extract, index, matrix, camera, settings):
    """Smooth contours of instance `index` of `extract` seen from `camera`: LineSegments. One
    native view per instance (each sees the camera from its own object space), kept so an
    unchanged view costs the library a comparison."""
    views = extract.views.get(index)
    if views is None:
        views = extract.views[index] = native.View(extract.native)
    cam = native.make_camera(object_to_world=matrix, eye=None if camera.orthographic else camera.eye,
                             view_dir=camera.view_dir if camera.orthographic else None)
    views.update(cam, native.VIEW_CONTOURS)
    d = extract.edge_data
    pts, tris = views.contours()
    # Not across flat-shaded faces: their shading has no contour (the library interpolates
    # vertex normals everywhere).
    smooth = getattr(extract, "smooth_faces", None)
    keep = smooth[tris] if smooth is not None and len(tris) else np.ones(len(tris), bool)
    fn = extract.face_normals()[tris] if len(tris) else np.zeros((0, 3), np.float32)
    links, chains = views.contour_chains() if len(tris) else (np.zeros(0, native.CHAIN_LINK), None)
    if settings.style("contour").taper > 0.0 and len(tris):
        t = taper_params(links, chains)
    else:
        t = np.full((len(tris), 2), NO_TAPER, np.float32)
    faces = np.stack([tris, tris], axis=1) if len(tris) else np.zeros((0, 2), np.int64)
    return LineSegments(np.ascontiguousarray(pts[keep, 0]), np.ascontiguousarray(pts[keep, 1]),
                        fn[keep], fn[keep], t[keep], surface_ids(d, faces[keep]), links[keep])
