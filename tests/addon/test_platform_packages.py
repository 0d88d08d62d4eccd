"""Every platform's package (scripts/package_addon.sh): its library is the platform's (format and
architecture read from the file: ELF x86-64, PE x86-64 DLL, Mach-O arm64 / x86_64), under the
name the loader picks there (addon/bridge/platforms.py), beside its checksum record; its manifest names
that platform alone; it exports exactly the el_ functions edgelight.h declares (read with the
platform's binutils or LLVM's tools); and Blender's own `extension validate` accepts it (bpy
4.5). Their dependencies are checked where they are built (native.windows, native.macos).

    PACKAGE_DIR=build/packages python3 tests/addon/test_platform_packages.py
"""
import hashlib
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import unittest
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "addon", "bridge"))
import platforms  # noqa: E402  (plain Python)

PACKAGES = os.environ.get("PACKAGE_DIR", os.path.join(ROOT, "out"))
BPY = os.path.join(os.environ.get("BUILD_DIR", os.path.join(ROOT, "build")), "bpy", "venv-4.5", "bin", "python")


def library_kind(data):
    """(format, architecture) read from a library's headers."""
    if data[:4] == b"\x7fELF":
        machine = struct.unpack_from("<H", data, 18)[0]
        return "ELF", {62: "x86_64", 183: "arm64"}.get(machine, str(machine))
    if data[:2] == b"MZ":
        pe = struct.unpack_from("<I", data, 0x3C)[0]
        if data[pe:pe + 4] != b"PE\0\0":
            return "MZ", "?"
        machine, characteristics = struct.unpack_from("<H", data, pe + 4)[0], struct.unpack_from("<H", data, pe + 22)[0]
        return ("PE DLL" if characteristics & 0x2000 else "PE"), {0x8664: "x86_64", 0xAA64: "arm64"}.get(machine, hex(machine))
    if data[:4] == b"\xcf\xfa\xed\xfe":
        cputype, filetype = struct.unpack_from("<i", data, 4)[0], struct.unpack_from("<I", data, 12)[0]
        return ("Mach-O dylib" if filetype == 6 else "Mach-O"), {0x0100000C: "arm64", 0x01000007: "x86_64"}.get(cputype, hex(cputype))
    return "unknown", "?"


EXPECTED = {
    "linux-x64": ("ELF", "x86_64"),
    "windows-x64": ("PE DLL", "x86_64"),
    "macos-arm64": ("Mach-O dylib", "arm64"),
    "macos-x64": ("Mach-O dylib", "x86_64"),
}


def exported_el(platform, path):
    """The el_ functions a library exports, read by a tool of its format."""
    if platform == "windows-x64":
        out = subprocess.run(["x86_64-w64-mingw32-objdump", "-p", path], capture_output=True, text=True, check=True).stdout
        return sorted(set(re.findall(r"^\s+\[\s*\d+\]\s+(el_\w+)$", out, re.M)))
    out = subprocess.run(["llvm-nm-14", "-gU", path], capture_output=True, text=True, check=True).stdout
    names = [line.split()[-1] for line in out.splitlines() if line.strip()]
    return sorted(n.lstrip("_") for n in names if n.lstrip("_").startswith("el_"))


def declared_el():
    with open(os.path.join(ROOT, "native", "include", "edgelight", "edgelight.h"), encoding="utf-8") as f:
        return sorted(re.findall(r"^EL_API [^(]*?\b(el_\w+)\(", f.read(), re.M))


class PlatformPackages(unittest.TestCase):
    def package(self, platform):
        found = [f for f in os.listdir(PACKAGES) if re.fullmatch(rf"edgelight-[0-9.]+-{platform}\.zip", f)]
        self.assertEqual(len(found), 1, f"{platform}: {found} in {PACKAGES}")
        return os.path.join(PACKAGES, found[0])

    def test_each_package_holds_its_platforms_library(self):
        for platform, (fmt, arch) in EXPECTED.items():
            with self.subTest(platform=platform), zipfile.ZipFile(self.package(platform)) as z:
                name = platforms.LIBRARY_FILES[platform]
                data = z.read("edgelight/" + name)
                self.assertEqual(library_kind(data), (fmt, arch))
                others = {n for n in platforms.LIBRARY_FILES.values() if n != name}
                self.assertFalse(others & {os.path.basename(n) for n in z.namelist()}, "another platform's library")
                record = json.loads(z.read("edgelight/" + os.path.splitext(name)[0] + ".json"))
                self.assertEqual(record, {"file": name, "size": len(data), "sha256": hashlib.sha256(data).hexdigest()})
                with tempfile.TemporaryDirectory() as tmp:
                    path = os.path.join(tmp, name)
                    with open(path, "wb") as f:
                        f.write(data)
                    self.assertEqual(exported_el(platform, path), declared_el())
                manifest = z.read("edgelight/blender_manifest.toml").decode()
                self.assertEqual(re.findall(r"^platforms\s*=\s*(.*)$", manifest, re.M), [f'["{platform}"]'])

    def test_the_loader_picks_the_packaged_name(self):
        self.assertEqual(platforms.library_file("linux"), "libedgelight.so")
        self.assertEqual(platforms.library_file("win32"), "edgelight.dll")
        self.assertEqual(platforms.library_file("darwin"), "libedgelight.dylib")

    def test_blender_validates_each_package(self):
        self.assertTrue(os.path.isfile(BPY), f"no bpy 4.5 venv at {BPY} (scripts/setup_bpy.sh)")
        for platform in EXPECTED:
            with self.subTest(platform=platform):
                run = subprocess.run([BPY, os.path.join(ROOT, "tests", "blender", "bpy_module.py"), "validate",
                                      self.package(platform)], capture_output=True, text=True, timeout=300)
                self.assertEqual(run.returncode, 0, (run.stdout + run.stderr)[-2000:])
                self.assertIn("Success", run.stdout + run.stderr)

    def test_blender_refuses_another_platforms_package(self):
        """Installed on this Linux machine, the Windows package is refused by its manifest."""
        env = dict(os.environ, BLENDER_USER_RESOURCES=os.path.join(PACKAGES, "user_refusal"))
        run = subprocess.run([BPY, os.path.join(ROOT, "tests", "blender", "bpy_module.py"), "install",
                              self.package("windows-x64")], capture_output=True, text=True, timeout=300, env=env)
        self.assertIn("This platform (linux-x64) isn't one of (windows-x64)", run.stdout + run.stderr)


if __name__ == "__main__":
    unittest.main()
