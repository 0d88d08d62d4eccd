"""Runs the add-on tests inside real Blender:

    blender -b --factory-startup --addons edgelight --python tests/blender/runner.py [-- -k PATTERN]
    python tests/blender/bpy_module.py run tests/blender/runner.py [-- -k PATTERN]   (PyPI's bpy)

First probes, in a separate process, whether this Blender can draw with the GPU here; if not,
every test that renders is skipped and one line says so: 'blender X: GPU tests skipped: why'.
Prints one line 'blender X: N passed, N failed, N skipped' and exits non-zero on any failure.
"""
import os
import subprocess
import sys
import unittest

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import helpers  # noqa: E402


def probe_gpu():
    """None if the GPU probe drew and read back a frame, else the reason it could not. An entry
    that names its rasteriser (EDGELIGHT_EXPECT_GPU: a word of the renderer's name, softpipe)
    must get it: another would pass for it unseen."""
    cmd = helpers.blender_command(os.path.join(HERE, "gpu_probe.py"))
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        return "the GPU probe did not finish in 120 s"
    for line in run.stdout.splitlines():
        if line.startswith("EDGELIGHT_GPU_PROBE "):
            _, status, text = line.split(" ", 2)
            if status == "ok":
                print(f"blender {bpy.app.version_string}: GPU: {text}")
                want = os.environ.get("EDGELIGHT_EXPECT_GPU", "")
                if want and want not in text:
                    print(f"blender {bpy.app.version_string}: 0 passed, 1 failed: expected the {want} rasteriser")
                    sys.stdout.flush()
                    os._exit(1)
                return None
            return text
    tail = (run.stderr or run.stdout).strip().splitlines()[-1:] or ["no output"]
    return f"the GPU probe process exited with code {run.returncode}: {tail[0]}"


def check_version():
    """The ctest name promises a version: refuse to report for another one."""
    want = os.environ.get("EDGELIGHT_EXPECT_BLENDER", "")
    have = "%d.%d" % bpy.app.version[:2]
    if want and not (have == want or (want.endswith(".x") and have.startswith(want[:-1]))):
        print(f"blender {bpy.app.version_string}: 0 passed, 1 failed: expected Blender {want}")
        sys.stdout.flush()
        os._exit(1)


def main():
    check_version()
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    helpers.GPU_UNAVAILABLE = probe_gpu()
    loader = unittest.TestLoader()
    patterns = [f"*{args[i + 1]}*" for i, a in enumerate(args[:-1]) if a == "-k"]
    if patterns:
        loader.testNamePatterns = patterns
    suite = loader.discover(HERE, pattern="test_*.py")
    result = unittest.TextTestRunner(verbosity=2, stream=sys.stdout).run(suite)
    failed = len(result.failures) + len(result.errors)
    passed = result.testsRun - failed - len(result.skipped)
    if helpers.GPU_UNAVAILABLE:
        print(f"blender {bpy.app.version_string}: GPU tests skipped: {helpers.GPU_UNAVAILABLE}")
        # The version matrix promises rendering tests: skipping them all is a failure there (only
        # the entry that removes the GPU on purpose expects the skips).
        if os.environ.get("EDGELIGHT_REQUIRE_GPU") == "1":
            failed += 1
            print(f"blender {bpy.app.version_string}: this entry requires the GPU, and the probe failed")
    print(f"blender {bpy.app.version_string}: {passed} passed, {failed} failed, {len(result.skipped)} skipped")
    sys.stdout.flush()
    os._exit(0 if failed == 0 and result.testsRun > 0 else 1)


main()
