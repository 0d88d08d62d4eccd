#!/usr/bin/env bash
# The library for macOS, arm64 and x86_64, from the project's CMake with zig's clang and linker
# (PyPI's ziglang, build/zig: scripts/setup.sh; cmake/macos.cmake). Nothing built here can run
# here, so each slice is checked with LLVM's Mach-O tools: its architecture, its minimum macOS
# (11.0: Blender 4.2 supports 11.2 and later), that it needs nothing but libSystem, and that it
# exports the C API of edgelight.h (and the global operators new and delete C++ makes
# replaceable), nothing else. Called by ctest (native.macos); prints 'macos: N passed, N failed'.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
python="$build/zig/venv/bin/python"
"$python" -m ziglang version >/dev/null 2>&1 || { echo "macos: 0 passed, 1 failed: no zig in $build/zig (scripts/setup.sh installs ziglang)"; exit 1; }
command -v llvm-objdump-14 >/dev/null || { echo "macos: 0 passed, 1 failed: llvm-objdump-14 missing"; exit 1; }
wrappers="$build/zig/wrappers"
mkdir -p "$wrappers"
for tool in "zcc cc" "zcxx c++" "zar ar" "zranlib ranlib"; do
  set -- $tool
  target=""
  case "$2" in cc|c++) target='-target ${EL_ZIG_TARGET}' ;; esac
  printf '#!/bin/sh\nexec "%s" -m ziglang %s %s "$@"\n' "$python" "$2" "$target" >"$wrappers/$1"
  chmod +x "$wrappers/$1"
done
header="$(grep -cE '^EL_API ' "$root/native/include/edgelight/edgelight.h")"
passed=0 failed=0
for slice in "arm64 aarch64-macos.11.0 ARM64" "x86_64 x86_64-macos.11.0 X86_64"; do
  set -- $slice
  arch=$1 target=$2 cputype=$3
  dir="$build/macos-$arch"
  export EL_ZIG_TARGET="$target"
  if ! cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE="$root/cmake/macos.cmake" \
       -DEL_ZIG_WRAPPERS="$wrappers" -DEL_MACOS_ARCH="$arch" >"$dir.log" 2>&1 ||
     ! cmake --build "$dir" --target edgelight -j"$(nproc)" >>"$dir.log" 2>&1; then
    tail -30 "$dir.log"; echo "macos $arch: the build failed"; failed=$((failed + 1)); continue
  fi
  lib="$dir/native/libedgelight.dylib"
  why=""
  headers="$(llvm-objdump-14 --macho --private-headers "$lib")"
  grep -qE "^MH_MAGIC_64 +$cputype " <<<"$headers" || why+=" not $cputype;"
  [ "$(grep -A4 LC_BUILD_VERSION <<<"$headers" | awk '/minos/ {print $2}')" = "11.0" ] || why+=" minimum macOS not 11.0;"
  deps="$(llvm-objdump-14 --macho --dylibs-used "$lib" | tail -n +3 | awk '{print $1}' | tr '\n' ' ')"
  [ "$deps" = "/usr/lib/libSystem.B.dylib " ] || why+=" needs $deps;"
  exported="$(llvm-nm-14 -gU "$lib" | awk '{print $3}')"
  el="$(grep -c '^_el_' <<<"$exported" || true)"
  other="$(grep -vE '^(_el_|__Zn[wa]m|__Zd[la]Pv|___dso_handle$|__mh_dylib_header$)' <<<"$exported" | tr '\n' ' ' || true)"
  [ "$el" = "$header" ] || why+=" exports $el el_ functions, edgelight.h declares $header;"
  [ -z "$other" ] || why+=" also exports $other;"
  if [ -z "$why" ]; then
    echo "macos $arch: $(basename "$lib") $cputype, macOS 11.0+, needs only libSystem, exports the $el functions of edgelight.h"
    passed=$((passed + 1))
  else
    echo "macos $arch:$why"; failed=$((failed + 1))
  fi
done
if [ "$failed" = 0 ]; then  # one universal library of both slices, as a package would ship it
  llvm-lipo-14 -create "$build/macos-arm64/native/libedgelight.dylib" "$build/macos-x86_64/native/libedgelight.dylib" \
    -output "$build/macos-universal-libedgelight.dylib"
  echo "macos: universal $(llvm-lipo-14 -archs "$build/macos-universal-libedgelight.dylib")"
fi
echo "macos: $passed passed, $failed failed"
[ "$failed" = 0 ]
