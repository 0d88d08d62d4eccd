#!/usr/bin/env bash
# The README's main job. Until the Blender add-on lands, it shows what the native core sees in a
# real mesh: edge statistics of libcgal-demo's fandisk as JSON, written to out/fandisk.json.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
BUILD_DIR="$build" "$root/scripts/build.sh"
mkdir -p "$root/out"
"$build/native/tools/edgelight-info" "$build/meshes/fandisk.off" --crease 30 | tee "$root/out/fandisk.json"
echo "main job: wrote $root/out/fandisk.json"
