"""What of a material's node tree EdgeLight reads, and what it cannot: the Principled BSDF's
socket values and the node chains linked into them that node_program.py evaluates (an image
per material, into Base Color, Metallic and Roughness), and none of its lobes past the base,
metallic and specular ones. What a material sets that EdgeLight does not draw is said once
per material (a report line) and in its panel, instead of rendering as if it were not there.
"""
from dataclasses import dataclass

from .. import compat
from ..bridge import shader_specs

# Principled BSDF inputs EdgeLight reads (materials.shading_of): their values, or the chains
# linked into them (node_program); a chain it cannot evaluate leaves the socket's own value
# drawn, which is said. Names of 3.4 and of 4.0+ (renamed sockets).
READ = ("Base Color", "Metallic", "Roughness", "Specular", "Specular IOR Level", "Alpha")
# The emission's sockets (3.4's and 4.0+'s names): their values or folded chains are drawn
# (materials.emission_of); a chain EdgeLight cannot fold means a glow it cannot place, so none is
# drawn, and that is said.
EMISSION = ("Emission", "Emission Color", "Emission Strength")
# The normal's input: a Normal Map in tangent space is drawn (node_program.normal); anything
# else linked into it is said, and the mesh's normals drawn.
NORMAL_INPUTS = ("Normal",)
# Lobes EdgeLight does not draw: (label, weight sockets by version). On when a weight is above 0.
LOBES = (("Subsurface", ("Subsurface", "Subsurface Weight")),
         ("Transmission", ("Transmission", "Transmission Weight")),
         ("Sheen", ("Sheen", "Sheen Weight")),
         ("Coat", ("Clearcoat", "Coat Weight")),
         ("Thin Film", ("Thin Film Thickness",)))


def _from_node(socket):
    """The node feeding a linked socket, through reroutes; None when unlinked."""
    return feeding(socket)[0]


@dataclass(frozen=True)
class ImageInput:
    """An Image Texture EdgeLight draws into a Principled input (shaders/textures.glsl): its image,
    the UV map it reads ("" for the mesh's active render map), Closest or not, and how it
    extends past [0, 1]."""
    image: object
    uv_map: str = ""
    closest: bool = False
    extension: str = 'REPEAT'   # REPEAT, EXTEND or CLIP


# What an Image Texture's settings can be for EdgeLight to draw it as EEVEE does (its Vector
# input: _uv_source); the extensions are shaders/surface_modes.json's EL_EXTEND.
_DRAWN_INTERPOLATION = {'Closest', 'Linear', 'Cubic', 'Smart'}
EXTENSIONS = shader_specs.enum("surface_modes.json", "EL_EXTEND")


def image_node_input(node):
    """The ImageInput of an Image Texture node EdgeLight can draw, or None (image_node_problem
    says why). Cubic and Smart interpolation draw as Linear."""
    if image_node_problem(node):
        return None
    uv = _uv_source(node.inputs["Vector"])
    return ImageInput(node.image, uv, node.interpolation == 'Closest', node.extension)


def image_node_problem(node):
    """Why EdgeLight cannot draw an Image Texture node as EEVEE does, or ""."""
    image = node.image
    if image is None:
        return "no image"
    if node.projection != 'FLAT':
        return f"its {node.projection.title()} projection"
    if node.interpolation not in _DRAWN_INTERPOLATION:
        return f"its {node.interpolation} interpolation"
    if _uv_source(node.inputs["Vector"]) is None:
        return "its Vector from other than a UV map"
    if image.source not in {'FILE', 'GENERATED'}:
        return f"its image '{image.name}' is a {image.source.lower()}"
    if image_unreadable(image):
        return f"its image '{image.name}' has no pixels"
    if node.extension not in EXTENSIONS:
        return f"its {node.extension.title()} extension"
    return ""


def feeding(socket):
    """(the node, its output socket) feeding a linked socket, through reroutes; (None, None)
    when unlinked, or linked through a muted or invalid link (which feeds nothing)."""
    while socket is not None and socket.is_linked:
        link = socket.links[0]
        if not link.is_valid or getattr(link, "is_muted", False):
            return None, None
        if link.from_node.type != 'REROUTE':
            return link.from_node, link.from_socket
        socket = link.from_node.inputs[0]
    return None, None


def image_alpha(node, image):
    """Whether the Principled BSDF `node`'s Alpha comes straight from the Alpha output of an Image
    Texture of `image` (the ImageInput its node program draws: node_program.Program.image), which
    the surface pass then cuts by (materials.BaseTexture)."""
    alpha = node.inputs.get("Alpha")
    if alpha is None or image is None:
        return False
    source, out = feeding(alpha)
    return source is not None and source.type == 'TEX_IMAGE' and out.name == "Alpha" and image_node_input(source) == image


