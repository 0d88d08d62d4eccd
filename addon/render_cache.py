"""Mesh extractions kept from one final render to the next: an animation whose meshes do not
change, or a frame rendered again after a camera or light change, does not classify and choose
the edges of every mesh afresh (on a 400k-triangle grid that was 2 of a render's 4 seconds).

An extraction is reused only for the same object (its label and materials) and the same
content: a fingerprint of every array the extraction reads from the evaluated mesh (positions,
topology, corner normals, edge marks, bevel weights, material indices). Shading and line
settings are applied afresh on reuse, as the viewport does on a material change. Within a render
job (every frame of an animation) what the previous frame used is kept past a frame change, one
extraction per object; when the job ends everything is dropped unless the scene's Persistent
Data is on (engine.py); a file load and the add-on's unregistering drop everything. No bpy:
plain-Python tests import it.
"""
import hashlib

import numpy as np


def fingerprint(arrays):
    """A digest of the arrays' dtypes, shapes and bytes."""
    h = hashlib.blake2b(digest_size=16)
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(f"{a.dtype.str}{a.shape}".encode())
        h.update(memoryview(a).cast("B"))
    return h.digest()


class ExtractCache:
    """key -> (fingerprint, extraction, the frame that last used it)."""

    def __init__(self):
        self._entries = {}
        self._frame = None

    def begin(self, frame):
        """A render of `frame` (any hashable: scene and frame number) starts. On a new frame,
        what the previous frame did not use is dropped."""
        if frame != self._frame:
            self._entries = {k: v for k, v in self._entries.items() if v[2] == self._frame}
            self._frame = frame

    def get(self, key, digest):
        """The extraction kept for `key` if its content had this fingerprint, else None."""
        entry = self._entries.get(key)
        if entry is None or entry[0] != digest:
            return None
        self._entries[key] = (digest, entry[1], self._frame)
        return entry[1]

    def put(self, key, digest, extract):
        """Keeps `extract` for `key` (replacing what was kept for it)."""
        self._entries[key] = (digest, extract, self._frame)

    def clear(self):
        self._entries = {}
        self._frame = None

    def __len__(self):
        return len(self._entries)


EXTRACTS = ExtractCache()
