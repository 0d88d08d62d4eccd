"""The world's light as EdgeLight draws it (docs/addon.md, "The world"): the Background node's
colour times its strength, or an Environment Texture (equirectangular) in its Color, filtered
for lighting once per image (environment_filter.py) and drawn by shaders/environment.glsl. A
Mapping node between a Texture Coordinate's Generated (or nothing) and the image turns it, as
artists turn an HDRI. What is not read is said in one report line per world."""
import math
import zlib
from dataclasses import dataclass

import numpy as np

from . import environment_filter, material_inputs, textures
from .material_inputs import _from_node, _value, describe, feeding

# (image pointer, name, size, file, unsaved edits, colour space, the pixels' CRC) ->
# EnvironmentAtlas: the filter costs a few tenths of a second. The CRC: a new image may reuse a
# freed one's pointer, name and size (a generated image, a file reloaded), with other pixels.
_atlases = {}
# An 8k x 4k HDRI is read (512 MB of floats while it is filtered); a larger one is said, and the
# socket's colour lights the scene.
MAX_PIXELS = 8192 * 4096


@dataclass(frozen=True)
class Environment:
    atlas: environment_filter.EnvironmentAtlas
    strength: float
    rotation: np.ndarray  # 3x3: world direction -> the image's direction (before normalising)
    key: tuple            # what the atlas was filtered from: its GPU texture is kept by it

    def signature(self):
        """Everything of it that the image on screen depends on."""
        return (self.key, self.strength, self.rotation.tobytes())


@dataclass(frozen=True)
class WorldLight:
    ambient: tuple        # uniform radiance: the colour, or the environment's mean, times strength
    environment: object   # Environment, or None for a uniform world
    note: str             # the report line; "" when everything is read


NONE = WorldLight((0.0, 0.0, 0.0), None, "")


def read(world):
    """The WorldLight of a world (None: black)."""
    if world is None:
        return NONE
    background, surface = material_inputs.world_background(world)
    if surface is not None and surface is not background:
        used = (f"the Background '{background.name}' lights the scene" if background is not None
                else "the world's viewport colour lights the scene")
        note = f"world '{world.name}': its Surface is a {describe(surface)}, which EdgeLight does not read; {used}"
    else:
        note = ""
    if background is None:
        return WorldLight(tuple(float(v) for v in world.color), None, note)
    strength = float(background.inputs["Strength"].default_value)
    colour = background.inputs["Color"]
    source = _from_node(colour)
    env, said = (None, [])
    if source is not None and source.type == 'TEX_ENVIRONMENT':
        env, said = _environment(source, strength)
    elif source is not None:
        said.append(f"its Color comes from {describe(source)}, which EdgeLight does not read")
    if _from_node(background.inputs["Strength"]) is not None:
        said.append(f"its Strength comes from {describe(_from_node(background.inputs['Strength']))}, "
                    "which EdgeLight does not read")
    if env is not None:
        ambient = tuple(c * strength for c in env.atlas.mean)
    else:
        ambient = tuple(float(v) * strength for v in colour.default_value[:3])
    if said:
        used = ("the image lights the scene" if env is not None else
                f"the socket values (colour {_value(colour)}, strength {strength:.3g}) light the scene")
        note = (note + "; " if note else f"world '{world.name}': ") + "; ".join(said) + f"; {used}"
    return WorldLight(ambient, env, note)


