#!/usr/bin/env bash
# The README's main job: set up, build, install the add-on into an isolated Blender user
# directory, and render the toon sample (fandisk: toon ramp, ink lines, edge highlights) headless
# with EdgeLight to a PNG. `./scripts/run.sh cube` renders the cube sample (the paper's figure 3) instead.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
sample="${1:-toon}"
"$root/scripts/setup.sh"
BUILD_DIR="$build" "$root/scripts/build.sh" >/dev/null
user_scripts="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh")"
mkdir -p "$root/out"
BLENDER_USER_SCRIPTS="$user_scripts" blender -b --addons edgelight "$root/blend_samples/$sample.blend" \
  -E EDGELIGHT -o "$root/out/${sample}_#" -F PNG -f 1 2>&1 | grep -E "^(Saved|Error|Warning)|EdgeLight" || true
png="$root/out/${sample}_1.png"
[ -f "$png" ] || { echo "main job: no image was written" >&2; exit 1; }
echo "main job: wrote $png"
