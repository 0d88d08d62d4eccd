"""Checks the native library's file before ctypes maps it. The dynamic loader maps the file, and
touching a page past the end of a truncated one kills the whole process with SIGBUS: a damaged
library must be refused before ctypes.CDLL, while refusing is still possible.

With a record beside the library (libedgelight.so -> libedgelight.json, written by
scripts/make_package.py), the file's size and SHA-256 must equal the record's. Without one (a
developer build named by EDGELIGHT_LIBRARY) the file must be ELF and long enough for every
segment and section its headers declare, which catches truncation.

Plain Python (no ctypes, no bpy): scripts/make_package.py imports it to write the record.
"""
import hashlib
import json
import os
import struct


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
    """Raises Corrupt unless the file at `library` passes; returns "record" or "elf", the check made."""
    size = os.path.getsize(library)
    record_file = record_path(library)
    if not os.path.exists(record_file):
        check_elf(library, size)
        return "elf"
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


# ELF header fields after e_ident, and the program/section header fields read here
# (offset and size in the file), for 32- and 64-bit files.
_HEADER = {1: "HHIIIIIHHHHHH", 2: "HHIQQQIHHHHHH"}  # e_type .. e_shstrndx
_PHDR = {1: ("IIIIIIII", 1, 4), 2: ("IIQQQQQQ", 2, 5)}  # format, index of p_offset, of p_filesz
_SHDR = {1: ("IIIIIIIIII", 4, 5), 2: ("IIQQQQIIQQ", 4, 5)}  # format, index of sh_offset, of sh_size
_SHT_NOBITS = 8  # .bss: occupies no bytes of the file


def check_elf(library, size):
    """Raises Corrupt unless `library` is an ELF file of at least the size its headers declare."""
    with open(library, "rb") as f:
        data = f.read()
    if len(data) < 16 or data[:4] != b"\x7fELF" or data[4] not in (1, 2) or data[5] not in (1, 2):
        raise Corrupt(f"{library} ({size} bytes) is not an ELF library: truncated or not a library")
    bits, order = data[4], "<" if data[5] == 1 else ">"
    header = struct.Struct(order + "16x" + _HEADER[bits])
    if len(data) < header.size:
        raise Corrupt(f"{library} is {size} bytes, shorter than its ELF header: the file is truncated")
    fields = header.unpack_from(data)
    phoff, shoff, phentsize, phnum, shentsize, shnum = fields[4], fields[5], *fields[8:12]
    needed = max(phoff + phentsize * phnum, shoff + shentsize * shnum)
    if needed <= len(data):
        for offset, count, entsize, (fmt, i_off, i_size), skip in (
                (phoff, phnum, phentsize, _PHDR[bits], None),
                (shoff, shnum, shentsize, _SHDR[bits], _SHT_NOBITS)):
            entry = struct.Struct(order + fmt)
            for k in range(count if entsize >= entry.size else 0):
                e = entry.unpack_from(data, offset + k * entsize)
                if skip is None or e[1] != skip:
                    needed = max(needed, e[i_off] + e[i_size])
    if needed > size:
        raise Corrupt(f"{library} is {size} bytes but its ELF headers declare {needed}: "
                      "the file is truncated")