def _environment(node, strength):
    """(Environment or None, [what is not read]) of an Environment Texture node."""
    image = node.image
    if image is None or material_inputs.image_unreadable(image):
        what = "has no image" if image is None else f"image '{image.name}' has no pixels"
        return None, [f"its Color comes from {describe(node)}, which {what}"]
    w, h = image.size
    if w * h > MAX_PIXELS:
        return None, [f"its Color comes from {describe(node)}, whose image '{image.name}' ({w} x {h}) is past the "
                      f"{MAX_PIXELS // 1_000_000} million pixels EdgeLight filters"]
    said = []
    if node.projection != 'EQUIRECTANGULAR':
        said.append(f"{describe(node)}'s {node.projection.replace('_', ' ').title()} projection is read as "
                    "Equirectangular")
    rotation, why = _mapping(node.inputs["Vector"])
    if why:
        said.append(why)
    try:
        atlas, key = _atlas(image)
    except (MemoryError, ValueError) as e:  # the render goes on under the socket's colour, and says why
        return None, [f"its Color comes from {describe(node)}, whose image '{image.name}' could not be filtered ({e})"]
    return Environment(atlas, strength, rotation, key), said


def _generated(socket):
    """Whether a linked socket reads a Texture Coordinate's Generated: the world's view direction."""
    node, out = feeding(socket)
    return node is not None and node.type == 'TEX_COORD' and out.name == "Generated"


def _mapping(vector):
    """(3x3 world -> image direction, "" or what is not read) of the texture's Vector input."""
    source = _from_node(vector)
    if source is None or _generated(vector):
        return np.eye(3), ""
    if source.type != 'MAPPING':
        return np.eye(3), f"its Vector comes from {describe(source)}, which EdgeLight does not read"
    into = _from_node(source.inputs["Vector"])
    why = ""
    if into is None:
        why = f"{describe(source)}'s Vector is not linked (a constant), which EdgeLight reads as the view direction"
    elif not _generated(source.inputs["Vector"]):
        why = f"{describe(source)}'s Vector comes from {describe(into)}, which EdgeLight does not read"
    location = source.inputs["Location"].default_value if "Location" in source.inputs else (0.0, 0.0, 0.0)
    if source.vector_type in {'POINT', 'TEXTURE'} and any(abs(float(v)) > 0.0 for v in location[:3]):
        why = "; ".join(w for w in (why, f"{describe(source)}'s Location is not used (a direction has none)") if w)
    rot = _euler_xyz(source.inputs["Rotation"].default_value) if "Rotation" in source.inputs else np.eye(3)
    scale = np.array(source.inputs["Scale"].default_value[:3], np.float64) if "Scale" in source.inputs else np.ones(3)
    kind = source.vector_type
    if kind == 'TEXTURE':  # the inverse: a texture turned the other way
        m = np.diag(1.0 / np.where(np.abs(scale) > 1e-12, scale, 1e-12)) @ rot.T
    elif kind == 'NORMAL':
        m = rot @ np.diag(1.0 / np.where(np.abs(scale) > 1e-12, scale, 1e-12))
    else:  # POINT, VECTOR: a direction ignores the location
        m = rot @ np.diag(scale)
    return m, why


def _euler_xyz(e):
    """Blender's XYZ Euler: X first, then Y, then Z, about the fixed axes."""
    x, y, z = (float(v) for v in e[:3])
    cx, sx, cy, sy, cz, sz = math.cos(x), math.sin(x), math.cos(y), math.sin(y), math.cos(z), math.sin(z)
    rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return rz @ ry @ rx


def _atlas(image):
    """(the image's filtered atlas, what it was filtered from): once per image and change;
    nothing is written to the image."""
    px = textures.linear_pixels(image)
    h, w, c = px.shape
    key = (image.as_pointer(), image.name_full, (w, h), image.filepath, image.is_dirty,
           image.colorspace_settings.name, zlib.crc32(px))
    if key not in _atlases:
        rgb = px[..., :3] if c >= 3 else np.repeat(px[..., :1], 3, axis=2)
        # An HDRI's NaN, infinite or negative texels would spread through every filtered tile;
        # cleaned in place (px is this read's own copy), bright suns kept as they are.
        rgb[~np.isfinite(rgb)] = 0.0
        np.maximum(rgb, 0.0, out=rgb)
        if len(_atlases) >= 4:
            _atlases.clear()
        _atlases[key] = environment_filter.prefilter(rgb)
    return _atlases[key], key
