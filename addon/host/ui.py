"""Panels: EdgeLight settings in Material and Render properties; Blender's own panels that suit
EdgeLight are shown for it too."""
import bpy

from .. import compat
from ..extract import color_ramp, material_inputs
from ..extract.materials import unread as unread_of
from . import clamp_notes, ui_light
from .panel_base import EdgeLightMaterialPanel, EdgeLightPanel
from .properties import LINE_TYPES


class EDGELIGHT_PT_material(EdgeLightMaterialPanel, bpy.types.Panel):
    bl_label = "EdgeLight"

    def draw_header(self, context):
        self.layout.prop(context.material.edgelight, "use_rounding", text="")

    def draw(self, context):
        s = context.material.edgelight
        layout = self.layout
        layout.use_property_split = True
        layout.active = s.use_rounding
        layout.prop(s, "radius")
        unread = material_inputs.panel_line(unread_of(context.material))
        if unread:  # what this material sets that EdgeLight does not draw (the render says it all)
            layout.label(text=unread, icon='ERROR')
        note = radius_clamp_note(context.material, context.scene)
        if note:
            col = layout.column(align=True)
            for line, icon in zip(note, ('INFO', 'BLANK1')):
                col.label(text=line, icon=icon)
        # Short labels: the panel is the highlight's, and "Highlight Strength" (the name tooltips
        # and the animation editors show) is cut off at the default panel width.
        layout.prop(s, "K", text="Strength")
        layout.prop(s, "tint", text="Tint")
        # Stacked, not a row of three: a row cuts their labels at the default panel width.
        layout.column(align=True).prop(s, "selection", expand=True)
        sub = layout.column()
        sub.active = 'ANGLE' in s.selection
        sub.prop(s, "angle")
        # Blender's toggle-and-value row (as Cycles' Clamp): "Custom Shininess" does not fit the
        # checkbox's column at the default width.
        row = layout.row(heading="Shininess")
        row.prop(s, "use_custom_shininess", text="")
        sub = row.row()
        sub.active = s.use_custom_shininess
        sub.prop(s, "shininess", text="")


class EDGELIGHT_PT_material_surface(EdgeLightMaterialPanel, bpy.types.Panel):
    """EEVEE's Surface panel (the Principled BSDF's inputs EdgeLight reads), drawn by Blender's own
    code but registered after EdgeLight's: Blender's panel comes first in the tab and fills three
    screens, which put the rounding settings out of sight (compat.SHOWN_PANELS)."""
    bl_label = "Surface"

    def draw(self, context):
        bpy.types.EEVEE_MATERIAL_PT_surface.draw(self, context)


def _length(value, scene):
    units = scene.unit_settings
    if units.system == 'NONE':
        return f"{value:.4g}"
    return bpy.utils.units.to_string(units.system, 'LENGTH', value * units.scale_length, precision=3)


def radius_clamp_note(material, scene):
    """The material panel's lines saying that some edges' faces allow less than the Radius (the
    clamp of radius_clamp.py, as clamp_notes.py keeps it: the Rendered view's, else the last
    render's); () when none is clamped or nothing was counted at this radius."""
    counted = clamp_notes.NOTES.radius_clamps(material)
    if not counted or not counted[0]:
        return ()
    clamped, rounded, smallest = counted
    # Short lines: a label is cut off past about 27 characters at the default panel width.
    return (f"{clamped} of {rounded} edges clamped", f"by their faces, min {_length(smallest, scene)}")


class EDGELIGHT_OT_ramp_new(bpy.types.Operator):
    """Give the material a toon colour ramp, starting from two bands of its base colour"""
    bl_idname = "edgelight.ramp_new"
    bl_label = "New Ramp"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return context.material is not None and context.material.edgelight.shade_ramp is None

    def execute(self, context):
        from ..extract.materials import base_color_of, default_ramp
        mat = context.material
        mat.edgelight.shade_ramp = color_ramp.new_ramp(default_ramp(base_color_of(mat)))
        return {'FINISHED'}


