"""Blender's own panels under EdgeLight: exactly those whose settings EdgeLight honours."""
import unittest

import bpy

import helpers

# Shown for EdgeLight on every version of the matrix (the same names in 3.4 through 5.x).
SHOWN = (
    "EEVEE_MATERIAL_PT_context_material",  # slots, New
    "EEVEE_WORLD_PT_surface",  # world colour
    "WORLD_PT_context_world",
    "DATA_PT_context_light",
    "RENDER_PT_color_management",
    "MATERIAL_PT_custom_props",
)
# Never shown: settings EdgeLight ignores (shadows, volumes, EEVEE's own light and material
# settings, light radius), Freestyle (EdgeLight draws its own lines), motion blur (unsupported).
# Each version has some of these names.
NOT_SHOWN = (
    "DATA_PT_EEVEE_light", "DATA_PT_EEVEE_light_distance", "DATA_PT_EEVEE_light_influence",
    "DATA_PT_EEVEE_light_shadow", "DATA_PT_EEVEE_shadow", "DATA_PT_EEVEE_shadow_contact",
    "DATA_PT_EEVEE_shadow_cascaded_shadow_map", "DATA_PT_light", "DATA_PT_area",
    "EEVEE_MATERIAL_PT_surface",  # drawn by EdgeLight's own Surface panel, below its settings
    "EEVEE_MATERIAL_PT_volume", "EEVEE_WORLD_PT_volume", "EEVEE_MATERIAL_PT_settings",
    "EEVEE_NEXT_MATERIAL_PT_settings", "EEVEE_MATERIAL_PT_displacement", "EEVEE_MATERIAL_PT_thickness",
    "MATERIAL_PT_preview", "EEVEE_WORLD_PT_mist", "EEVEE_WORLD_PT_settings",
    "MATERIAL_PT_freestyle_line", "RENDER_PT_freestyle", "VIEWLAYER_PT_freestyle",
    "RENDER_PT_eevee_motion_blur", "RENDER_PT_eevee_next_motion_blur", "RENDER_PT_motion_blur",
)


def engines(name):
    return getattr(getattr(bpy.types, name), "COMPAT_ENGINES", set())


class Panels(unittest.TestCase):
    def test_honoured_panels_list_edgelight(self):
        for name in SHOWN:
            self.assertTrue(hasattr(bpy.types, name), f"{name} exists in Blender {bpy.app.version_string}")
            self.assertIn('EDGELIGHT', engines(name), name)

    def test_ignored_panels_do_not(self):
        present = [n for n in NOT_SHOWN if hasattr(bpy.types, n)]
        self.assertGreater(len(present), 5, "the names still exist in this version")
        for name in present:
            self.assertNotIn('EDGELIGHT', engines(name), name)

    def test_material_settings_come_before_the_surface(self):
        # Panels of one tab show in the order they were registered: EdgeLight's settings first,
        # then the Principled inputs (Blender's own drawing), which fill several screens.
        ui = helpers.addon().host.ui
        order = [cls.__name__ for cls in ui.CLASSES if getattr(cls, "bl_context", "") == "material"]
        self.assertLess(order.index("EDGELIGHT_PT_material"), order.index("EDGELIGHT_PT_material_surface"))
        self.assertIn('EDGELIGHT', ui.EDGELIGHT_PT_material_surface.COMPAT_ENGINES)

    def test_edgelight_light_panel_replaces_eevee_s(self):
        panel = helpers.addon().host.ui_light.EDGELIGHT_PT_light
        self.assertEqual(panel.bl_context, "data")
        self.assertTrue(hasattr(bpy.types, "EDGELIGHT_PT_light"))

    def test_unregister_removes_edgelight(self):
        ui = helpers.addon().host.ui
        ui.unregister()
        try:
            for name in SHOWN:
                self.assertNotIn('EDGELIGHT', engines(name), name)
            self.assertFalse(hasattr(bpy.types, "EDGELIGHT_PT_light"))
        finally:
            ui.register()
        self.assertIn('EDGELIGHT', engines(SHOWN[0]))


if __name__ == "__main__":
    unittest.main()
