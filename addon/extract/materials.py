"""What the passes need to know about a material, read once per frame."""
import math
import os
from dataclasses import dataclass, replace

import bpy

from .. import compat
from ..bridge import shader_specs
from . import color_ramp, material_inputs, node_program, textures
from . import material_defaults as defaults

DEFAULT_COLOR = (0.8, 0.8, 0.8)  # Principled BSDF's Base Color
# The surface program's shading modes (shaders/surface_modes.json), keyed as the material's
# `shading` setting.
SURFACE_MODES = shader_specs.enum("surface_modes.json", "EL_SURFACE_MODE")
ALPHA = shader_specs.enum("surface_modes.json", "EL_ALPHA")


@dataclass(frozen=True)
class Toon:
    mode: int              # SURFACE_MODES: PHONG, RAMP or XTOON
    ramp: tuple = ()       # ((position, (r, g, b)), ...) sorted by position
    smooth: bool = False   # the ramp interpolates between stops
    image: object = None   # X-Toon bpy.types.Image, or None for the built-in map
    orientation: bool = False  # X-Toon y axis: N.V instead of depth
    near: float = 1.0
    far: float = 20.0


PHONG = Toon(SURFACE_MODES["PHONG"])


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
    pass_index: int = 0    # the material's Pass Index (the Material Index render pass)
    texture: object = None  # BaseTexture: an image drawn into Base Color by the surface pass
    emission: tuple = (0.0, 0.0, 0.0)  # Emission colour x strength, scene-linear radiance
    shadow: str = 'OPAQUE'  # compat.shadow_mode: 'OPAQUE', 'CUT' (by its image's alpha) or 'NONE'


@dataclass(frozen=True)
class BaseTexture:
    """An image or a colour attribute in a material's node chains into Base Color, Metallic or
    Roughness, as the surface pass, the bands and the corner patches draw it (EL_BASE_TEXTURE):
    its node program (node_program.Program) gives base colour, metallic and roughness per pixel,
    split as shading_of splits the values. The Shading's own colours take the program at the
    image's mean colour (and a white attribute), for what draws the material without them (toon
    shading, its default ramp stops)."""
    source: object         # material_inputs.ImageInput, or None: the program reads no image
    program: object        # node_program.Program
    f0: float              # the dielectric F0: 0.08 x Specular
    shininess: float = -1.0  # the material's own Blinn exponent (Custom Shininess); -1: from roughness
    alpha: int = 0         # EL_ALPHA (surface_modes.json): how its alpha, fed into Alpha too, cuts
    alpha_threshold: float = 0.5  # EL_ALPHA_CLIP's
    shadow_alpha: int = 0  # EL_ALPHA of its shadow (compat.shadow_mode: a cut shadow), by the same alpha


def default_ramp(base):
    """Two bands from the material's colour: a shadow at a third of it, lit from N.L = 0.5."""
    return ((0.0, tuple(0.35 * c for c in base)), (0.5, tuple(base)))


def toon_of(settings, base):
    mode = SURFACE_MODES[settings.shading]
    if mode == PHONG.mode:
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
    return material_inputs.principled_of(material)[0]


def chains_of(node):
    """What the node chains linked into a Principled BSDF's inputs come to (node_program.read)."""
    return node_program.read(node, material_inputs.READ + material_inputs.EMISSION + material_inputs.NORMAL_INPUTS)


def unread_inputs(node):
    """[(short, long)] of what the Principled BSDF `node` sets that EdgeLight does not draw."""
    return material_inputs.unread_inputs(node, chains_of(node))


def unread(material):
    """[(short, long)] of what `material` sets that EdgeLight does not draw (material_inputs)."""
    node, said = material_inputs.principled_of(material)
    return said + (unread_inputs(node) if node is not None else [])


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
    if material is None:  # Principled BSDF's defaults (Specular 0.5, Roughness 0.5), EdgeLight's
        return Shading(DEFAULT_COLOR, 1.0, (0.08 * 0.5,) * 3, shininess_from_roughness(0.5),
                       defaults.ROUNDED, defaults.HIGHLIGHT_STRENGTH, defaults.RADIUS, defaults.TINT, defaults.EDGES,
                       defaults.ANGLE_DEG, Toon(SURFACE_MODES[defaults.SHADING]))
    node = _principled(material)
    image = program = None
    if node is not None:
        chains = chains_of(node)
        folded = _Folded(node, chains.values)
        program = chains.program
        image = program.image
        base = folded.color("Base Color", DEFAULT_COLOR)
        roughness = folded.scalar(0.5, "Roughness")
        metallic = folded.scalar(0.0, "Metallic")
        if program.outputs:  # the program at its images' mean colours, under a white attribute
            means = [(*textures.mean_color(i.image), 1.0) for i in program.images]
            at_mean = node_program.run(program, means, (1.0, 1.0, 1.0, 1.0))
            base = tuple(at_mean["Base Color"][:3])
            metallic, roughness = at_mean["Metallic"][0], at_mean["Roughness"][0]
        # As the Principled BSDF takes them (material_program.glsl): no negative albedo; a chain
        # that computes no number (a NaN, an overflow) gives the socket's default.
        base = tuple(max(c, 0.0) if math.isfinite(c) else 0.0 for c in base)
        metallic = min(max(metallic, 0.0), 1.0) if math.isfinite(metallic) else 0.0
        roughness = min(max(roughness, 0.0), 1.0) if math.isfinite(roughness) else 0.5
        specular = folded.scalar(0.5, "Specular", "Specular IOR Level")  # renamed in 4.0
        # An image's alpha into Alpha cuts the surface (BaseTexture.alpha); the socket's own value,
        # left from before it was linked, is not the material's alpha.
        alpha = 1.0 if material_inputs.image_alpha(node, image) else folded.scalar(1.0, "Alpha")
        emission = emission_of(node, folded)
    else:
        emission = (0.0, 0.0, 0.0)
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
    if node is not None and program.outputs and toon.mode != PHONG.mode:
        # Toon shading draws no node program (passes/texture_variants.texture_key; an image's alpha still
        # cuts): said, as what is not drawn is.
        what = (f"its image '{image.image.name}' is drawn as its mean colour" if image is not None
                else "its colour attribute is drawn as white" if program.attribute is not None
                else "its Normal Map is not drawn")
        note = "; ".join(n for n in (note, f"material '{material.name}': {what} under toon shading") if n)
    note = "; ".join(n for n in (material_inputs.note(material, unread(material)), note) if n)
    # K is capped at K_MAX; a value stored past it (a linked file of an older layout, which
    # versioning leaves to its library, or a raw ID property) draws as the cap.
    alpha_mode, threshold, alpha_note = _alpha_mode(material, node, image)
    note = "; ".join(n for n in (note, alpha_note) if n)
    shadow, shadow_cut = compat.shadow_mode(material)
    shadow_alpha = (ALPHA[shadow_cut] if shadow == 'CUT' and node is not None and material_inputs.image_alpha(node, image)
                    else ALPHA["NONE"])
    texture = (BaseTexture(image, program, f0, float(n) if s.use_custom_shininess else -1.0, alpha_mode, threshold,
                           shadow_alpha) if program is not None and program.outputs else None)
    return Shading(albedo, alpha, spec, float(n), bool(s.use_rounding), min(float(s.K), defaults.K_MAX), float(s.radius),
                   tuple(s.tint), frozenset(s.selection), math.degrees(s.angle), toon, note, material.name_full,
                   int(material.pass_index), texture, emission, shadow)


