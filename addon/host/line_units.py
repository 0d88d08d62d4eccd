"""Line widths in pixels or scene units: switching the unit converts the width, so 2 px does not
become 2 m.

The rule: a width keeps its size in the scene camera's view at the reference point, the centre
of the bounding box of the objects that render (the world origin if there are none); pixels
are the render's (resolution x percentage). Without a camera, or with the point behind it, the
number is kept. Functions here are the get/set of properties.py's line-style properties.
"""
import bpy
from mathutils import Vector

_RENDERED_TYPES = {'MESH', 'CURVE', 'SURFACE', 'META', 'FONT'}
_UNITS = ('PIXELS', 'SCENE')


def reference_point(scene):
    """Centre of the bounding box of the scene's rendered objects, or the origin."""
    corners = [ob.matrix_world @ Vector(c) for ob in scene.objects
               if ob.type in _RENDERED_TYPES and not ob.hide_render for c in ob.bound_box]
    if not corners:
        return Vector((0.0, 0.0, 0.0))
    lo = Vector(tuple(min(c[i] for c in corners) for i in range(3)))
    hi = Vector(tuple(max(c[i] for c in corners) for i in range(3)))
    return (lo + hi) / 2.0


def pixels_per_unit(scene, point=None):
    """Render pixels one scene unit spans at `point` (default: reference_point), across the view;
    None without a camera or with the point behind it."""
    from bpy_extras.object_utils import world_to_camera_view
    cam = scene.camera
    if cam is None:
        return None
    point = reference_point(scene) if point is None else Vector(point)
    a = world_to_camera_view(scene, cam, point)
    if a.z <= 0.0:
        return None
    right = cam.matrix_world.to_3x3().normalized().col[0]
    step = 1e-3 * max(a.z, 1e-3)  # small against the distance; the projection is linear across
    b = world_to_camera_view(scene, cam, point + right * step)
    width_px = scene.render.resolution_x * scene.render.resolution_percentage / 100.0
    return (b.x - a.x) * width_px / step


def get_unit(self):
    return self.get("unit", 0)


def set_unit(self, value):
    old = self.get("unit", 0)
    self["unit"] = value
    if value == old:
        return
    ppu = pixels_per_unit(self.id_data) if isinstance(self.id_data, bpy.types.Scene) else None
    if ppu:
        self.width = self.width / ppu if _UNITS[value] == 'SCENE' else self.width * ppu


def get_width(self):
    return self.width


def set_width(self, value):
    self.width = value
