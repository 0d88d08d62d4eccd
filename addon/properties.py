"""EdgeLight settings stored in the .blend: per material and per scene."""
import bpy

# The settings layout. Bumped when a stored property is renamed or changes meaning; each bump
# gets a step in versioning.py that upgrades files saved with the layout before.
#   1: first layout
#   2: material `enabled` -> `use_rounding`
SETTINGS_VERSION = 2


def _tag(self, context):
    """Python-defined properties send no depsgraph update by themselves: tag their ID so the
    viewport (view_update) sees the change."""
    self.id_data.update_tag()


class EdgeLightMaterialSettings(bpy.types.PropertyGroup):
    use_rounding: bpy.props.BoolProperty(
        update=_tag, name="Rounded Edges", default=True,
        description="Round this material's chosen edges with a thin highlight, like a bevel would")
    K: bpy.props.FloatProperty(
        update=_tag, name="K", default=1.0, min=0.0, soft_max=4.0,
        description="Blend gain of the highlight: 1 draws each edge at the pixel coverage a real "
                    "rounded edge of this radius has (the paper's K = focal length); 0 turns the "
                    "highlight off; larger values exaggerate it")
    radius: bpy.props.FloatProperty(
        update=_tag, name="Radius", default=0.01, min=0.0, soft_max=0.1, unit='LENGTH', precision=4,
        description="Radius of the rounding in scene units")
    tint: bpy.props.FloatVectorProperty(
        update=_tag, name="Highlight Tint", subtype='COLOR', size=3, default=(1.0, 1.0, 1.0), min=0.0, soft_max=1.0,
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
        default={'ANGLE', 'SHARP', 'BEVEL'},
        description="Which edges are rounded (any of the chosen rules)")
    angle: bpy.props.FloatProperty(
        update=_tag, name="Angle", default=0.5235988, min=0.0, max=3.14159265, subtype='ANGLE',
        description="Edges whose face normals differ by more than this are rounded (Auto Smooth convention)")
    settings_version: bpy.props.IntProperty(default=SETTINGS_VERSION, options={'HIDDEN'})


class EdgeLightSceneSettings(bpy.types.PropertyGroup):
    samples: bpy.props.IntProperty(
        update=_tag, name="Render Samples", default=8, min=1, max=256,
        description="Jittered samples accumulated per pixel for anti-aliasing (final render)")
    viewport_samples: bpy.props.IntProperty(
        update=_tag, name="Viewport Samples", default=1, min=1, max=64,
        description="Jittered samples accumulated in the viewport")
    highlights: bpy.props.BoolProperty(
        update=_tag, name="Edge Highlights", default=True, description="Draw the rounded-edge highlight pass")
    settings_version: bpy.props.IntProperty(default=SETTINGS_VERSION, options={'HIDDEN'})


CLASSES = (EdgeLightMaterialSettings, EdgeLightSceneSettings)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Material.edgelight = bpy.props.PointerProperty(type=EdgeLightMaterialSettings)
    bpy.types.Scene.edgelight = bpy.props.PointerProperty(type=EdgeLightSceneSettings)


def unregister():
    del bpy.types.Scene.edgelight
    del bpy.types.Material.edgelight
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
