"""Makes the farm tests' animation from the cube sample: 6 frames, the cube (and a small
instance of it) turning, small and cheap (96 x 72, 2 jittered samples, highlights, ink lines),
saved as OUT_DIR/anim.blend; and OUT_DIR/broken.blend, the same with the camera scaled to zero
on frame 4 only, which EdgeLight refuses (singular camera).

    blender -b --factory-startup --python make_scene.py -- CUBE.blend OUT_DIR
"""
import math
import os
import sys

import bpy

cube_blend, out_dir = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.open_mainfile(filepath=cube_blend)
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 96, 72, 100
scene.render.image_settings.file_format = 'PNG'
scene.render.image_settings.color_mode = 'RGBA'
scene.view_settings.view_transform = 'Standard'
scene.frame_start, scene.frame_end = 1, 6
scene.edgelight.samples = 2  # run with the add-on enabled
scene.edgelight.use_lines = True  # silhouettes too: view-dependent, so they change per frame
for name in dir(scene.edgelight):  # every line type translucent: the jittered surface edge shows
    style = getattr(scene.edgelight, name) if name.startswith("line_") else None
    if hasattr(style, "opacity"):
        style.opacity = 0.6

cube = next(ob for ob in scene.objects if ob.type == 'MESH')
for frame in range(1, 7):
    cube.rotation_euler.z = math.radians(9.0 * (frame - 1))
    cube.keyframe_insert("rotation_euler", index=2, frame=frame)
# A second instance of the same mesh: several objects and a shared mesh, whose order must not
# change a frame.
small = cube.copy()
small.location, small.scale = (1.3, -1.3, -0.4), (0.3, 0.3, 0.3)
scene.collection.objects.link(small)
os.makedirs(out_dir, exist_ok=True)
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out_dir, "anim.blend"), copy=True)

camera = scene.camera
for frame, scale in ((3, 1.0), (4, 0.0), (5, 1.0)):
    camera.scale = (scale,) * 3
    camera.keyframe_insert("scale", frame=frame)
for fcurve in camera.animation_data.action.fcurves:
    for key in fcurve.keyframe_points:
        key.interpolation = 'CONSTANT'
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out_dir, "broken.blend"), copy=True)
print("made", out_dir)
