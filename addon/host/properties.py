"""EdgeLight settings stored in the .blend: per material and per scene."""
import math

import bpy

from ..extract import material_defaults as defaults
from . import line_units

# The settings layout. Bumped when a stored property is renamed or changes meaning; each bump
# gets a step in versioning.py that upgrades files saved with the layout before.
#   1: first layout
#   2: material `enabled` -> `use_rounding`
#   3: material `ramp` (a list of stops) and `ramp_interpolation` -> `shade_ramp` (a colour ramp)
#   4: material `K` (Highlight Strength) at most 1; a stored K > 1 becomes K = 1 and the radius times K
#   5: material `radius` defaults to 5 cm instead of 1 cm; files of older layouts keep 1 cm
#   6: scene `use_shadows` (cast shadows, on by default); scenes of older layouts keep none
SETTINGS_VERSION = 6

K_MAX = defaults.K_MAX  # versioning.py caps older files' K at it


def _tag(self, context):
    """Python-defined properties send no depsgraph update by themselves: tag their ID so the
    viewport (view_update) sees the change."""
    self.id_data.update_tag()


class EdgeLightMaterialSettings(bpy.types.PropertyGroup):
    use_rounding: bpy.props.BoolProperty(
        update=_tag, name="Rounded Edges", default=defaults.ROUNDED,
        description="Round this material's chosen edges with a thin highlight, like a bevel would")
    # Stored as `K` (the paper's name): files and scripts keep working.
    K: bpy.props.FloatProperty(
        update=_tag, name="Highlight Strength", default=defaults.HIGHLIGHT_STRENGTH, min=0.0, max=K_MAX, subtype='FACTOR',
        description="How strongly the edge highlight shows: 1 is as bright and wide as a real rounded "
                    "edge of this radius, 0 turns it off. For a wider or brighter band, raise the Radius")
    radius: bpy.props.FloatProperty(
        update=_tag, name="Radius", default=defaults.RADIUS, min=0.0, soft_max=0.1, unit='LENGTH', precision=4,
        description="Bevel radius in the object's local units, scaled with the object, like the Bevel "
                    "modifier's Amount. Each edge takes at most what its faces allow (as Bevel's Clamp "
                    "Overlap): half its narrower face's width over tan(half the angle between the faces)")
    tint: bpy.props.FloatVectorProperty(
        update=_tag, name="Highlight Tint", subtype='COLOR', size=3, default=defaults.TINT, min=0.0, soft_max=1.0,
        description="Multiplies the specular part of the edge highlight")
    use_custom_shininess: bpy.props.BoolProperty(
        update=_tag, name="Custom Shininess", default=False,
        description="Use a Blinn exponent instead of the one derived from roughness")
    shininess: bpy.props.FloatProperty(
        update=_tag, name="Shininess", default=50.0, min=1.0, max=10000.0,
        description="Blinn-Phong exponent n used for surface and edges")
    selection: bpy.props.EnumProperty(
        update=_tag, name="Edges", options={'ENUM_FLAG'},
        items=[('ANGLE', "Angle", "Edges whose faces meet at more than the angle below"),
               ('SHARP', "Sharp", "Edges marked sharp"),
               ('BEVEL', "Bevel Weight", "Edges with a bevel weight; the radius is scaled by it")],
        default=set(defaults.EDGES),
        description="Which edges are rounded (any of the chosen rules)")
    angle: bpy.props.FloatProperty(
        update=_tag, name="Angle", default=math.radians(defaults.ANGLE_DEG), min=0.0, max=3.14159265, subtype='ANGLE',
        description="Edges whose face normals differ by more than this are rounded (Auto Smooth convention)")
    # Toon shading: a shade ramp (cel shading) or an X-Toon image.
    shading: bpy.props.EnumProperty(
        update=_tag, name="Shading", default=defaults.SHADING,
        items=[('PHONG', "Blinn-Phong", "Lit by the scene's lights from the material's colour and roughness"),
               ('RAMP', "Toon Ramp", "Cel shading: the lighting N.L looked up in a colour ramp"),
               ('XTOON', "X-Toon", "The lighting N.L and depth or orientation looked up in a 2-D image")],
        description="How the surface is shaded: lit, in toon bands from a colour ramp, or from an X-Toon image")
    shade_ramp: bpy.props.PointerProperty(
        update=_tag, type=bpy.types.NodeTree, name="Shade Ramp", options={'HIDDEN'},
        description="The node group holding this material's toon colour ramp (see color_ramp.py); "
                    "none: two bands of the base colour")
    xtoon_image: bpy.props.PointerProperty(
        update=_tag, type=bpy.types.Image, name="X-Toon Image",
        description="x: lighting N.L (left dark, right lit); y: the detail axis below (bottom near). "
                    "Empty: a built-in map that fades towards grey with distance")
    xtoon_axis: bpy.props.EnumProperty(
        update=_tag, name="Y Axis", default='DEPTH',
        items=[('DEPTH', "Depth", "y runs from the near distance (bottom) to the far distance (top)"),
               ('ORIENTATION', "Orientation", "y runs from facing the eye (bottom) to the outline (top)")],
        description="What the X-Toon image's vertical axis follows: distance from the camera or turning away from it")
    xtoon_near: bpy.props.FloatProperty(
        update=_tag, name="Near", default=1.0, min=0.0, unit='LENGTH', description="Distance of the image's bottom row")
    xtoon_far: bpy.props.FloatProperty(
        update=_tag, name="Far", default=20.0, min=0.0, unit='LENGTH', description="Distance of the image's top row")
    settings_version: bpy.props.IntProperty(
        default=SETTINGS_VERSION, options={'HIDDEN'}, description="Settings layout these values were saved with")


