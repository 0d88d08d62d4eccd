#!/usr/bin/env bash
# Builds the add-on package an artist installs (see README): out/edgelight-VERSION-linux-x64.zip,
# one zip for Blender 4.2+ (extension) and 3.4 (legacy add-on). Same as
# `cmake --build build --target package_addon`, then a copy into out/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target package_addon >/dev/null
zip="$(ls -t "$build"/edgelight-*-linux-x64.zip | head -1)"
mkdir -p "$root/out"
cp "$zip" "$root/out/"
echo "package: $root/out/$(basename "$zip")"
