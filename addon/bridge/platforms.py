"""The platforms EdgeLight ships for: each one's Blender extension platform name and the file
name of its native library. One table: the loader (native.py) picks the library by sys.platform,
scripts/make_package.py writes each platform's package. No bpy: plain Python imports it."""
import sys

# Blender's extension platform -> the library's file name in the package (beside __init__.py).
LIBRARY_FILES = {
    "linux-x64": "libedgelight.so",
    "windows-x64": "edgelight.dll",
    "macos-arm64": "libedgelight.dylib",
    "macos-x64": "libedgelight.dylib",
}


def library_file(system=None):
    """The library's file name on `system` (sys.platform by default)."""
    system = system or sys.platform
    if system.startswith("win"):
        return LIBRARY_FILES["windows-x64"]
    if system == "darwin":
        return LIBRARY_FILES["macos-arm64"]
    return LIBRARY_FILES["linux-x64"]

