"""Runs scripts in Blender-as-a-Python-module (PyPI's bpy) the way `blender -b` runs them.

    python bpy_module.py install PACKAGE.zip      # = blender --command extension install-file
                                                  #   -r user_default --enable PACKAGE.zip
    python bpy_module.py run SCRIPT [-- ARGS]     # = blender -b --addons $EDGELIGHT_MODULE
                                                  #   --python SCRIPT -- ARGS
    python bpy_module.py run-bare SCRIPT [-- ARGS]  # the same without enabling the add-on
    python bpy_module.py validate PACKAGE.zip     # = blender --command extension validate

The module has no `--command`: install and validate call the handler that Blender's own
`--command extension` runs (bl_pkg, bundled and enabled in 4.2+). The user directory comes from
BLENDER_USER_RESOURCES, so nothing touches the real one.
"""
import os
import runpy
import sys

import bpy  # noqa: F401 -- starts Blender (the module), before bl_pkg and the add-on are imported


def extension_command(args):
    from bl_pkg import bl_extension_cli  # bundled core add-on, enabled by default in 4.2+
    return bl_extension_cli.cli_extension_handler(args)


def run(script, args, enable=True):
    import addon_utils
    module = os.environ.get("EDGELIGHT_MODULE", "edgelight")
    if enable and addon_utils.enable(module, default_set=True) is None:
        print(f"bpy_module: cannot enable add-on {module}", file=sys.stderr)
        return 1
    sys.argv = [sys.executable, "--python", script, "--", *args]
    try:
        runpy.run_path(script, run_name="__main__")
    except SystemExit as e:
        return e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    except Exception:  # like blender --python-exit-code 1
        import traceback
        traceback.print_exc()
        return 1
    return 0


def main(argv):
    if len(argv) >= 2 and argv[0] == "install":
        return extension_command(["install-file", "-r", "user_default", "--enable", os.path.abspath(argv[1])])
    if len(argv) >= 2 and argv[0] == "validate":
        return extension_command(["validate", os.path.abspath(argv[1])])
    if len(argv) >= 2 and argv[0] in ("run", "run-bare"):
        rest = argv[2:]
        return run(os.path.abspath(argv[1]), rest[1:] if rest[:1] == ["--"] else rest, enable=argv[0] == "run")
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    code = main(sys.argv[1:])
    sys.stdout.flush()
    sys.stderr.flush()
    # bpy 4.2 as a module segfaults in its exit-time destructors (bpy_class_free after Python
    # is finalised) once an add-on registered panels; 4.5 and 5.0 do not. Skip them.
    os._exit(code or 0)
