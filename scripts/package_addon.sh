#!/usr/bin/env bash
# Builds the add-on package of every platform an artist installs (see README), into
# ${OUT_DIR:-out}/edgelight-VERSION-PLATFORM.zip: linux-x64 (the cmake target package_addon),
# windows-x64 (mingw-w64: cmake/windows-x64.cmake), macos-arm64 and macos-x64 (zig:
# scripts/macos_slices.sh, which also checks each slice). Each zip serves Blender 4.2+ (an
# extension whose manifest names its platform) and 3.4 (a legacy add-on), with its own library
# and checksum record.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
out="${OUT_DIR:-$root/out}"
"$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target package_addon >/dev/null
mkdir -p "$out"
linux="$(ls -t "$build"/edgelight-*-linux-x64.zip | head -1)"
cp "$linux" "$out/"
echo "package: $out/$(basename "$linux")"
version="$(basename "$linux" | sed 's/^edgelight-\(.*\)-linux-x64\.zip$/\1/')"
cmake -S "$root" -B "$build/windows" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE="$root/cmake/windows-x64.cmake" \
  -DEDGELIGHT_GTEST_SOURCE=/usr/src/googletest >/dev/null
cmake --build "$build/windows" --target edgelight >/dev/null
python3 "$root/scripts/make_package.py" "$root" "$build/windows/native/edgelight.dll" "$out/edgelight-$version-windows-x64.zip" windows-x64
BUILD_DIR="$build" "$root/scripts/macos_slices.sh" >/dev/null
for arch in arm64:macos-arm64 x86_64:macos-x64; do
  python3 "$root/scripts/make_package.py" "$root" "$build/macos-${arch%%:*}/native/libedgelight.dylib" \
    "$out/edgelight-$version-${arch#*:}.zip" "${arch#*:}"
done
