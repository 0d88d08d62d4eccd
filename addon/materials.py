"""What the passes need to know about a material, read once per frame."""
import math
from dataclasses import dataclass, replace

from . import color_ramp, compat

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
    return Shading(albedo, alpha, spec, float(n), bool(s.use_rounding), float(s.K), float(s.radius),
                   tuple(s.tint), frozenset(s.selection), math.degrees(s.angle), toon, note)


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
