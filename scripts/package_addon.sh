#!/usr/bin/env bash
# Builds the add-on zip an artist installs (Edit > Preferences > Add-ons > Install...):
# out/edgelight-addon.zip with edgelight/ (Python, shaders, libedgelight.so for linux-x64).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
BUILD_DIR="$build" "$root/scripts/build.sh" >/dev/null
user_scripts="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh")"
mkdir -p "$root/out"
rm -f "$root/out/edgelight-addon.zip"
(cd "$user_scripts/addons" && python3 -m zipfile -c "$root/out/edgelight-addon.zip" edgelight)
echo "package: $root/out/edgelight-addon.zip"
