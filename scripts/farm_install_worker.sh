#!/usr/bin/env bash
# Installs the EdgeLight package on a render worker, headless, for the Blender it is given:
#
#   farm_install_worker.sh PACKAGE.zip [BLENDER...]
#
# BLENDER (default: blender) is the command, e.g. /opt/blender-4.2/blender, or for PyPI's bpy
# "VENV/bin/python farm/blender_bpy.py". The user directory is Blender's own, or the one
# BLENDER_USER_RESOURCES (4.2+) / BLENDER_USER_SCRIPTS (3.4) names.
#   4.2+: blender --command extension install-file -r user_default --enable PACKAGE.zip
#         (an extension, enabled in the saved preferences: renders need no --addons)
#   < 4.2: the zip unpacked into USER_SCRIPTS/addons/edgelight (a legacy add-on: render with
#         `blender -b --addons edgelight ...`, as the farm template does)
set -euo pipefail
package="${1:?usage: farm_install_worker.sh PACKAGE.zip [BLENDER...]}"
shift
[ $# -gt 0 ] || set -- blender
[ -s "$package" ] || { echo "farm_install_worker: no package at $package" >&2; exit 1; }
package="$(cd "$(dirname "$package")" && pwd)/$(basename "$package")"

read -r major minor < <("$@" --version 2>/dev/null | sed -n 's/^Blender \([0-9]*\)\.\([0-9]*\).*/\1 \2/p' | head -1; echo 0 0)
[ "$major" -gt 0 ] || { echo "farm_install_worker: '$* --version' names no Blender version" >&2; exit 1; }

if [ "$major" -gt 4 ] || { [ "$major" -eq 4 ] && [ "$minor" -ge 2 ]; }; then
  "$@" --command extension install-file -r user_default --enable "$package"
  echo "farm_install_worker: EdgeLight installed as an extension of Blender $major.$minor"
  exit 0
fi

# 3.4 has no extensions. Its user-scripts directory: BLENDER_USER_SCRIPTS, else Blender's own.
scripts="${BLENDER_USER_SCRIPTS:-}"
if [ -z "$scripts" ]; then
  scripts="$("$@" -b --factory-startup --python-expr \
    "import bpy; print('USER_SCRIPTS=' + bpy.utils.user_resource('SCRIPTS'))" 2>/dev/null \
    | sed -n 's/^USER_SCRIPTS=//p')"
fi
[ -n "$scripts" ] || { echo "farm_install_worker: cannot find Blender's user-scripts directory" >&2; exit 1; }
rm -rf "$scripts/addons/edgelight"
mkdir -p "$scripts/addons"
python3 -m zipfile -e "$package" "$scripts/addons"
[ -f "$scripts/addons/edgelight/__init__.py" ] || { echo "farm_install_worker: $package holds no edgelight/" >&2; exit 1; }
echo "farm_install_worker: EdgeLight installed in $scripts/addons for Blender $major.$minor (enable with --addons edgelight)"
