"""Writes tests/data/settings_layout2.blend: EdgeLight settings in layout 2, as saved by the
add-on before layout 3 moved the toon shade ramp from a list of stops to a colour ramp
(addon/host/versioning.py).

Run in Blender 3.4 with the add-on of commit 33b1592, the last one with layout 2:

    rm -rf /tmp/el2 && mkdir -p /tmp/el2/scripts/addons
    git archive 33b1592 addon shaders | tar -x -C /tmp/el2 && mv /tmp/el2/addon /tmp/el2/scripts/addons/edgelight
    BLENDER_USER_SCRIPTS=/tmp/el2/scripts blender -b --factory-startup --addons edgelight \
        blend_samples/cube.blend --python tests/data/make_settings_layout2.py -- tests/data/settings_layout2.blend

"Stepped" has a three-stop stepped ramp (stops stored out of order), "Smooth" a two-stop smooth
one, "NoStops" toon shading with an empty list (the base colour's two bands), and the cube
keeps Blinn-Phong.
"""
import os
import sys

import bpy

out = os.path.abspath(sys.argv[sys.argv.index("--") + 1])
assert "ramp_interpolation" in type(bpy.data.materials["Cube"].edgelight).__annotations__, "needs the layout-2 add-on"


def toon(name, stops, interpolation):
    mat = bpy.data.materials.new(name)
    mat.use_fake_user = True
    s = mat.edgelight
    s.shading = 'RAMP'
    s.ramp_interpolation = interpolation
    for position, color in stops:
        stop = s.ramp.add()
        stop.position, stop.color = position, color
    return mat


toon("Stepped", ((0.75, (0.55, 0.68, 0.85)), (0.0, (0.05, 0.07, 0.12)), (0.3, (0.22, 0.3, 0.45))), 'CONSTANT')
toon("Smooth", ((0.1, (1.0, 0.0, 0.0)), (0.9, (0.0, 0.0, 1.0))), 'LINEAR')
toon("NoStops", (), 'CONSTANT')

bpy.ops.wm.save_as_mainfile(filepath=out, compress=True)
print("wrote", out)
