#!/usr/bin/env bash
# Unzips the built add-on package (build first: scripts/build.sh) as a legacy add-on into an
# isolated Blender user directory, ${1:-${BUILD_DIR}/blender_user/scripts}/addons/edgelight
# (Blender 3.4's way; later versions read legacy add-ons there too). Prints the
# BLENDER_USER_SCRIPTS value to use.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
scripts="${1:-$build/blender_user/scripts}"
zip="$(ls -t "$build"/edgelight-*-linux-x64.zip 2>/dev/null | head -1)"
[ -n "$zip" ] || { echo "install_addon: no package in $build (run scripts/build.sh)" >&2; exit 1; }
rm -rf "$scripts/addons/edgelight"
mkdir -p "$scripts/addons"
python3 -m zipfile -e "$zip" "$scripts/addons"
echo "$scripts"
