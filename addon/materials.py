"""What the passes need to know about a material, read once per frame."""
import math
import weakref
from dataclasses import dataclass, replace

import numpy as np

from . import color_ramp, compat
from .properties import K_MAX

DEFAULT_COLOR = (0.8, 0.8, 0.8)


@dataclass(frozen=True)
class Toon:
    mode: int              # 0 Blinn-Phong, 1 ramp, 2 X-Toon
    ramp: tuple = ()       # ((position, (r, g, b)), ...) sorted by position
    smooth: bool = False   # the ramp interpolates between stops
    image: object = None   # X-Toon bpy.types.Image, or None for the built-in map
    orientation: bool = False  # X-Toon y axis: N.V instead of depth
    near: float = 1.0
    far: float = 20.0


PHONG = Toon(0)


@dataclass(frozen=True)
class Shading:
    base_color: tuple      # rgb, scene-linear
    alpha: float
    spec_color: tuple      # rgb F0
    shininess: float       # Blinn exponent n
    # edge highlight
    enabled: bool
    K: float
    radius: float
    tint: tuple
    rules: frozenset       # {'ANGLE', 'SHARP', 'BEVEL'}
    angle_deg: float
    # toon shading
    toon: Toon = PHONG
    # A setting this material could not use, and what was used instead (a report line).
    note: str = ""
    material: str = ""     # the material's name_full ("" without one): keys the radius clamp notes


def default_ramp(base):
    """Two bands from the material's colour: a shadow at a third of it, lit from N.L = 0.5."""
    return ((0.0, tuple(0.35 * c for c in base)), (0.5, tuple(base)))


def toon_of(settings, base):
    mode = {'PHONG': 0, 'RAMP': 1, 'XTOON': 2}[settings.shading]
    if mode == 0:
        return PHONG
    stops, smooth = color_ramp.stops_of(settings)
    return Toon(mode, stops or default_ramp(base), smooth, settings.xtoon_image,
                settings.xtoon_axis == 'ORIENTATION', float(settings.xtoon_near), float(settings.xtoon_far))


def shininess_from_roughness(roughness):
    """Blinn-Phong exponent matching a GGX/Beckmann roughness: n = 2 / alpha^2 - 2, alpha = r^2."""
    alpha = max(roughness, 1e-3) ** 2
    return min(max(2.0 / (alpha * alpha) - 2.0, 1.0), 10000.0)


def _input(node, *names):
    for name in names:
        socket = node.inputs.get(name)
        if socket is not None and hasattr(socket, "default_value"):
            return socket.default_value
    return None


def _float(node, default, *names):
    v = _input(node, *names)
    return default if v is None else float(v)


def _principled(material):
    if not compat.uses_nodes(material):
        return None
    for node in material.node_tree.nodes:
        if node.type == 'BSDF_PRINCIPLED':
            return node
    return None


def base_color_of(material):
    """The colour EdgeLight shades a material with (before metallic): the Principled BSDF's Base
    Color, or the viewport colour without one."""
    node = _principled(material)
    if node is None:
        return tuple(material.diffuse_color[:3])
    c = _input(node, "Base Color")
    return tuple(c[:3]) if c is not None else DEFAULT_COLOR


def shading_of(material):
    """Shading for a material slot's material, or the default look when there is none."""
    if material is None:
        return Shading(DEFAULT_COLOR, 1.0, (0.04,) * 3, shininess_from_roughness(0.5),
                       True, 1.0, 0.01, (1.0, 1.0, 1.0), frozenset({'ANGLE', 'SHARP', 'BEVEL'}), 30.0, PHONG)
    node = _principled(material)
    if node is not None:
        base = base_color_of(material)
        roughness = _float(node, 0.5, "Roughness")
        metallic = _float(node, 0.0, "Metallic")
        specular = _float(node, 0.5, "Specular", "Specular IOR Level")  # renamed in 4.0
        alpha = _float(node, 1.0, "Alpha")
    else:
        base = tuple(material.diffuse_color[:3])
        alpha = float(material.diffuse_color[3])
        roughness = float(material.roughness)
        metallic = float(material.metallic)
        specular = float(material.specular_intensity)
    f0 = 0.08 * specular
    spec = tuple(f0 * (1.0 - metallic) + b * metallic for b in base)
    albedo = tuple(b * (1.0 - metallic) for b in base)
    s = material.edgelight
    n = s.shininess if s.use_custom_shininess else shininess_from_roughness(roughness)
    toon, note = usable_toon(material.name, toon_of(s, base))
    # K is capped at K_MAX; a value stored past it (a linked file of an older layout, which
    # versioning leaves to its library, or a raw ID property) draws as the cap.
    return Shading(albedo, alpha, spec, float(n), bool(s.use_rounding), min(float(s.K), K_MAX), float(s.radius),
                   tuple(s.tint), frozenset(s.selection), math.degrees(s.angle), toon, note, material.name_full)


