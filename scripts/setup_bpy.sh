#!/usr/bin/env bash
# Blender as a Python module (PyPI's `bpy`, CPython 3.11 wheels) for the version matrix: one
# venv per version under ${BUILD_DIR}/bpy/venv-VERSION, made with Debian's python3.11. A venv
# whose stamp matches is reused, so re-runs download nothing. Called by setup.sh.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
python=/usr/bin/python3.11  # the wheels are cp311; Debian 12's python3

# version name in ctest -> pip requirements (the newest release of that line). bpy 4.2's wheel
# leaves numpy unpinned (pip then takes 2.x); 4.5's and 5.0's pin numpy<2: pin 4.2 alike.
declare -A spec=([4.2]="bpy==4.2.* numpy<2" [4.5]="bpy==4.5.*" [5]="bpy>=5,<6")

for version in 4.2 4.5 5; do
  venv="$build/bpy/venv-$version"
  stamp="$venv/edgelight-stamp"
  want="$python ${spec[$version]}"
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
    continue
  fi
  echo "setup: installing ${spec[$version]} into $venv (about 300 MB)"
  rm -rf "$venv"
  "$python" -m venv "$venv"
  read -ra requirements <<< "${spec[$version]}"  # words, never globbed
  "$venv/bin/python" -m pip install --no-cache-dir --disable-pip-version-check -q "${requirements[@]}"
  "$venv/bin/python" -c "import bpy; print('setup: bpy', bpy.app.version_string)" 2>/dev/null | grep '^setup:'
  echo "$want" > "$stamp"
done
