#!/usr/bin/env bash
# style.clang_format: every C, C++ and GLSL file under native/, tests/ and shaders/ is unchanged
# by clang-format (.clang-format at the root, shaders/.clang-format for GLSL), except the files
# listed in clang_format_exempt.txt. Usage: check_clang_format.sh ROOT [CLANG_FORMAT]
set -uo pipefail
root="$1"
clang_format="${2:-clang-format}"
if ! command -v "$clang_format" >/dev/null; then
  echo "style.clang_format: $clang_format not found (Debian's clang-format; scripts/setup.sh installs it)" >&2
  exit 1
fi
cd "$root" || exit 1
exempt_list=tests/style/clang_format_exempt.txt
declare -A exempt=()
while read -r f; do
  case "$f" in ''|'#'*) continue ;; esac
  [ -f "$f" ] || { echo "style.clang_format: $exempt_list names $f, which does not exist" >&2; exit 1; }
  exempt[$f]=1
done < "$exempt_list"

checked=0; failed=0; exempt_differ=0; exempt_conform=()
while IFS= read -r -d '' f; do
  f="${f#./}"
  if [ -n "${exempt[$f]:-}" ]; then
    if "$clang_format" --dry-run --Werror "$f" >/dev/null 2>&1; then exempt_conform+=("$f"); else exempt_differ=$((exempt_differ + 1)); fi
    continue
  fi
  checked=$((checked + 1))
  if ! "$clang_format" --dry-run --Werror "$f"; then
    failed=$((failed + 1))
    echo "style.clang_format: $f differs from clang-format (see above; \`clang-format -i $f\` fixes it)" >&2
  fi
done < <(find native tests shaders -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.hpp' \
           -o -name '*.glsl' \) -print0 | sort -z)

echo "style.clang_format: $checked files checked with $("$clang_format" --version | sed 's/.*version //'), $failed differ;" \
     "${#exempt[@]} exempt ($exempt_list), $exempt_differ of them not yet formatted"
for f in "${exempt_conform[@]}"; do
  echo "style.clang_format: $f is formatted now: drop it from $exempt_list"
done
[ "$checked" -gt 0 ] && [ "$failed" -eq 0 ]
