"""Panels: EdgeLight settings in Material and Render properties; Blender's own panels that suit
EdgeLight are shown for it too."""
import bpy

from . import compat


class EdgeLightPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    COMPAT_ENGINES = {'EDGELIGHT'}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES


class EDGELIGHT_PT_material(EdgeLightPanel, bpy.types.Panel):
    bl_label = "EdgeLight"
    bl_context = "material"

    @classmethod
    def poll(cls, context):
        return super().poll(context) and context.material is not None

    def draw_header(self, context):
        self.layout.prop(context.material.edgelight, "use_rounding", text="")

    def draw(self, context):
        s = context.material.edgelight
        layout = self.layout
        layout.use_property_split = True
        layout.active = s.use_rounding
        layout.prop(s, "radius")
        layout.prop(s, "K")
        layout.prop(s, "tint")
        row = layout.row(heading="Edges")
        row.prop(s, "selection")
        sub = layout.column()
        sub.active = 'ANGLE' in s.selection
        sub.prop(s, "angle")
        layout.prop(s, "use_custom_shininess")
        sub = layout.column()
        sub.active = s.use_custom_shininess
        sub.prop(s, "shininess")


class EDGELIGHT_PT_render(EdgeLightPanel, bpy.types.Panel):
    bl_label = "EdgeLight"
    bl_context = "render"

    def draw(self, context):
        s = context.scene.edgelight
        layout = self.layout
        layout.use_property_split = True
        layout.prop(s, "samples")
        layout.prop(s, "viewport_samples")
        layout.prop(s, "highlights")
        layout.prop(context.scene.render, "film_transparent")


CLASSES = (EDGELIGHT_PT_material, EDGELIGHT_PT_render)
_patched = []


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    for panel in compat.compat_panels():
        if 'EDGELIGHT' not in panel.COMPAT_ENGINES:
            panel.COMPAT_ENGINES.add('EDGELIGHT')
            _patched.append(panel)


def unregister():
    for panel in _patched:
        panel.COMPAT_ENGINES.discard('EDGELIGHT')
    _patched.clear()
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
