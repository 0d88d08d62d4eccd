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
  npm                   # acorn, which parses the Flamenco job type in the farm tests
  python3-venv          # venvs for Blender 4.2 / 4.5 / 5.x as Python modules (setup_bpy.sh)
  xvfb                  # the UI under xvfb-run for viewport tests
  xdotool               # presses Esc in the render window in the viewport session
  clang libclang-rt-14-dev  # libFuzzer + ASan/UBSan for the C API fuzz test (scripts/fuzz.sh)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
