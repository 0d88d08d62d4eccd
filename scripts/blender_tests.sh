#!/usr/bin/env bash
# Runs the add-on tests on one Blender version (headless, Mesa llvmpipe). Called by ctest.
#   blender_tests.sh 3.4        Debian's blender; the package unzipped as a legacy add-on
#   blender_tests.sh 4.2|4.5|5  PyPI's bpy (setup_bpy.sh); the package installed as an extension
# Both install the zip that ships (cmake target package_addon, built by scripts/build.sh) into
# an isolated user directory per version.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
version="${1:?usage: blender_tests.sh VERSION [-- -k PATTERN]}"
shift
[ "${1:-}" = "--" ] && shift
runner="$root/tests/blender/runner.py"
user="$build/blender_user/${EDGELIGHT_TEST_TAG:-$version}"  # per ctest entry: they run in parallel

if [ "$version" = "3.4" ]; then
  export BLENDER_USER_SCRIPTS="$(BUILD_DIR="$build" "$root/scripts/install_addon.sh" "$user/scripts")"
  export EDGELIGHT_MODULE=edgelight EDGELIGHT_EXPECT_BLENDER=3.4
  export EDGELIGHT_PACKAGE="$(ls -t "$build"/edgelight-*-linux-x64.zip | head -1)"
  exec blender -b --factory-startup --python-exit-code 1 --addons edgelight --python "$runner" -- "$@"
fi

python="$build/bpy/venv-$version/bin/python"
if [ ! -f "$build/bpy/venv-$version/edgelight-stamp" ]; then  # stamped once bpy installed
  echo "blender $version: 0 passed, 1 failed: no bpy venv at $build/bpy/venv-$version (run scripts/setup_bpy.sh)"
  exit 1
fi
zip="$(ls -t "$build"/edgelight-*-linux-x64.zip | head -1)"
unset BLENDER_USER_SCRIPTS
export BLENDER_USER_RESOURCES="$user"
rm -rf "$BLENDER_USER_RESOURCES"
mkdir -p "$BLENDER_USER_RESOURCES"
boot="$root/tests/blender/bpy_module.py"
"$python" "$boot" install "$zip" >"$BLENDER_USER_RESOURCES/install.log" 2>&1 || {
  cat "$BLENDER_USER_RESOURCES/install.log"
  echo "blender $version: 0 passed, 1 failed: extension install-file $zip failed"
  exit 1
}
export EDGELIGHT_MODULE=bl_ext.user_default.edgelight EDGELIGHT_EXPECT_BLENDER="$version"
[ "$version" = "5" ] && export EDGELIGHT_EXPECT_BLENDER=5.x
export EDGELIGHT_PACKAGE="$zip"
exec "$python" "$boot" run "$runner" -- "$@"
