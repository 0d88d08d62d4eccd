"""Panels: EdgeLight settings in Material and Render properties; Blender's own panels that suit
EdgeLight are shown for it too."""
import bpy

from . import compat
from .properties import LINE_TYPES


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


class EDGELIGHT_UL_ramp(bpy.types.UIList):
    def draw_item(self, context, layout, data, item, icon, active_data, active_propname, index):
        row = layout.row(align=True)
        row.prop(item, "color", text="")
        row.prop(item, "position", text="")


class EDGELIGHT_OT_ramp_add(bpy.types.Operator):
    """Add a stop to the material's toon ramp (the first one adds the two default bands)"""
    bl_idname = "edgelight.ramp_add"
    bl_label = "Add Ramp Stop"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return context.material is not None

    def execute(self, context):
        from .materials import default_ramp, shading_of
        mat = context.material
        s = mat.edgelight
        if len(s.ramp) == 0:
            for position, color in default_ramp(shading_of(mat).base_color):
                stop = s.ramp.add()
                stop.position, stop.color = position, color
        else:
            last = s.ramp[len(s.ramp) - 1]
            stop = s.ramp.add()
            stop.position, stop.color = min(1.0, last.position + 0.25), last.color
        s.ramp_index = len(s.ramp) - 1
        mat.update_tag()
        return {'FINISHED'}


class EDGELIGHT_OT_ramp_remove(bpy.types.Operator):
    """Remove the active stop of the material's toon ramp"""
    bl_idname = "edgelight.ramp_remove"
    bl_label = "Remove Ramp Stop"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return context.material is not None and len(context.material.edgelight.ramp) > 0

    def execute(self, context):
        s = context.material.edgelight
        s.ramp.remove(min(s.ramp_index, len(s.ramp) - 1))
        s.ramp_index = max(0, min(s.ramp_index, len(s.ramp) - 1))
        context.material.update_tag()
        return {'FINISHED'}


class EDGELIGHT_PT_material_toon(EdgeLightPanel, bpy.types.Panel):
    bl_label = "Toon Shading"
    bl_context = "material"
    bl_parent_id = "EDGELIGHT_PT_material"

    @classmethod
    def poll(cls, context):
        return super().poll(context) and context.material is not None

    def draw(self, context):
        s = context.material.edgelight
        layout = self.layout
        layout.use_property_split = True
        layout.prop(s, "shading")
        if s.shading == 'RAMP':
            layout.prop(s, "ramp_interpolation")
            row = layout.row()
            row.template_list("EDGELIGHT_UL_ramp", "", s, "ramp", s, "ramp_index", rows=3)
            col = row.column(align=True)
            col.operator("edgelight.ramp_add", icon='ADD', text="")
            col.operator("edgelight.ramp_remove", icon='REMOVE', text="")
            if len(s.ramp) == 0:
                layout.label(text="No stops: two bands of the base colour are used", icon='INFO')
        elif s.shading == 'XTOON':
            layout.template_ID(s, "xtoon_image", new="image.new", open="image.open")
            layout.prop(s, "xtoon_axis")
            if s.xtoon_axis == 'DEPTH':
                layout.prop(s, "xtoon_near")
                layout.prop(s, "xtoon_far")


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


class EDGELIGHT_PT_lines(EdgeLightPanel, bpy.types.Panel):
    bl_label = "EdgeLight Lines"
    bl_context = "render"

    def draw_header(self, context):
        self.layout.prop(context.scene.edgelight, "use_lines", text="")

    def draw(self, context):
        s = context.scene.edgelight
        layout = self.layout
        layout.use_property_split = True
        layout.active = s.use_lines
        layout.prop(s, "crease_angle")
        layout.prop(s, "marks")
        layout.prop(s, "hidden_lines")
        sub = layout.column()
        sub.active = s.hidden_lines == 'DIMMED'
        sub.prop(s, "hidden_opacity")


def _line_type_panel(name, label):
    """One sub-panel per line type, its switch in the header."""
    def draw_header(self, context):
        self.layout.prop(getattr(context.scene.edgelight, "line_" + name), "enabled", text="")

    def draw(self, context):
        scene_settings = context.scene.edgelight
        st = getattr(scene_settings, "line_" + name)
        layout = self.layout
        layout.use_property_split = True
        layout.active = scene_settings.use_lines and st.enabled
        layout.prop(st, "color")
        layout.prop(st, "opacity")
        layout.prop(st, "unit")
        layout.prop(st, "width")
        if st.unit == 'SCENE':
            layout.prop(st, "min_pixels")
        layout.prop(st, "taper")

    return type(f"EDGELIGHT_PT_lines_{name}", (EdgeLightPanel, bpy.types.Panel), {
        "bl_label": label, "bl_context": "render", "bl_parent_id": "EDGELIGHT_PT_lines",
        "bl_options": {'DEFAULT_CLOSED'}, "draw_header": draw_header, "draw": draw})


class EDGELIGHT_PT_debug(EdgeLightPanel, bpy.types.Panel):
    bl_label = "EdgeLight Debug"
    bl_context = "render"
    bl_options = {'DEFAULT_CLOSED'}

    def draw(self, context):
        self.layout.prop(context.scene.edgelight, "debug")


LINE_PANELS = tuple(_line_type_panel(name, label) for name, label, _on, _doc in LINE_TYPES)
CLASSES = (EDGELIGHT_UL_ramp, EDGELIGHT_OT_ramp_add, EDGELIGHT_OT_ramp_remove, EDGELIGHT_PT_material,
           EDGELIGHT_PT_material_toon, EDGELIGHT_PT_render, EDGELIGHT_PT_lines, *LINE_PANELS, EDGELIGHT_PT_debug)
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