class EDGELIGHT_OT_ramp_single_user(bpy.types.Operator):
    """Give this material a copy of the ramp it shares with other materials, to edit it alone"""
    bl_idname = "edgelight.ramp_single_user"
    bl_label = "Make Single User"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return context.material is not None and context.material.edgelight.shade_ramp is not None

    def execute(self, context):
        color_ramp.copy_ramp(context.material.edgelight)
        return {'FINISHED'}


class EDGELIGHT_PT_material_toon(EdgeLightMaterialPanel, bpy.types.Panel):
    bl_label = "Toon Shading"
    bl_parent_id = "EDGELIGHT_PT_material"

    def draw(self, context):
        s = context.material.edgelight
        layout = self.layout
        layout.use_property_split = True
        layout.prop(s, "shading")
        if s.shading == 'RAMP':
            ramp = color_ramp.ramp_of(s)
            if ramp is None:
                layout.label(text="Two bands of the base colour", icon='INFO')
                layout.operator("edgelight.ramp_new", icon='ADD')
            else:
                # x: the lighting N.L, 0 unlit to 1 facing the light. Constant: hard bands.
                layout.template_color_ramp(s.shade_ramp.nodes[color_ramp.NODE], "color_ramp", expand=True)
                users = s.shade_ramp.users
                if users > 1:
                    row = layout.row()
                    row.label(text=f"Shared by {users} materials", icon='LINKED')
                    row.operator("edgelight.ramp_single_user", text="Make Single User")
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
        col = layout.column(align=True)
        col.prop(s, "samples", text="Samples")
        col.prop(s, "viewport_samples", text="Viewport")
        layout.prop(s, "highlights")
        col = layout.column(heading="Shadows")
        col.prop(s, "use_shadows", text="")
        sub = col.column()
        sub.active = s.use_shadows
        sub.prop(s, "shadow_size", text="Resolution")
        sub.prop(s, "soft_shadows")
        layout.prop(context.scene.render, "film_transparent")
        # Blender's own setting (Cycles shows it under Performance): keep the meshes' extractions
        # from one render job to the next (render_cache.py).
        layout.prop(context.scene.render, "use_persistent_data")


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
        # One crease angle, in Freestyle's and Line Art's convention: the tools ink is compared
        # with (rounding's Angle follows the Bevel modifier's, as its own tool does).
        layout.prop(s, "crease_angle_faces")
        layout.column(align=True).prop(s, "marks", expand=True)
        layout.prop(s, "hidden_lines")
        sub = layout.column()
        sub.active = s.hidden_lines == 'DIMMED'
        sub.prop(s, "hidden_opacity", text="Opacity")  # under Hidden Lines: "Hidden" is said


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
        layout.prop(st, "width_scene" if st.unit == 'SCENE' else "width_px")
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
        self.layout.prop(context.scene.edgelight, "show_debug_stats")


# Generated panels, one per line type under EDGELIGHT_PT_lines: EDGELIGHT_PT_lines_silhouette,
# EDGELIGHT_PT_lines_crease, EDGELIGHT_PT_lines_border, EDGELIGHT_PT_lines_contour,
# EDGELIGHT_PT_lines_marked and EDGELIGHT_PT_lines_material.
LINE_PANELS = tuple(_line_type_panel(name, label) for name, label, _on, _doc in LINE_TYPES)
CLASSES = (EDGELIGHT_OT_ramp_new, EDGELIGHT_OT_ramp_single_user, EDGELIGHT_PT_material,
           EDGELIGHT_PT_material_toon, EDGELIGHT_PT_material_surface, ui_light.EDGELIGHT_PT_light, EDGELIGHT_PT_render,
           EDGELIGHT_PT_lines, *LINE_PANELS, EDGELIGHT_PT_debug)
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