# Line types: (property suffix, label, enabled by default, description).
LINE_TYPES = (
    ("silhouette", "Silhouettes", True, "Edges between a face turned to the eye and one turned away"),
    ("crease", "Creases", True, "Edges whose faces meet at more than the crease angle"),
    ("border", "Borders", True, "Edges of holes: edges with one face"),
    ("contour", "Smooth Contours", False, "Where a smooth surface turns away, interpolated inside faces"),
    ("marked", "Marked Edges", False, "Edges marked Freestyle, sharp or seam (see Marks)"),
    ("material", "Material Boundaries", False, "Edges between faces of different materials"),
)


def _line_style(name, enabled):
    """A line type's style. One class per type, because a PointerProperty's group cannot carry
    per-pointer defaults and silhouettes, creases and borders start enabled."""
    annotations = {
        "enabled": bpy.props.BoolProperty(update=_tag, name="Enabled", default=enabled, description="Draw these lines"),
        "color": bpy.props.FloatVectorProperty(
            update=_tag, name="Color", subtype='COLOR', size=3, default=(0.0, 0.0, 0.0), min=0.0, soft_max=1.0,
            description="Ink colour of these lines"),
        "opacity": bpy.props.FloatProperty(update=_tag, name="Opacity", default=1.0, min=0.0, max=1.0, subtype='FACTOR',
                                           description="How opaque these lines are over the image"),
        # Stored in the unit `unit` names; the UI edits it through width_px or width_scene,
        # which carry the unit (px, or the scene's length unit).
        "width": bpy.props.FloatProperty(
            update=_tag, name="Width", default=2.0, min=0.0, soft_max=20.0,
            description="Line width, in pixels or in scene units (see Unit)"),
        "width_px": bpy.props.FloatProperty(
            name="Width", subtype='PIXEL', min=0.0, soft_max=20.0, get=line_units.get_width, set=line_units.set_width,
            description="Line width in pixels of the rendered image"),
        "width_scene": bpy.props.FloatProperty(
            name="Width", unit='LENGTH', min=0.0, soft_max=0.1, precision=4,
            get=line_units.get_width, set=line_units.set_width,
            description="Line width in scene units: lines thin with distance, down to the pixel floor"),
        "unit": bpy.props.EnumProperty(
            update=_tag, name="Unit", default='PIXELS', get=line_units.get_unit, set=line_units.set_unit,
            items=[('PIXELS', "Pixels", "The same width at any distance"),
                   ('SCENE', "Scene Units", "A width in the scene that thins with distance, down to the pixel floor")],
            description="Whether Width is in pixels or in scene units; switching converts the width "
                        "so the lines keep their size in the camera view"),
        "min_pixels": bpy.props.FloatProperty(
            update=_tag, name="Pixel Floor", default=1.0, min=0.0, soft_max=4.0,
            description="Scene-unit lines never get thinner than this many pixels"),
        "taper": bpy.props.FloatProperty(
            update=_tag, name="Taper", default=0.0, min=0.0, max=0.5, subtype='FACTOR',
            description="Open chains thin to a point over this fraction of their length at their free ends"),
    }
    return type(f"EdgeLightLineStyle_{name}", (bpy.types.PropertyGroup,), {"__annotations__": annotations})


# Generated classes, one per line type: EdgeLightLineStyle_silhouette, EdgeLightLineStyle_crease,
# EdgeLightLineStyle_border, EdgeLightLineStyle_contour, EdgeLightLineStyle_marked and
# EdgeLightLineStyle_material, held by EdgeLightSceneSettings.line_silhouette, line_crease, ...
LINE_STYLES = tuple(_line_style(name, on) for name, _label, on, _doc in LINE_TYPES)


