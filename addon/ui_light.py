"""The Light tab under EdgeLight: the settings of a light that EdgeLight reads (scene_sync.light_of)
and nothing else. Blender's EEVEE light panel also shows diffuse / specular / volume factors,
radius and shadows, which EdgeLight ignores, so it is not shown for EdgeLight."""
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
