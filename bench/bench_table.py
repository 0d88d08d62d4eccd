"""Rewrite one benchmark's section of BENCHMARKS.md with its current table.

BENCHMARKS.md holds one section per benchmark, its content between two markers:

    <!-- bench:NAME -->
    ...
    <!-- /bench:NAME -->

A benchmark script (or a person, from its output) calls rewrite(NAME, text) to replace what lies
between them; everything else in the file is left as it is. The dated history of the benchmarks
is in docs/benchmark_history.md, which this never touches. Pure Python, no bpy:

    python3 bench/bench_table.py NAME FILE    # section NAME := FILE's content
"""
import re
import sys
from pathlib import Path

DEFAULT_PATH = Path(__file__).resolve().parent.parent / "BENCHMARKS.md"


def rewrite(name, text, path=None):
    """Replace the text between NAME's markers in BENCHMARKS.md (or path) with text."""
    if not re.fullmatch(r"[A-Za-z0-9_.-]+", name or ""):
        raise ValueError(f"bench section name {name!r}: use letters, digits, '_', '.', '-'")
    path = Path(path) if path is not None else DEFAULT_PATH
    doc = path.read_text(encoding="utf-8")
    start, end = f"<!-- bench:{name} -->", f"<!-- /bench:{name} -->"
    for marker in (start, end):
        count = doc.count(marker)
        if count != 1:
            found = "missing" if count == 0 else f"found {count} times"
            raise ValueError(f"section {name!r} in {path}: marker {marker!r} {found} (need exactly one)")
    i, j = doc.index(start) + len(start), doc.index(end)
    if j < i:
        raise ValueError(f"section {name!r} in {path}: {end!r} comes before {start!r}")
    doc = doc[:i] + "\n" + text.strip("\n") + "\n" + doc[j:]
    path.write_text(doc, encoding="utf-8")


def main(argv):
    if len(argv) != 3:
        print(f"usage: python3 {argv[0]} NAME FILE", file=sys.stderr)
        return 2
    try:
        rewrite(argv[1], Path(argv[2]).read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        print(f"bench_table: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