def _alpha_mode(material, node, image):
    """(EL_ALPHA value, clip threshold, note) of a material whose image feeds its Alpha too:
    cut as EEVEE cuts it (compat.alpha_blend); Alpha Blend, which EdgeLight does not sort, is
    drawn hashed, which the samples average to the same coverage, and that is said."""
    if image is None or node is None or not material_inputs.image_alpha(node, image):
        return ALPHA["NONE"], 0.5, ""
    blend, threshold = compat.alpha_blend(material)
    if blend == 'OPAQUE':
        return ALPHA["NONE"], threshold, ""  # EEVEE ignores the alpha too
    if blend == 'CLIP':
        return ALPHA["CLIP"], threshold, ""
    note = (f"material '{material.name}': its blended alpha is drawn hashed (dithered), averaged over the samples"
            if blend == 'BLEND' else "")
    return ALPHA["HASHED"], threshold, note


class _Folded:
    """A Principled BSDF's input values: a linked input's folded chain (node_program), else its
    socket's value."""

    def __init__(self, node, values):
        self.node, self.values = node, values

    def _get(self, names):
        for name in names:
            if name in self.values:
                return self.values[name]
        return _input(self.node, *names)

    def scalar(self, default, *names):
        """A float input's value; `default` for none, or a chain that computes no number."""
        v = self._get(names)
        v = None if v is None else float(v if isinstance(v, (int, float)) else v[0])
        return v if v is not None and math.isfinite(v) else default

    def color(self, name, default):
        v = self._get((name,))
        v = None if v is None else tuple(float(c) for c in v[:3])
        return v if v is not None and all(math.isfinite(c) for c in v) else default

    def unfolded(self, *names):
        """Whether one of the inputs is linked to a chain that did not fold."""
        return any(n in self.node.inputs and self.node.inputs[n].is_linked and n not in self.values for n in names)


def emission_of(node, folded):
    """A Principled BSDF's emitted radiance: its Emission colour (3.4: Emission; 4.0+: Emission
    Color) x Emission Strength, the sockets' values or folded chains; none where a chain did not
    fold (4.0's unlinked colour is white: a texture's glow would be a white one), which
    material_inputs says."""
    if folded.unfolded(*material_inputs.EMISSION):
        return (0.0, 0.0, 0.0)
    color = folded.color("Emission Color", None) or folded.color("Emission", None)
    strength = folded.scalar(1.0, "Emission Strength")
    if color is None or not math.isfinite(strength):
        return (0.0, 0.0, 0.0)
    out = tuple(max(float(c), 0.0) * max(strength, 0.0) for c in color[:3])
    return out if all(math.isfinite(c) for c in out) else (0.0, 0.0, 0.0)


def usable_toon(material_name, toon):
    """The toon settings with anything unusable replaced by the default, and a note saying so:
    a bad setting falls back for its own material only, never blanks the frame."""
    image = toon.image
    if toon.mode != SURFACE_MODES["XTOON"] or image is None:
        return toon, ""
    missing = image_file_missing(image)
    if missing:
        return (replace(toon, image=None),
                f"material '{material_name}': X-Toon image '{image.name}': its file {missing} is not found; "
                f"the built-in map is used")
    w, h = image.size
    if w >= 2 and h >= 2 and image.channels >= 1:
        return toon, ""
    return (replace(toon, image=None),
            f"material '{material_name}': X-Toon image '{image.name}' is {w} x {h} (it needs at least "
            f"2 x 2 pixels); the built-in map is used")


def image_file_missing(image):
    """The path of an image's file when it reads from one that is not there (Blender then gives it
    a size of 0 x 0), else ""."""
    if image.source not in {'FILE', 'SEQUENCE', 'MOVIE'} or image.packed_file is not None:
        return ""
    path = bpy.path.abspath(image.filepath, library=image.library)
    return "" if os.path.exists(path) else f"'{image.filepath}'"