# ---- radius clamp notes ------------------------------------------------------------------------
# What the material panel says about the radius clamp (ui.py): per material, how many of the
# edges it rounds take a smaller radius than its own because their faces allow no more
# (radius_clamp.py). scene_sync.choose_edges records each geometry's counts whenever it picks
# that geometry's rounded edges (extraction, or a material change in the viewport). Nothing is
# written to the material or saved: material name -> {id(geometry's edge data): RadiusClamps}.
_clamps = {}


@dataclass(frozen=True)
class RadiusClamps:
    radius: float          # the material's Radius when counted
    rounded: int           # edges of the geometry the material rounds (on either face)
    clamped: int           # of those, edges its faces allow less than that radius
    smallest: float        # the smallest radius an edge was clamped to (inf: none)
    geometry: object       # weakref to the geometry's edge data: alive while it is drawn


def record_radius_clamps(geometry, shading, sides, limit):
    """Records one geometry's counts for every material of `shading` (slot -> Shading).
    sides: ((slot, picked, radius) of the rounded edges' first faces, the same of their second),
    arrays over the rounded edges, `picked` whether that face's material rounds the edge and
    `radius` the radius it asks; limit: each rounded edge's largest radius (radius_clamp).
    An edge counts once for each material of its two faces."""
    for name in list(_clamps):  # geometries freed since the last call (a re-extracted mesh)
        entries = _clamps[name]
        for key in [k for k, e in entries.items() if e.geometry() is None]:
            del entries[key]
        if not entries:
            del _clamps[name]
    names = sorted({s.material for s in shading if s.material})
    if not names:
        return
    index = {name: i for i, name in enumerate(names)}
    of_slot = np.array([index.get(s.material, -1) for s in shading])
    (slot_a, pick_a, rad_a), (slot_b, pick_b, rad_b) = sides
    limit = np.asarray(limit, np.float64)
    mat_a, mat_b = of_slot[np.asarray(slot_a)], of_slot[np.asarray(slot_b)]
    rad_a = np.where(pick_a, np.asarray(rad_a, np.float64), math.inf)
    rad_b = np.where(pick_b, np.asarray(rad_b, np.float64), math.inf)
    # Clamped: the edge's radius (the smaller one its faces ask) is past the limit; it counts
    # for the faces' materials that asked more than the limit.
    cut = np.minimum(rad_a, rad_b) > limit
    over_a, over_b = cut & (rad_a > limit), cut & (rad_b > limit)
    second = mat_b != mat_a  # the second face's material is another one
    rounded, clamped, smallest = np.zeros(len(names), int), np.zeros(len(names), int), np.full(len(names), math.inf)
    for mat, touch, over in ((mat_a, np.ones(len(limit), bool), over_a | (over_b & ~second)),
                             (mat_b, second, over_b & second)):
        has = mat >= 0
        rounded += np.bincount(mat[has & touch], minlength=len(names))
        clamped += np.bincount(mat[has & over], minlength=len(names))
        np.minimum.at(smallest, mat[has & over], limit[has & over])
    ref = weakref.ref(geometry)
    radius_of = {s.material: s.radius for s in shading if s.material}
    for i, name in enumerate(names):
        _clamps.setdefault(name, {})[id(geometry)] = RadiusClamps(radius_of[name], int(rounded[i]), int(clamped[i]),
                                                                  float(smallest[i]), ref)


def radius_clamps(material):
    """(edges clamped, edges rounded, smallest clamped radius) of `material` over the geometries
    EdgeLight holds (the Rendered viewport's), else over those of the last render; None when
    nothing was counted at the material's current radius."""
    entries = list(_clamps.get(material.name_full, {}).values())
    live = [e for e in entries if e.geometry() is not None]
    radius = float(material.edgelight.radius)
    entries = [e for e in (live or entries) if e.radius == radius]
    if not entries:
        return None
    return (sum(e.clamped for e in entries), sum(e.rounded for e in entries), min(e.smallest for e in entries))


def usable_toon(material_name, toon):
    """The toon settings with anything unusable replaced by the default, and a note saying so:
    a bad setting falls back for its own material only, never blanks the frame."""
    image = toon.image
    if toon.mode != 2 or image is None:
        return toon, ""
    w, h = image.size
    if w >= 2 and h >= 2 and image.channels >= 1:
        return toon, ""
    return (replace(toon, image=None),
            f"material '{material_name}': X-Toon image '{image.name}' is {w} x {h} (it needs at least "
            f"2 x 2 pixels); the built-in map is used")
