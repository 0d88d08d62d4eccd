#!/usr/bin/env python3
"""Runs edgelight-info and edgelight-render over every file of assimp's test models that assimp
claims to import (Debian's assimp-testmodels: valid, odd and deliberately broken files), each
under an address-space limit and a timeout. A file may be read (exit 0) or refused (exit 1, the last line
on stderr the tool's message naming the file); anything else -- a signal, another exit code, a timeout, a silent refusal --
fails the test. The limit lives here, not in the tools: the tools must refuse on their own what
would not fit, and the limit turns a runaway allocation into a failure instead of a dead machine.
"""
import argparse
import concurrent.futures
import os
import subprocess
import sys
import tempfile
import time


def model_files(root, extensions):
    # Longest first so "mesh.xml" is matched before "xml"; a file counts once either way.
    exts = sorted(("." + e for e in extensions), key=len, reverse=True)
    files = []
    for d, _, names in os.walk(root):
        for n in names:
            if any(n.lower().endswith(e) for e in exts):
                files.append(os.path.join(d, n))
    return sorted(files)


def run(cmd, path, mem_mb, timeout):
    """(verdict, detail): verdict is "ok", "refused" or a failure description."""
    limited = ["prlimit", f"--as={mem_mb * 1024 * 1024}", "--"] + cmd
    t0 = time.monotonic()
    try:
        p = subprocess.run(limited, stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return f"timeout after {timeout} s", ""
    secs = time.monotonic() - t0
    err = p.stderr.decode(errors="replace").strip()
    if p.returncode == 0:
        return "ok", f"{secs:.1f} s"
    if p.returncode < 0:
        return f"killed by signal {-p.returncode}", err[-300:]
    if p.returncode != 1:
        return f"exit code {p.returncode}", err[-300:]
    if not err:
        return "exit 1 without a message", ""
    # The tool's own line comes last; assimp's parsers may print before it (OpenGEX's does).
    last = err.splitlines()[-1]
    if not (last.startswith(os.path.basename(cmd[0]) + ": ") and path in last):
        return "exit 1 without a last line '<tool>: ... <file> ...'", err[-300:]
    # Refusing only because the allocation hit the test's limit means the tool would have taken
    # whatever memory the machine has: the caps must refuse first.
    if "bad_alloc" in last or "out of memory" in last:
        return "refused only by the memory limit", last
    return "refused", last


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--info", required=True)
    ap.add_argument("--render", required=True)
    ap.add_argument("--extensions", required=True, help="helper printing assimp's extensions")
    ap.add_argument("--models", default="/usr/share/assimp/models")
    ap.add_argument("--mem-mb", type=int, default=2048)
    ap.add_argument("--timeout", type=float, default=20.0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()

    if not os.path.isdir(a.models):
        print(f"{a.models} missing: install assimp-testmodels (scripts/setup.sh)", file=sys.stderr)
        return 1
    extensions = subprocess.run([a.extensions], capture_output=True, text=True, check=True).stdout.split()
    files = model_files(a.models, extensions)
    if not files:
        print(f"no model files under {a.models}", file=sys.stderr)
        return 1

    others = sum(len(names) for _, _, names in os.walk(a.models)) - len(files)
    print(f"{len(files)} files under {a.models} have an extension assimp imports; {others} others "
          "(textures, buffers, notes) are not meshes to try")
    out_dir = tempfile.mkdtemp(prefix="edgelight-sweep-")

    def both(i, path):
        info = run([a.info, path], path, a.mem_mb, a.timeout)
        png = os.path.join(out_dir, f"{i}.png")
        render = run([a.render, path, "--out", png, "--size", "64x48", "--samples", "1"], path, a.mem_mb,
                     a.timeout)
        if os.path.exists(png):
            os.remove(png)
        return path, info, render

    t0 = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        results = list(pool.map(lambda ip: both(*ip), enumerate(files)))
    os.rmdir(out_dir)

    failures = []
    counts = {"edgelight-info": {"ok": 0, "refused": 0}, "edgelight-render": {"ok": 0, "refused": 0}}
    for path, *verdicts in results:
        rel = os.path.relpath(path, a.models)
        for tool, (verdict, detail) in zip(counts, verdicts):
            if verdict in counts[tool]:
                counts[tool][verdict] += 1
                if a.verbose:
                    print(f"{tool} {verdict}: {rel}  {detail}")
            else:
                failures.append(f"{tool} {rel}: {verdict}" + (f"\n    {detail}" if detail else ""))
    for tool, c in counts.items():
        print(f"{tool}: {len(files)} files tried, {c['ok']} read, {c['refused']} refused with exit 1, "
              f"{len(files) - c['ok'] - c['refused']} failed")
    print(f"({len(extensions)} assimp extensions, {a.mem_mb} MB address space, {a.timeout:g} s per run, "
          f"{time.monotonic() - t0:.0f} s)")
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
