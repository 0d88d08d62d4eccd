"""A material's toon shade ramp as Blender's colour-ramp widget.

A PropertyGroup cannot own a ColorRamp, so each ramp lives in a tiny shader node group of its
own holding one Color Ramp node; the material's settings point at it (`shade_ramp`). The
pointer is the group's user: it is saved, appended and linked with the material and purged
with it. The name starts with a dot, which keeps it out of the Add > Group menu. Nothing is
added to the user's own node trees. A copied material shares its ramp until Make Single User.
"""
import bpy

NODE = "Shade Ramp"
GROUP = ".EdgeLight Shade Ramp"
MAX_ELEMENTS = 32  # a ColorRamp's limit
# Interpolations the toon shader draws as they are; any other (Ease, B-Spline, ...) and the HSV /
# HSL colour modes are sampled at this many points and drawn linearly between them.
_EXACT = ('CONSTANT', 'LINEAR')
_SAMPLES = 65


def ramp_of(settings):
    """The material settings' ColorRamp, or None."""
    tree = settings.shade_ramp
    node = tree.nodes.get(NODE) if tree is not None else None
    return node.color_ramp if node is not None and node.type == 'VALTORGB' else None


def new_ramp(stops, interpolation='CONSTANT'):
    """A new ramp group from ((position, rgb), ...) (at least one stop)."""
    tree = bpy.data.node_groups.new(GROUP, 'ShaderNodeTree')
    node = tree.nodes.new('ShaderNodeValToRGB')
    node.name = node.label = NODE
    ramp = node.color_ramp
    ramp.interpolation = interpolation
    elements = ramp.elements
    while len(elements) > 1:
        elements.remove(elements[len(elements) - 1])
    stops = sorted(stops)[:MAX_ELEMENTS]
    first = elements[0]
    first.position, first.color = stops[0][0], (*stops[0][1][:3], 1.0)
    for position, rgb in stops[1:]:
        element = elements.new(position)  # sorted in; returned for its colour
        element.color = (*rgb[:3], 1.0)
    return tree


def copy_ramp(settings):
    """Gives the settings a ramp of their own (a copied material shares its original's)."""
    if settings.shade_ramp is not None:
        settings.shade_ramp = settings.shade_ramp.copy()


def stops_of(settings):
    """((position, rgb), ...) sorted, and whether to blend between them; ((), False) without a ramp."""
    ramp = ramp_of(settings)
    if ramp is None or len(ramp.elements) == 0:
        return (), False
    if ramp.interpolation in _EXACT and ramp.color_mode == 'RGB':
        stops = tuple(sorted((float(e.position), tuple(float(c) for c in e.color[:3])) for e in ramp.elements))
        return stops, ramp.interpolation == 'LINEAR'
    xs = [i / (_SAMPLES - 1) for i in range(_SAMPLES)]
    return tuple((x, tuple(float(c) for c in ramp.evaluate(x)[:3])) for x in xs), True


# The widget edits the node group, which no depsgraph holds (only the settings point at it), so
# the viewport would not hear of it: a message-bus subscription tags the materials with a ramp.
_OWNER = object()


def _ramp_edited(*_args):
    for mat in bpy.data.materials:
        if mat.library is None and getattr(mat, "edgelight", None) and mat.edgelight.shade_ramp is not None:
            mat.update_tag()


def subscribe():
    bpy.msgbus.clear_by_owner(_OWNER)
    for key in (bpy.types.ColorRamp, bpy.types.ColorRampElement):
        bpy.msgbus.subscribe_rna(key=key, owner=_OWNER, args=(), notify=_ramp_edited)


@bpy.app.handlers.persistent
def _load_post(*_args):
    subscribe()  # loading a file clears the message bus


def register():
    subscribe()
    bpy.app.handlers.load_post.append(_load_post)


def unregister():
    while _load_post in bpy.app.handlers.load_post:
        bpy.app.handlers.load_post.remove(_load_post)
    bpy.msgbus.clear_by_owner(_OWNER)
