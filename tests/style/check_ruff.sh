#!/usr/bin/env bash
# style.ruff: `ruff check` (ruff.toml at the root) over every directory with Python in it.
# Usage: check_ruff.sh ROOT RUFF (RUFF: build/lint/venv/bin/ruff, which scripts/setup.sh installs).
set -uo pipefail
root="$1"
ruff="$2"
if [ ! -x "$ruff" ]; then
  echo "style.ruff: $ruff not found (scripts/setup.sh installs ruff into build/lint/venv)" >&2
  exit 1
fi
cd "$root" || exit 1
# --no-cache: no .ruff_cache in the source tree.
"$ruff" check --no-cache addon bench blend_samples farm scripts tests && echo "style.ruff: passed ($("$ruff" --version))"
