"""The package zip: what is inside, that Blender validates it, and that it installs and renders."""
import ast
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest
import zipfile

import bpy

import helpers

PACKAGE = os.environ.get("EDGELIGHT_PACKAGE", "")


def manifest_version(text):
    return re.search(r'^version\s*=\s*"([0-9.]+)"', text, re.M).group(1)


class Contents(unittest.TestCase):
    def setUp(self):
        self.assertTrue(os.path.isfile(PACKAGE), f"EDGELIGHT_PACKAGE={PACKAGE!r} (set by blender_tests.sh)")

    def test_one_folder_with_manifest_bl_info_shaders_and_library(self):
        with zipfile.ZipFile(PACKAGE) as z:
            names = z.namelist()
            manifest = z.read("edgelight/blender_manifest.toml").decode()
            init = z.read("edgelight/__init__.py").decode()
        self.assertEqual({n.split("/")[0] for n in names}, {"edgelight"})
        for name in ("__init__.py", "host/versioning.py", "compat.py", "libedgelight.so",
                     "shaders/programs.json", "passes/frame.py"):
            self.assertIn("edgelight/" + name, names)
        self.assertFalse([n for n in names if "__pycache__" in n or n.endswith(".pyc")])
        self.assertIn('platforms = ["linux-x64"]', manifest)
        self.assertIn('blender_version_min = "4.2.0"', manifest)
        # From the source: 4.2+ does not keep bl_info on an extension's module.
        bl_info = next(ast.literal_eval(node.value) for node in ast.parse(init).body
                       if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "bl_info")
        self.assertEqual(bl_info["blender"], (3, 4, 0))
        info_version = ".".join(map(str, bl_info["version"]))
        self.assertEqual(manifest_version(manifest), info_version)

    def test_library_record_matches_the_library(self):
        with zipfile.ZipFile(PACKAGE) as z:
            library = z.read("edgelight/libedgelight.so")
            record = json.loads(z.read("edgelight/libedgelight.json"))
        self.assertEqual(record, {"file": "libedgelight.so", "size": len(library),
                                  "sha256": hashlib.sha256(library).hexdigest()})

    def test_running_add_on_is_the_installed_package(self):
        mod = helpers.addon()
        here = os.path.dirname(mod.__file__)
        self.assertEqual(mod.__name__, helpers.MODULE)
        self.assertTrue(os.path.isfile(os.path.join(here, "blender_manifest.toml")))
        # The library is found beside the add-on (EDGELIGHT_LIBRARY overrides only in tests).
        self.assertEqual(mod.bridge.native.default_library_path(), os.path.join(here, "libedgelight.so"))
        self.assertEqual(mod.bridge.native.load().path, os.path.join(here, "libedgelight.so"))
        # Installed with its record, so the full check (size and SHA-256) applies.
        self.assertEqual(mod.bridge.library_check.check(os.path.join(here, "libedgelight.so")), "record")


class Validates(unittest.TestCase):
    def test_extension_validate(self):
        if not helpers.is_module_build() and bpy.app.version < (4, 2, 0):
            self.skipTest("Blender 3.4 has no extensions: it installs the zip as a legacy add-on")
        if helpers.is_module_build():
            cmd = [sys.executable, os.path.join(helpers.HERE, "bpy_module.py"), "validate", PACKAGE]
        else:
            cmd = [bpy.app.binary_path, "--command", "extension", "validate", PACKAGE]
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stdout[-2000:] + run.stderr[-2000:])
        self.assertIn("Success parsing TOML", run.stdout + run.stderr)


class InstallsAndRenders(unittest.TestCase):
    def test_install_in_a_fresh_user_directory_then_render(self):
        user = tempfile.mkdtemp(prefix="edgelight_user_")
        env = dict(os.environ, BLENDER_USER_RESOURCES=user, BLENDER_USER_SCRIPTS=os.path.join(user, "scripts"))
        env.pop("EDGELIGHT_LIBRARY", None)
        render = "0" if helpers.GPU_UNAVAILABLE else "1"
        cmd = helpers.blender_command(os.path.join(helpers.HERE, "install_and_render.py"),
                                      PACKAGE, helpers.SAMPLES, render, addon=False)
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=300, env=env)
        out = run.stdout + run.stderr
        self.assertEqual(run.returncode, 0, out[-3000:])
        installed = re.search(r"^EDGELIGHT_INSTALLED (\S+) (\S+)$", run.stdout, re.M)
        self.assertIsNotNone(installed, out[-3000:])
        self.assertTrue(installed.group(2).startswith(user), "installed into the fresh user directory")
        if render == "1":
            rendered = re.search(r"^EDGELIGHT_RENDERED (\d+) \(48, 64, 4\)$", run.stdout, re.M)
            self.assertIsNotNone(rendered, out[-3000:])
            self.assertGreaterEqual(int(rendered.group(1)), 12, "the cube's edges were drawn")
        else:
            helpers.needs_gpu()  # installed and enabled; the render part is skipped, and says so


if __name__ == "__main__":
    unittest.main()
