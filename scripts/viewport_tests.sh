#!/usr/bin/env bash
# The viewport tests: real Blender UI under xvfb-run (Mesa llvmpipe), scripted by
# tests/blender/viewport_session.py on the cube sample. Called by ctest.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
user_scripts="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh" "$build/blender_user/viewport/scripts")"
out="$build/viewport_session"
rm -rf "$out"
mkdir -p "$out"
export BLENDER_USER_SCRIPTS="$user_scripts"
exec xvfb-run -a -s "-screen 0 1400x1000x24" blender --factory-startup --addons edgelight \
  "$root/blend_samples/cube.blend" --python "$root/tests/blender/viewport_session.py" -- "$out"
