"""The Light tab under EdgeLight: the settings of a light that EdgeLight reads (scene_sync.light_of)
and nothing else: colour, power, the spot's cone, and the shadow with the size that softens it
(a point or spot light's Radius, an area light's size, a sun's Angle). Blender's EEVEE light panel
also shows diffuse / specular / volume factors, which EdgeLight ignores, so it is not shown."""
import bpy

from .panel_base import EdgeLightPanel


class EDGELIGHT_PT_light(EdgeLightPanel, bpy.types.Panel):
    bl_label = "Light"
    bl_context = "data"

    @classmethod
    def poll(cls, context):
        return super().poll(context) and context.light is not None

    def draw(self, context):
        light = context.light
        layout = self.layout
        layout.row().prop(light, "type", expand=True)
        layout.use_property_split = True
        col = layout.column()
        col.prop(light, "color")
        col.prop(light, "energy")
        if light.type == 'SPOT':
            col.separator()
            col.prop(light, "spot_size", text="Spot Size")
            col.prop(light, "spot_blend", text="Blend")
            col.prop(light, "show_cone")
        col.separator()
        if light.type == 'AREA':
            col.prop(light, "shape")
            sub = col.column(align=True)
            if light.shape in {'SQUARE', 'DISK'}:
                sub.prop(light, "size")
            else:
                sub.prop(light, "size", text="Size X")
                sub.prop(light, "size_y", text="Y")
        col.prop(light, "use_shadow", text="Shadow")
        sub = col.column()
        sub.active = light.use_shadow
        if light.type == 'SUN':
            sub.prop(light, "angle")
        elif light.type != 'AREA':
            sub.prop(light, "shadow_soft_size", text="Radius")
