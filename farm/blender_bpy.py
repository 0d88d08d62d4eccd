"""A `blender` command line for PyPI's bpy, which has no executable: the farm template and the
worker-install script call it exactly as they call Blender.

    PYTHON blender_bpy.py --version
    PYTHON blender_bpy.py --command extension install-file -r user_default --enable PACKAGE.zip
    PYTHON blender_bpy.py -b [--factory-startup] [--python-exit-code N] [--addons M[,M]] [--python FILE]
        SCENE.blend [-E ENGINE] [--python-expr EXPR] [-o PATTERN] [-F FORMAT] [-x 0|1]
        [-s N] [-e N] [-f A,B,C..D | -a]

Arguments run in order, as Blender runs them. A failed render (an ERROR report from the engine)
exits 1 and writes no frame, as `blender -b -f` does. The user directory is
BLENDER_USER_RESOURCES, as for Blender.
"""
import os
import sys

import bpy

USAGE = __doc__


def fail(message, code=1):
    print(f"blender_bpy: {message}", file=sys.stderr, flush=True)
    return code


def enable_installed_extensions():
    """Blender enables the add-ons its saved preferences name; the module build reads no
    preferences (and wm.read_userpref crashes bpy 4.2), so enable what the user repository holds:
    what `extension install-file --enable` put there."""
    import addon_utils
    repo = os.path.join(bpy.utils.user_resource('EXTENSIONS'), "user_default")
    if not os.path.isdir(repo):
        return
    for name in sorted(os.listdir(repo)):
        if os.path.isfile(os.path.join(repo, name, "__init__.py")):
            addon_utils.enable(f"bl_ext.user_default.{name}", default_set=True)


def frames_of(spec, scene):
    """Blender's -f syntax: comma-separated frames and A..B ranges (inclusive)."""
    out = []
    for part in spec.split(","):
        a, _, b = part.partition("..")
        first = int(a) if a else scene.frame_start
        last = (int(b) if b else scene.frame_end) if _ else first
        out.extend(range(first, last + 1))
    return out


def render_frames(scene, frames):
    """One frame at a time as an animation of that frame, which is what `blender -f` does
    (write_still would not put the frame number into the output path)."""
    first, last = scene.frame_start, scene.frame_end
    try:
        for frame in frames:
            scene.frame_start = scene.frame_end = frame
            try:
                bpy.ops.render.render(animation=True)
            except RuntimeError as e:  # the engine's ERROR report: nothing written
                return fail(f"frame {frame} failed: {e}")
    finally:
        scene.frame_start, scene.frame_end = first, last
    return 0


def run(args):
    import addon_utils
    exit_code_on_error = 0
    enable_installed_extensions()
    i = 0
    while i < len(args):
        arg = args[i]
        nxt = args[i + 1] if i + 1 < len(args) else None
        i += 1
        if arg in ("-b", "--background", "--factory-startup", "-y", "--enable-autoexec"):
            continue
        if arg == "--":
            break
        if nxt is None and arg.startswith("-") and arg not in ("-a", "--render-anim"):
            return fail(f"{arg} needs a value", 2)
        if arg == "--python-exit-code":
            exit_code_on_error, i = int(nxt), i + 1
        elif arg == "--addons":
            for module in nxt.split(","):
                if addon_utils.enable(module, default_set=True) is None:
                    print(f"blender_bpy: add-on not loaded: {module}", file=sys.stderr)
            i += 1
        elif arg in ("-E", "--engine"):
            bpy.context.scene.render.engine, i = nxt, i + 1
        elif arg == "--python":
            i += 1
            sys.argv = [sys.executable, *args[i - 2:]]  # the script reads its args after "--"
            try:
                import runpy
                runpy.run_path(nxt, run_name="__main__")
            except SystemExit as e:
                if e.code:
                    return e.code if isinstance(e.code, int) else 1
            except Exception:
                import traceback
                traceback.print_exc()
                if exit_code_on_error:
                    return exit_code_on_error
        elif arg == "--python-expr":
            i += 1
            try:
                exec(compile(nxt, "<python-expr>", "exec"), {"__name__": "__main__"})
            except Exception:
                import traceback
                traceback.print_exc()
                if exit_code_on_error:
                    return exit_code_on_error
        elif arg in ("-o", "--render-output"):
            bpy.context.scene.render.filepath, i = nxt, i + 1
        elif arg in ("-F", "--render-format"):
            bpy.context.scene.render.image_settings.file_format, i = nxt, i + 1
        elif arg in ("-x", "--use-extension"):
            bpy.context.scene.render.use_file_extension, i = nxt == "1", i + 1
        elif arg in ("-s", "--frame-start"):
            bpy.context.scene.frame_start, i = int(nxt), i + 1
        elif arg in ("-e", "--frame-end"):
            bpy.context.scene.frame_end, i = int(nxt), i + 1
        elif arg in ("-f", "--render-frame"):
            scene = bpy.context.scene
            code = render_frames(scene, frames_of(nxt, scene))
            i += 1
            if code:
                return code
        elif arg in ("-a", "--render-anim"):
            scene = bpy.context.scene
            code = render_frames(scene, range(scene.frame_start, scene.frame_end + 1, scene.frame_step))
            if code:
                return code
        elif arg.startswith("-"):
            return fail(f"unsupported argument {arg}\n{USAGE}", 2)
        else:  # a .blend file, loaded where it stands, as Blender does
            try:
                bpy.ops.wm.open_mainfile(filepath=os.path.abspath(arg))
            except RuntimeError as e:
                return fail(f"cannot read {arg}: {e}")
    return 0


def main(args):
    if args[:1] in (["--version"], ["-v"]):
        print(f"Blender {bpy.app.version_string}")
        return 0
    if args[:2] == ["--command", "extension"]:
        from bl_pkg import bl_extension_cli  # the handler of Blender's own `--command extension`
        return bl_extension_cli.cli_extension_handler(args[2:])
    if not args or args[0] in ("-h", "--help"):
        print(USAGE)
        return 0 if args else 2
    return run(args)


if __name__ == "__main__":
    code = main(sys.argv[1:])
    sys.stdout.flush()
    sys.stderr.flush()
    # bpy 4.2 as a module can crash in its exit-time destructors once an add-on registered
    # classes (tests/blender/bpy_module.py): leave without them.
    os._exit(code or 0)
