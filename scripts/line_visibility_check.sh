#!/usr/bin/env bash
# Ink-line visibility against the ray-cast reference on bench/line_visibility_bench.py's eleven
# meshes (CAD parts with holes and bosses, an imported house of thin parts, a jointed figure, a
# hollow tube and a thin conical shell), EdgeLight only, at two sizes and three line widths: fails
# where any setting misses recall >= 98 % or stray ink <= 0.2 %. Outputs in BUILD_DIR/line_visibility.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
out="$build/line_visibility"
BLENDER_USER_SCRIPTS="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh" "$build/blender_user/line_visibility")"
export BLENDER_USER_SCRIPTS
exec blender -b --factory-startup --addons edgelight --python-exit-code 1 \
  --python "$root/bench/line_visibility_bench.py" -- --methods edgelight --check \
  --cache "$build/line_meshes" --out "$out/line_visibility.csv" --png-dir "$out/png"
