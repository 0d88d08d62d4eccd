"""Writes tests/data/settings_layout1.blend: EdgeLight settings in layout 1, as saved by the
add-on before layout 2 renamed the material's `enabled` to `use_rounding` (addon/host/versioning.py).

Run in Blender 3.4 (the oldest version of the matrix; every newer one reads its files) with the
add-on of commit cc19a79, the last one with layout 1:

    rm -rf /tmp/el1 && mkdir -p /tmp/el1/scripts/addons
    git archive cc19a79 addon | tar -x -C /tmp/el1 && mv /tmp/el1/addon /tmp/el1/scripts/addons/edgelight
    BLENDER_USER_SCRIPTS=/tmp/el1/scripts blender -b --factory-startup --addons edgelight \
        blend_samples/cube.blend --python tests/data/make_settings_layout1.py -- tests/data/settings_layout1.blend

The cube's material has rounding off and every other setting away from its default (values
tests/blender/test_versioning.py checks); a spare material has rounding switched on explicitly.
"""
import math
import os
import sys

import bpy

out = os.path.abspath(sys.argv[sys.argv.index("--") + 1])
assert "enabled" in type(bpy.data.materials["Cube"].edgelight).__annotations__, "needs the layout-1 add-on"

s = bpy.data.materials["Cube"].edgelight
s.enabled = False
s.K, s.radius, s.tint = 2.5, 0.033, (0.2, 0.4, 0.6)
s.selection, s.angle = {'SHARP', 'ANGLE'}, math.radians(40.0)
s.use_custom_shininess, s.shininess = True, 123.0

spare = bpy.data.materials.new("Spare")
spare.use_fake_user = True
spare.edgelight.enabled = True  # stored explicitly, although it is the default
spare.edgelight.radius = 0.05

scene = bpy.context.scene.edgelight
scene.samples, scene.viewport_samples, scene.highlights = 5, 3, True

bpy.ops.wm.save_as_mainfile(filepath=out, compress=True)
print("wrote", out)
