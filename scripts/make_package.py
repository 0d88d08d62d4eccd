#!/usr/bin/env python3
"""Assembles the add-on package an artist installs: one zip, edgelight/ inside, holding the
Python package, blender_manifest.toml (Blender 4.2+ extension), bl_info (Blender 3.4 legacy
add-on), the shaders, the platform's library (libedgelight.so, edgelight.dll, libedgelight.dylib:
addon/bridge/platforms.py) and its record (size and SHA-256, which the add-on checks before loading the
library: addon/bridge/library_check.py), the manifest's platforms line set to the platform. Called by the
CMake target `package_addon` (linux-x64) and scripts/package_addon.sh (every platform).

    make_package.py ROOT LIBRARY OUT_ZIP [PLATFORM]
"""
import ast
import json
import os
import re
import sys
import zipfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "addon", "bridge"))
import library_check  # noqa: E402  (plain Python: the add-on's check and this record share one format)
import platforms  # noqa: E402  (the library's name per platform, as the loader picks it)


def manifest_version(path):
    with open(path, encoding="utf-8") as f:
        m = re.search(r'^version\s*=\s*"([0-9.]+)"', f.read(), re.M)
    return m.group(1)


def bl_info_version(path):
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read())
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "bl_info":
            info = ast.literal_eval(node.value)
            return ".".join(str(v) for v in info["version"])
    raise SystemExit(f"{path}: no bl_info")


def files(root):
    """(path on disk, path in the zip) for every file of the package."""
    addon, shaders = os.path.join(root, "addon"), os.path.join(root, "shaders")
    for base, prefix in ((addon, "edgelight"), (shaders, "edgelight/shaders")):
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames[:] = sorted(d for d in dirnames if d != "__pycache__")
            for name in sorted(filenames):
                if name.endswith(".pyc"):
                    continue
                path = os.path.join(dirpath, name)
                yield path, prefix + "/" + os.path.relpath(path, base).replace(os.sep, "/")


def main(root, library, out, platform="linux-x64"):
    """The package of `platform` (a key of platforms.LIBRARY_FILES) holding `library`: its own
    library file name, checksum record and manifest platforms line."""
    manifest = os.path.join(root, "addon", "blender_manifest.toml")
    version, legacy = manifest_version(manifest), bl_info_version(os.path.join(root, "addon", "__init__.py"))
    if version != legacy:
        raise SystemExit(f"blender_manifest.toml version {version} != bl_info version {legacy}")
    name = platforms.LIBRARY_FILES[platform]
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    tmp = out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for path, arcname in files(root):
            if arcname == "edgelight/blender_manifest.toml":
                with open(path, encoding="utf-8") as f:
                    text = re.sub(r'^platforms\s*=.*$', f'platforms = ["{platform}"]', f.read(), count=1, flags=re.M)
                z.writestr(arcname, text)
                continue
            z.write(path, arcname)
        z.write(library, "edgelight/" + name)
        record = dict(library_check.make_record(library), file=name)
        z.writestr("edgelight/" + os.path.splitext(name)[0] + ".json", json.dumps(record, indent=1) + "\n")
    os.replace(tmp, out)
    print(f"package: {out}")


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5):
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
