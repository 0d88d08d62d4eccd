#!/usr/bin/env bash
# Runs the add-on tests inside Debian's Blender (headless, Mesa llvmpipe): installs the freshly
# built add-on into an isolated user directory first. Called by ctest.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
user_scripts="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh")"
export BLENDER_USER_SCRIPTS="$user_scripts"
exec blender -b --factory-startup --python-exit-code 1 --addons edgelight \
  --python "$root/tests/blender/runner.py" -- "$@"
