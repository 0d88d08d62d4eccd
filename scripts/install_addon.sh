#!/usr/bin/env bash
# Assembles the add-on package (Python, shaders, native library) and installs it into an
# isolated Blender user directory: ${BUILD_DIR}/blender_user/scripts/addons/edgelight.
# Prints the BLENDER_USER_SCRIPTS value to use.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
pkg="$build/blender_user/scripts/addons/edgelight"
rm -rf "$pkg"
mkdir -p "$pkg"
cp -r "$root/addon/." "$pkg/"
cp -r "$root/shaders" "$pkg/shaders"
cp "$build/native/libedgelight.so" "$pkg/libedgelight.so"
find "$pkg" -name __pycache__ -prune -exec rm -rf {} +
echo "$build/blender_user/scripts"
