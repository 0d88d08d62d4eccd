"""Checks the native library's file before ctypes maps it. The dynamic loader maps the file, and
touching a page past the end of a truncated one kills the whole process with SIGBUS: a damaged
library must be refused before ctypes.CDLL, while refusing is still possible.

The record beside the library (libedgelight.so -> libedgelight.json) is required: the file's
size and SHA-256 must equal it. Without one a damaged file could only be judged by its format's
headers, and a flipped byte inside passes any such check and crashes Blender when it runs.
scripts/make_package.py writes the record into every package, and the build writes one beside
each library it makes (`python3 addon/bridge/library_check.py LIBRARY`), so a developer build named by
EDGELIGHT_LIBRARY is checked the same way. Nothing here reads a format's headers, so the check
is the same for ELF, PE and Mach-O.

Plain Python (no ctypes, no bpy): scripts/make_package.py imports it to write the record.
"""
import hashlib
import json
import os
import sys


class Corrupt(Exception):
    """The file is not the library it should be; the message names it and says why."""


def record_path(library):
    return os.path.splitext(library)[0] + ".json"


def make_record(library):
    """The record of `library`: {"file": name, "size": bytes, "sha256": hex digest}."""
    return {"file": os.path.basename(library), "size": os.path.getsize(library), "sha256": sha256(library)}


_digests = {}  # (path, size, mtime, inode) -> digest: hashed once per file per process


def sha256(path):
    st = os.stat(path)
    key = (os.path.abspath(path), st.st_size, st.st_mtime_ns, st.st_ino)
    if key not in _digests:
        h = hashlib.sha256()
        with open(path, "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
        _digests[key] = h.hexdigest()
    return _digests[key]


def check(library):
    """Raises Corrupt unless the file at `library` matches its record; returns "record"."""
    size = os.path.getsize(library)
    record_file = record_path(library)
    if not os.path.exists(record_file):
        raise Corrupt(f"{library} has no checksum record ({os.path.basename(record_file)} beside it), so it "
                      "cannot be checked before it is loaded: reinstall the add-on (a developer build writes "
                      "one: python3 addon/bridge/library_check.py LIBRARY)")
    try:
        with open(record_file, encoding="utf-8") as f:
            record = json.load(f)
        want_size, want_sha = int(record["size"]), str(record["sha256"])
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise Corrupt(f"{record_file} (the record of {library}) is unreadable: {e}") from None
    if size != want_size:
        raise Corrupt(f"{library} is {size} bytes but {os.path.basename(record_file)} records {want_size}: "
                      "the file is truncated or replaced; reinstall the add-on")
    if sha256(library) != want_sha:
        raise Corrupt(f"{library} does not match the SHA-256 checksum in {os.path.basename(record_file)}: "
                      "the file is damaged or replaced; reinstall the add-on")
    return "record"


def write_record(library, name=None):
    """Writes `library`'s record beside it (`name`: the file name it records, by default its own)."""
    record = make_record(library)
    if name:
        record["file"] = name
    with open(record_path(library), "w", encoding="utf-8") as f:
        json.dump(record, f, indent=1)
        f.write("\n")


if __name__ == "__main__":  # the build: python3 addon/bridge/library_check.py LIBRARY...
    for path in sys.argv[1:]:
        write_record(path)
