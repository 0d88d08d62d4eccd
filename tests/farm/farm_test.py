"""The render-farm tests, on one Blender version (3.4: Debian's blender; 4.2 / 4.5 / 5: PyPI's
bpy through farm/blender_bpy.py). Run by ctest (tests/farm/CMakeLists.txt):

    farm_test.py install VERSION     scripts/farm_install_worker.sh in a fresh user directory,
                                     then a render with what it installed
    farm_test.py openjd VERSION      farm/edgelight-render.openjd.yaml under `openjd run`: 6
                                     frames in chunks of 2, each identical to a single-process
                                     render; a broken frame and a missing scene fail the job
    farm_test.py same_frame VERSION  a frame rendered in two processes, and after another frame
                                     in one process: identical pixels
    farm_test.py flamenco VERSION    farm/flamenco's job type parsed by acorn, compiled against
                                     stand-ins for Flamenco's API, and its commands run

Prints one result line, 'farm MODE VERSION: passed' or '... FAILED: why', and exits 0 or 1.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np
from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BUILD = os.environ.get("BUILD_DIR", os.path.join(ROOT, "build"))
TEMPLATE = os.path.join(ROOT, "farm", "edgelight-render.openjd.yaml")
OPENJD = os.path.join(BUILD, "farm", "venv", "bin", "openjd")


ENGINE_CHECK = "import bpy; assert bpy.context.scene.render.engine == 'EDGELIGHT', 'EdgeLight is not enabled'"


TMP = []  # this test's directory


class Failed(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failed(message)


def blender_command(version):
    if version == "3.4":
        return ["blender"]
    venv = os.path.join(BUILD, "bpy", f"venv-{version}")
    check(os.path.isfile(os.path.join(venv, "edgelight-stamp")),
          f"no bpy venv at {venv} (run scripts/setup_bpy.sh)")
    return [os.path.join(venv, "bin", "python"), os.path.join(ROOT, "farm", "blender_bpy.py")]


_package = []


def package():
    """The newest build/edgelight-*-linux-x64.zip, copied once per test: a rebuild while the
    test runs must not change what its workers install."""
    if not _package:
        zips = sorted((os.path.join(BUILD, n) for n in os.listdir(BUILD) if n.startswith("edgelight-") and n.endswith("-linux-x64.zip")),
                      key=os.path.getmtime)
        check(zips, f"no package in {BUILD} (cmake --build build --target package_addon)")
        _package.append(shutil.copy(zips[-1], TMP[0]))
    return _package[0]


def run(cmd, env, timeout=120, expect=0):
    start = time.monotonic()
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout)
    out = proc.stdout + proc.stderr
    ok = proc.returncode == 0 if expect == 0 else proc.returncode != 0
    check(ok, f"{' '.join(cmd[:4])} ... exited {proc.returncode}, expected "
              f"{'0' if expect == 0 else 'non-zero'}:\n{out[-3000:]}")
    print(f"  {time.monotonic() - start:5.1f} s  {' '.join(os.path.basename(c) if os.path.isabs(c) else c for c in cmd[:6])} ...", flush=True)
    return out


class Worker:
    """A fresh user directory with the add-on installed by scripts/farm_install_worker.sh."""

    def __init__(self, version, tmp, install=True):
        self.version, self.blender = version, blender_command(version)
        self.user = os.path.join(tmp, "user")
        env = {k: v for k, v in os.environ.items() if not k.startswith("BLENDER_USER_") and k != "EDGELIGHT_LIBRARY"}
        # Only the top directory: on 3.4 the install script asks Blender for the scripts in it.
        env["BLENDER_USER_RESOURCES"] = self.user
        self.env = env
        self.addons = ["--addons", "edgelight"] if version == "3.4" else []
        if install:
            self.install_output = run([os.path.join(ROOT, "scripts", "farm_install_worker.sh"), package(), *self.blender], env)

    def render(self, scene, out_pattern, frames):
        """`blender -b SCENE -E EDGELIGHT -o PATTERN -f FRAMES`, the template's command, failing
        when the engine is not there (-E alone only warns)."""
        return run([*self.blender, "-b", "--python-exit-code", "1", *self.addons, scene, "-E", "EDGELIGHT",
                    "--python-expr", ENGINE_CHECK, "-o", out_pattern, "-x", "1", "-f", frames], self.env)

    def make_scenes(self, tmp):
        run([*self.blender, "-b", "--factory-startup", *self.addons, "--python", os.path.join(HERE, "make_scene.py"),
             "--", os.path.join(ROOT, "blend_samples", "cube.blend"), tmp], self.env)
        return os.path.join(tmp, "anim.blend"), os.path.join(tmp, "broken.blend")


def pixels(path):
    check(os.path.isfile(path) and os.path.getsize(path) > 0, f"missing or empty: {path}")
    return np.asarray(Image.open(path))


def assert_identical(a_path, b_path, what):
    a, b = pixels(a_path), pixels(b_path)
    check(a.shape == b.shape, f"{what}: {a.shape} vs {b.shape}")
    diff = np.abs(a.astype(int) - b.astype(int))
    check(not diff.any(), f"{what}: {int((diff.max(axis=-1) > 0).sum())} pixels differ, by up to {diff.max()} "
                          f"({os.path.basename(a_path)} vs {os.path.basename(b_path)})")
    check(a[..., :3].std() > 5, f"{what}: a flat image, nothing rendered ({a_path})")


def test_install(version, tmp):
    worker = Worker(version, tmp)
    if version == "3.4":
        installed = os.path.join(worker.user, "scripts", "addons", "edgelight")
    else:
        installed = os.path.join(worker.user, "extensions", "user_default", "edgelight")
        check(os.path.isfile(os.path.join(worker.user, "config", "userpref.blend")), "no preferences saved (--enable)")
    for name in ("__init__.py", "libedgelight.so", "blender_manifest.toml"):
        check(os.path.isfile(os.path.join(installed, name)), f"not installed: {installed}/{name}")
    cube = os.path.join(ROOT, "blend_samples", "cube.blend")
    worker.render(cube, os.path.join(tmp, "out", "cube_#"), "1")
    check(pixels(os.path.join(tmp, "out", "cube_1.png"))[..., :3].std() > 5, "the render is flat")
    # A second install over the first (a worker updated in place) must work too.
    run([os.path.join(ROOT, "scripts", "farm_install_worker.sh"), package(), *worker.blender], worker.env)


def openjd(worker, scene, pattern, env, expect=0, extra=()):
    cmd = [OPENJD, "run", TEMPLATE, "-p", f"SceneFile={scene}", "-p", "Frames=1-6", "-p", "ChunkSize=2",
           "-p", f"OutputPattern={pattern}", "-p", f"BlenderExecutable={' '.join(worker.blender)}", *extra]
    return run(cmd, env, timeout=300, expect=expect)


def test_openjd(version, tmp):
    check(os.path.isfile(OPENJD), f"no openjd at {OPENJD} (run scripts/setup.sh)")
    worker = Worker(version, tmp)
    anim, broken = worker.make_scenes(tmp)
    # The job installs the package itself: its worker has an empty user directory.
    bare = dict(worker.env, BLENDER_USER_RESOURCES=os.path.join(tmp, "bare"))
    with_package = ["-p", f"AddonPackage={package()}"]
    out = openjd(worker, anim, os.path.join(tmp, "farm", "f_###"), bare, extra=with_package)
    check("EdgeLight: installed" in out, "the job did not install the package:\n" + out[-2000:])
    # Each frame against a render of that frame alone, in its own process (the add-on installed
    # on the worker): chunks render frames 2, 4 and 6 after another frame in the same process.
    for frame in range(1, 7):
        worker.render(anim, os.path.join(tmp, "single", f"f{frame}_###"), str(frame))
        assert_identical(os.path.join(tmp, "farm", f"f_{frame:03d}.png"),
                         os.path.join(tmp, "single", f"f{frame}_{frame:03d}.png"), f"frame {frame}")
    # Frame 4's camera is scaled to zero: EdgeLight refuses it, the task and the job fail, and
    # no frame 4 is written. The worker's installed add-on this time.
    out = openjd(worker, broken, os.path.join(tmp, "broken", "f_###"), worker.env, expect=1)
    check("singular transform" in out, "no EdgeLight error for frame 4:\n" + out[-2000:])
    check(not os.path.exists(os.path.join(tmp, "broken", "f_004.png")), "frame 4 was written")
    check(os.path.isfile(os.path.join(tmp, "broken", "f_001.png")), "the chunk before the broken one did not render")
    out = openjd(worker, os.path.join(tmp, "missing.blend"), os.path.join(tmp, "missing", "f_###"), worker.env, expect=1)
    check("scene file missing" in out, "no missing-scene error:\n" + out[-2000:])


def test_same_frame(version, tmp):
    worker = Worker(version, tmp)
    anim, _ = worker.make_scenes(tmp)
    worker.render(anim, os.path.join(tmp, "a", "f_###"), "1")
    worker.render(anim, os.path.join(tmp, "b", "f_###"), "1")
    worker.render(anim, os.path.join(tmp, "c", "f_###"), "3,1")  # frame 3 first, same process
    first = os.path.join(tmp, "a", "f_001.png")
    assert_identical(first, os.path.join(tmp, "b", "f_001.png"), "frame 1 in two processes")
    assert_identical(first, os.path.join(tmp, "c", "f_001.png"), "frame 1 after frame 3")


def test_flamenco(version, tmp):
    """The Flamenco job type compiled against stand-ins for Flamenco's API (flamenco_check.js),
    and the Blender command lines it makes run here as a Worker would run them (`{blender}
    {blenderArgs}` = blender -b -y). Flamenco itself is not run."""
    acorn = os.path.join(BUILD, "farm", "node_modules", "acorn")
    check(os.path.isdir(acorn), f"no acorn at {acorn} (run scripts/setup.sh)")
    worker = Worker(version, tmp)
    anim, _ = worker.make_scenes(tmp)
    import json
    out = run(["node", os.path.join(HERE, "flamenco_check.js"), acorn, os.path.join(ROOT, "farm", "flamenco", "edgelight_render.js"),
               anim, os.path.join(tmp, "flamenco", "f_###"), "1-6", "4", "1" if version == "3.4" else "0"], worker.env)
    tasks = json.loads(out.strip().splitlines()[-1])
    check([t["name"] for t in tasks] == ["render-1-4", "render-5-6"], f"tasks: {[t['name'] for t in tasks]}")
    for task in tasks:
        (command,) = task["commands"]
        p = command["params"]
        check(command["type"] == "blender-render" and p["exe"] == "{blender}", f"command: {command}")
        run([*worker.blender, "-b", "-y", *p["argsBefore"], p["blendfile"], *p["args"]], worker.env)
    for frame in range(1, 7):
        check(pixels(os.path.join(tmp, "flamenco", f"f_{frame:03d}.png"))[..., :3].std() > 5, f"frame {frame} is flat")


TESTS = {"install": test_install, "openjd": test_openjd, "same_frame": test_same_frame, "flamenco": test_flamenco}


def main(mode, version):
    tmp = tempfile.mkdtemp(prefix=f"edgelight_farm_{mode}_")
    TMP.append(tmp)
    start = time.monotonic()
    try:
        TESTS[mode](version, tmp)
    except (Failed, subprocess.TimeoutExpired) as e:
        print(f"farm {mode} {version}: FAILED: {e}\n(files kept in {tmp})")
        return 1
    shutil.rmtree(tmp, ignore_errors=True)
    print(f"farm {mode} {version}: passed in {time.monotonic() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
