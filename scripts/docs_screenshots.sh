#!/usr/bin/env bash
# Regenerates docs/img/: screenshots of what an artist sees, taken by the scripted UI session
# (tests/blender/viewport_session.py under xvfb-run, Blender 3.4's UI; build first).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
BUILD_DIR="$build" "$root/scripts/viewport_tests.sh" >/dev/null
mkdir -p "$root/docs/img"
for shot in rendered lines properties_material properties_data properties_world; do
  cp "$build/viewport_session/$shot.png" "$root/docs/img/ui_$shot.png"
done
echo "docs_screenshots: docs/img/ui_*.png from $build/viewport_session"
