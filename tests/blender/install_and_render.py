"""Installs the package zip the way an artist does, in a fresh process and user directory, then
renders the cube sample with it. Run by test_package.py (without the add-on enabled):

    install_and_render.py PACKAGE.zip SAMPLES_DIR RENDER(0|1)

3.4: Preferences > Add-ons > Install (preferences.addon_install) and enable, the legacy way.
4.2+: the handler behind `blender --command extension install-file -r user_default --enable`.
Prints 'EDGELIGHT_INSTALLED <module> <file>' and, when rendering, 'EDGELIGHT_RENDERED <edges>'.
"""
import os
import sys

import bpy

zip_path, samples, do_render = sys.argv[sys.argv.index("--") + 1:]

if bpy.app.version >= (4, 2, 0):
    from bl_pkg import bl_extension_cli
    rc = bl_extension_cli.cli_extension_handler(["install-file", "-r", "user_default", "--enable", zip_path])
    assert rc == 0, f"install-file returned {rc}"
    module = "bl_ext.user_default.edgelight"
else:
    bpy.ops.preferences.addon_install(filepath=zip_path)
    module = "edgelight"
    bpy.ops.preferences.addon_enable(module=module)

mod = sys.modules[module]
assert module in bpy.context.preferences.addons, f"{module} is not enabled"
print("EDGELIGHT_INSTALLED", module, mod.__file__, flush=True)

if do_render == "1":
    bpy.ops.wm.open_mainfile(filepath=os.path.join(samples, "cube.blend"))
    scene = bpy.context.scene
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 64, 48, 100
    scene.edgelight.samples = 1
    mod.host.engine.capture = True  # keep the render's record for this check
    bpy.ops.render.render()
    record = mod.host.engine.last_render
    print("EDGELIGHT_RENDERED", record["stats"].edges_drawn, record["pixels"].shape, flush=True)