def _uv_source(vector):
    """The UV map an Image Texture's Vector reads: "" for the active render map; None when it is
    fed by anything but a UV Map node or a Texture Coordinate's UV output."""
    if not vector.is_linked:
        return ""
    link = vector.links[0]
    node = link.from_node
    if node.type == 'UVMAP' and not node.from_instancer:
        return node.uv_map
    if node.type == 'TEX_COORD' and link.from_socket.name == "UV" and not node.from_instancer:
        return ""
    return None


def image_unreadable(image):
    """Whether an image has no pixels to draw (a missing file reads as 0 x 0)."""
    w, h = image.size
    return w < 1 or h < 1


def describe(node):
    """A node as a report names it: its kind, and its label or name where that differs."""
    label = node.label or node.name
    kind = node.bl_label
    return kind if label == kind else f"{kind} '{label}'"


def _value(socket):
    v = getattr(socket, "default_value", None)
    if v is None:
        return "none"
    try:
        return "(" + ", ".join(f"{float(c):.3g}" for c in v[:3]) + ")"
    except TypeError:
        return f"{float(v):.3g}"


def output_node(tree):
    """The material output EEVEE renders with (its target EEVEE or All, the active one first),
    as Blender picks it (ShaderNodeTree.get_output_node)."""
    getter = getattr(tree, "get_output_node", None)
    if getter is not None:
        return getter('EEVEE')
    outputs = [n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL']
    return next((n for n in outputs if n.is_active_output), outputs[0] if outputs else None)


def world_background(world):
    """(the Background node whose colour and strength light the scene or None, the node on the
    world output's Surface or None): the output's own when it is one, else the first in the
    tree (world_light.read reads the same)."""
    if world is None or not compat.uses_nodes(world):
        return None, None
    tree = world.node_tree
    getter = getattr(tree, "get_output_node", None)
    output = getter('EEVEE') if getter is not None else None
    if output is None:
        outs = [n for n in tree.nodes if n.type == 'OUTPUT_WORLD']
        output = next((n for n in outs if n.is_active_output), outs[0] if outs else None)
    surface = _from_node(output.inputs["Surface"]) if output is not None else None
    if surface is not None and surface.type == 'BACKGROUND':
        return surface, surface
    return next((n for n in tree.nodes if n.type == 'BACKGROUND'), None), surface


def principled_of(material):
    """(the Principled BSDF EdgeLight reads or None, [what it cannot draw of the material's
    outputs]): the one on the output's Surface; past another shader, the first in the tree as
    before (its values are the material's best guess), said in the list."""
    if not compat.uses_nodes(material):
        return None, []
    tree = material.node_tree
    out = output_node(tree)
    unread = []
    surface = _from_node(out.inputs["Surface"]) if out is not None else None
    if out is not None:
        for name in ("Volume", "Displacement"):
            node = _from_node(out.inputs.get(name)) if out.inputs.get(name) is not None else None
            if node is not None:
                unread.append((f"{name.lower()} ({describe(node)})", f"the {name} output: {describe(node)}"))
    if surface is not None and surface.type == 'BSDF_PRINCIPLED':
        return surface, unread
    first = next((n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED'), None)
    if surface is not None:
        used = f"the Principled BSDF '{first.name}' in it is drawn" if first else "the viewport display colour is drawn"
        unread.append((describe(surface), f"its Surface is a {describe(surface)} ({used})"))
    return first, unread


def unread_inputs(node, chains):
    """[(short, long)] of what the Principled BSDF `node` sets that EdgeLight does not draw;
    `chains` (node_program.read) says which linked inputs' chains it cannot evaluate, and why."""
    out = []
    failed = dict(chains.unread)
    for name in READ + EMISSION + NORMAL_INPUTS:
        socket = node.inputs.get(name)
        source = _from_node(socket) if socket is not None else None
        if source is None:
            continue
        if name == "Alpha" and image_alpha(node, chains.program.image):
            continue  # drawn: the image's alpha cuts the surface (EL_TEX_ALPHA)
        if name not in failed:
            continue  # drawn: folded, or per pixel (node_program)
        what = failed.get(name, describe(source))
        if name in EMISSION:
            out.append((f"{name}: {source.bl_label}", f"{name} from {what} (no emission is drawn)"))
        elif name in READ:
            out.append((f"{name}: {source.bl_label}", f"{name} from {what} (its value {_value(socket)} is drawn)"))
        else:
            out.append((f"{name}: {source.bl_label}", f"{name} from {what}"))
    for label, names in LOBES:
        for name in names:
            socket = node.inputs.get(name)
            if socket is not None and not socket.is_linked and float(socket.default_value) > 0.0:
                out.append((label, f"{label} ({name} {float(socket.default_value):.3g})"))
                break
    return out


def note(material, unread):
    """The report line for a material's unread settings; "" when it has none."""
    if not unread:
        return ""
    return f"material '{material.name}': EdgeLight does not draw " + "; ".join(long for _short, long in unread)


def panel_line(unread):
    """The material panel's one line."""
    return "Not drawn: " + ", ".join(short for short, _long in unread) if unread else ""
