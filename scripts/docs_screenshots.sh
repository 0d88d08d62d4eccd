#!/usr/bin/env bash
# Regenerates docs/img/: screenshots of what an artist sees, from Blender 3.4's UI under
# xvfb-run (build first). Two scripted sessions:
#   - the viewport tests' (tests/blender/viewport_session.py, scripts/viewport_tests.sh): the
#     Rendered 3D view and the Material, Light and World tabs (ui_*.png);
#   - tests/blender/docs_session.py: highlights off and on, each line type, the toon modes, the
#     compositor's node tree and a render's passes, and the material panel's radius clamp note.
# Each session checks that its shots show their feature and fails otherwise; then
# scripts/docs_images.py crops them, lays them out with captions and writes small PNGs.
# EDGELIGHT_DOCS_SHOTS=toon,lines (groups of docs_session.py) retakes only those groups.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
if [ -z "${EDGELIGHT_DOCS_SHOTS:-}" ]; then
  BUILD_DIR="$build" "$root/scripts/viewport_tests.sh" >"$build/viewport_session.log" 2>&1 || {
    grep -E "FAIL|viewport:" "$build/viewport_session.log" >&2
    echo "docs_screenshots: the viewport session failed (log: $build/viewport_session.log)" >&2
    exit 1
  }
fi
out="$build/docs_session"
[ -n "${EDGELIGHT_DOCS_SHOTS:-}" ] || rm -rf "$out"
mkdir -p "$out"
export BLENDER_USER_SCRIPTS="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh" "$build/blender_user/docs/scripts")"
# A .blend on the command line keeps Blender's splash screen away.
xvfb-run -a -s "-screen 0 1400x1000x24" blender --factory-startup --addons edgelight \
  "$root/blend_samples/cube.blend" --python "$root/tests/blender/docs_session.py" -- "$out" >"$out/session.log" 2>&1 || {
  grep -E "FAIL|docs session:|Error" "$out/session.log" >&2
  echo "docs_screenshots: the docs session failed (log: $out/session.log)" >&2
  exit 1
}
grep -E "docs session:" "$out/session.log"
/usr/bin/python3 "$root/scripts/docs_images.py" "$build/viewport_session" "$out" "$root/docs/img"