class EdgeLightSceneSettings(bpy.types.PropertyGroup):
    samples: bpy.props.IntProperty(
        update=_tag, name="Render Samples", default=8, min=1, max=256,
        description="Jittered samples accumulated per pixel for anti-aliasing (final render)")
    viewport_samples: bpy.props.IntProperty(
        update=_tag, name="Viewport Samples", default=1, min=1, max=64,
        description="Jittered samples accumulated in the viewport")
    highlights: bpy.props.BoolProperty(
        update=_tag, name="Edge Highlights", default=True, description="Draw the rounded-edge highlight pass")
    use_shadows: bpy.props.BoolProperty(
        update=_tag, name="Shadows", default=True,
        description="Lights with Shadow on cast shadows (shadow maps drawn once per frame)")
    shadow_size: bpy.props.EnumProperty(
        update=_tag, name="Shadow Resolution", default='1024',
        items=[('512', "512 px", ""), ('1024', "1024 px", ""), ('2048', "2048 px", ""), ('4096', "4096 px", "")],
        description="Width and height of each shadow map: a sun's cascade, a spot's map, each face of a point or "
                    "area light's cube")
    soft_shadows: bpy.props.BoolProperty(
        update=_tag, name="Soft Shadows", default=True,
        description="Soften shadows by each light's Radius (a sun's Angle), as a light of that size casts them")
    show_debug_stats: bpy.props.BoolProperty(
        update=_tag, name="Developer Counters", default=False,
        description="Show the viewport's counters in the status bar: objects, edges drawn and culled, "
                    "line segments, cache hits, native calls and uploads")
    # Ink lines.
    use_lines: bpy.props.BoolProperty(update=_tag, name="Lines", default=False, description="Draw ink lines on feature edges")
    crease_angle: bpy.props.FloatProperty(
        update=_tag, name="Crease Angle", default=0.7853982, min=0.0, max=3.14159265, subtype='ANGLE',
        description="Edges whose face normals differ by more than this are creases (Auto Smooth convention; "
                    "Freestyle's crease angle is 180 degrees minus this)")
    # The same setting in Freestyle's and Line Art's convention; stores nothing of its own.
    crease_angle_faces: bpy.props.FloatProperty(
        name="Crease Angle", min=0.0, max=math.pi, subtype='ANGLE',
        get=lambda self: math.pi - self.crease_angle,
        set=lambda self, value: setattr(self, "crease_angle", math.pi - value),
        description="Edges whose faces meet at less than this angle are creases (measured between the faces, "
                    "180 degrees is flat: Freestyle's and Line Art's convention)")
    marks: bpy.props.EnumProperty(
        update=_tag, name="Marks", options={'ENUM_FLAG'}, default={'FREESTYLE'},
        items=[('FREESTYLE', "Freestyle", "Edges marked for Freestyle"),
               ('SHARP', "Sharp", "Edges marked sharp"),
               ('SEAM', "Seam", "UV seams")],
        description="Which edge marks the Marked Edges lines draw")
    hidden_lines: bpy.props.EnumProperty(
        update=_tag, name="Hidden Lines", default='OFF',
        items=[('OFF', "Off", "Lines behind surfaces are not drawn"),
               ('DIMMED', "Dimmed", "Lines behind surfaces are drawn at the hidden opacity")],
        description="Whether lines behind surfaces are left out or drawn dimmed")
    hidden_opacity: bpy.props.FloatProperty(
        update=_tag, name="Hidden Opacity", default=0.25, min=0.0, max=1.0, subtype='FACTOR',
        description="Opacity of lines behind surfaces, as a fraction of their own")
    debug: bpy.props.EnumProperty(
        update=_tag, name="Debug", options={'ENUM_FLAG'}, default=set(),
        items=[('EDGE_TYPES', "Edge Types", "Every line type in its own colour: silhouettes red, creases and borders "
                                            "yellow, contours cyan, marks magenta, material boundaries green"),
               ('WHITEOUT', "Whiteout", "Unlit white surfaces and no highlights: lines only"),
               ('WIRE', "Wire", "The mesh's edges as thin blue lines")],
        description="Views for checking what EdgeLight finds")
    settings_version: bpy.props.IntProperty(
        default=SETTINGS_VERSION, options={'HIDDEN'}, description="Settings layout these values were saved with")


for (_name, _label, _on, _doc), _style in zip(LINE_TYPES, LINE_STYLES):
    EdgeLightSceneSettings.__annotations__["line_" + _name] = bpy.props.PointerProperty(
        type=_style, name=_label, description=_doc)


CLASSES = (EdgeLightMaterialSettings, *LINE_STYLES, EdgeLightSceneSettings)


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(CLASSES)


def register():
    _register_classes()
    bpy.types.Material.edgelight = bpy.props.PointerProperty(type=EdgeLightMaterialSettings)
    bpy.types.Scene.edgelight = bpy.props.PointerProperty(type=EdgeLightSceneSettings)


def unregister():
    del bpy.types.Scene.edgelight
    del bpy.types.Material.edgelight
    _unregister_classes()
