#!/usr/bin/env bash
# The library for Windows x64 and its GoogleTest suite: cross-built with Debian's mingw-w64
# (cmake/windows-x64.cmake: the project's CMake, the library and its tests only), checked to
# depend on no DLL Blender lacks and to export the C API, then run under wine with the Linux
# tolerances. Called by ctest (native.windows); prints one line 'windows: N passed, N failed'.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}/windows"
for tool in x86_64-w64-mingw32-g++-posix wine; do
  command -v "$tool" >/dev/null || { echo "windows: 0 passed, 1 failed: $tool missing (scripts/setup.sh installs mingw-w64 and wine)"; exit 1; }
done
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE="$root/cmake/windows-x64.cmake" \
  -DEDGELIGHT_GTEST_SOURCE=/usr/src/googletest >"$build.configure.log" 2>&1 || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j"$(nproc)" >"$build.build.log" 2>&1 || { tail -40 "$build.build.log"; exit 1; }
dll="$build/native/edgelight.dll"
# Only the system's own DLLs: Blender ships no mingw runtime (error 126 on load).
deps="$(x86_64-w64-mingw32-objdump -p "$dll" | sed -n 's/^\tDLL Name: //p' | sort | tr '\n' ' ')"
[ "$deps" = "KERNEL32.dll msvcrt.dll " ] || { echo "windows: 0 passed, 1 failed: edgelight.dll needs $deps"; exit 1; }
exports="$(x86_64-w64-mingw32-objdump -p "$dll" | grep -cE '^\s+\[ *[0-9]+\] el_')"
header="$(grep -cE '^EL_API ' "$root/native/include/edgelight/edgelight.h")"
[ "$exports" = "$header" ] || { echo "windows: 0 passed, 1 failed: edgelight.dll exports $exports el_ functions, edgelight.h declares $header"; exit 1; }
echo "windows: edgelight.dll needs only $deps and exports the $exports functions of edgelight.h"
cp "$dll" "$build/tests/native/"
export WINEPREFIX="$build/wineprefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
cd "$build/tests/native"
set +e
wine edgelight_tests.exe --gtest_brief=1 >"$build/tests.log" 2>&1
rc=$?
set -e
tail -5 "$build/tests.log"
passed="$(sed -n 's/^\[  PASSED  \] \([0-9]*\) tests\?\..*/\1/p' "$build/tests.log")"
failed="$(sed -n 's/^\[  FAILED  \] \([0-9]*\) tests\?, listed below:/\1/p' "$build/tests.log")"
echo "windows: ${passed:-0} passed, ${failed:-0} failed"
[ "$rc" = 0 ] && [ -n "$passed" ]
