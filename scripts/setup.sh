#!/usr/bin/env bash
# Installs what EdgeLight needs from Debian's packages (idempotent: apt runs only when something
# is missing). Needs root or sudo. The test command adds Blender 4.2 / 4.5 / 5.x (setup_bpy.sh).
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libglm-dev libassimp-dev nlohmann-json3-dev
  assimp-testmodels     # assimp's own valid and broken files: the tools must read or refuse each
  libosmesa6-dev libpng-dev  # edgelight-render: the add-on's shaders offscreen (llvmpipe), PNG out
  libgtest-dev libbenchmark-dev
  libcgal-demo          # classic meshes (cow, fandisk, bunny, armadillo) in data.tar.gz
  blender python3-numpy # Debian's Blender 3.4 (system Python 3.11) for the add-on
  python3-matplotlib    # the ground-truth benchmark's Pareto plot (bench/plot_ground_truth.py)
  python3-pil           # the farm tests read rendered PNGs (tests/farm)
  librsvg2-bin          # rsvg-convert: the SVG output tests rasterise the written SVG
  python3-venv          # venvs for Blender 4.2 / 4.5 / 5.x as Python modules (setup_bpy.sh)
  xvfb                  # the UI under xvfb-run for viewport tests
  xdotool               # presses Esc in the render window in the viewport session
  clang libclang-rt-14-dev  # libFuzzer + ASan/UBSan for the C API fuzz test (scripts/fuzz.sh)
  clang-format          # style.clang_format (.clang-format; ruff comes from PyPI below)
  g++-mingw-w64-x86-64-posix wine wine64 googletest  # the Windows DLL and its tests under wine (native.windows)
  llvm-14               # llvm-objdump, llvm-nm, llvm-lipo: the macOS slices checked (native.macos)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm (acorn for the farm tests): any npm will do, e.g. one that came with another nodejs.
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The farm tests' tools, cached under build/farm (reused while the stamp matches): openjd-cli in
# a venv of Debian's python3.11 (runs farm/edgelight-render.openjd.yaml), acorn from npm (parses
# the Flamenco job type). A failure leaves the farm tests failing, each saying what is missing.
farm="${BUILD_DIR:-$(cd "$(dirname "$0")/.." && pwd)/build}/farm"
want="openjd-cli==0.8.0 acorn@8.19.0"
if [ ! -f "$farm/stamp" ] || [ "$(cat "$farm/stamp")" != "$want" ]; then
  echo "setup: installing $want into $farm"
  rm -rf "$farm/venv" "$farm/node_modules"
  mkdir -p "$farm"
  if /usr/bin/python3.11 -m venv "$farm/venv" &&
     "$farm/venv/bin/python" -m pip install --no-cache-dir --disable-pip-version-check -q "openjd-cli==0.8.0" &&
     npm install --prefix "$farm" --no-audit --no-fund --silent "acorn@8.19.0" >/dev/null; then
    echo "$want" > "$farm/stamp"
  else
    echo "setup: installing the farm tools failed (the farm tests will say so)" >&2
  fi
fi

# A pinned PyPI tool in its own venv under build/NAME, reused while the stamp matches; a failure
# leaves the tests that need it failing, each saying so.
pip_tool() {
  local dir="${BUILD_DIR:-$(cd "$(dirname "$0")/.." && pwd)/build}/$1" want="$2" why="$3"
  if [ ! -f "$dir/stamp" ] || [ "$(cat "$dir/stamp")" != "$want" ]; then
    echo "setup: installing $want into $dir"
    rm -rf "$dir/venv"
    mkdir -p "$dir"
    if /usr/bin/python3.11 -m venv "$dir/venv" &&
       "$dir/venv/bin/python" -m pip install --no-cache-dir --disable-pip-version-check -q "$want"; then
      echo "$want" > "$dir/stamp"
    else
      echo "setup: installing $want failed ($why will say so)" >&2
    fi
  fi
}

# ruff for style.ruff (ruff.toml), pinned so that its rules do not move under the tests.
pip_tool lint "ruff==0.17.6" style.ruff
# zig (PyPI's ziglang): the macOS library's cross compiler and linker (scripts/macos_slices.sh).
pip_tool zig "ziglang==0.17.1" native.macos
