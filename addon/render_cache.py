"""Mesh extractions kept from one final render to the next: an animation whose meshes do not
change, or a frame rendered again after a camera or light change, does not classify and choose
the edges of every mesh afresh (on a 400k-triangle grid that was 2 of a render's 4 seconds).

An extraction is reused only for the same object (its label) and the same content: a
fingerprint of every array the extraction reads from the evaluated mesh (positions, topology,
corner normals, edge marks, bevel weights, material indices). The materials' shading and the
line settings are applied afresh on reuse, as the viewport does on a material change. Within a
render job (every frame of an animation) only what a scene's previous frame used is kept past
its frame change; when the job ends, what each scene's last frame used is kept if the scene's
Persistent Data is on (engine.py), else nothing; a file load and the add-on's unregistering drop
everything. No bpy: plain-Python tests import it.
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
    """Extractions by key: (object label, library, content fingerprint), each with the scene
    whose render kept it. Per scene, what its current frame used; the previous frame's unused
    ones are dropped when its frame changes, and the job's end keeps only what the last frame of
    each scene used (or nothing)."""

    def __init__(self):
        self.clear()

    def begin(self, scene, frame):
        """A render of `scene` (its name) at `frame` starts (one per view layer)."""
        if self._frame.get(scene) != frame:
            if scene in self._frame:
                self._drop(scene)
            self._frame[scene] = frame
            self._used[scene] = set()
        self._scene = scene

    def get(self, key):
        """The extraction kept for `key`, or None."""
        entry = self._entries.get(key)
        if entry is None:
            return None
        self._entries[key] = (entry[0], self._scene)
        self._used[self._scene].add(key)
        return entry[0]

    def put(self, key, extract):
        self._entries[key] = (extract, self._scene)
        self._used[self._scene].add(key)

    def end_job(self, keep):
        """A render job ended: with `keep`, what the last frame of each scene used stays."""
        if not keep:
            self.clear()
            return
        for scene in list(self._frame):
            self._drop(scene)
        # The next job starts afresh: its first frame drops nothing when it begins.
        self._frame, self._used = {}, {}

    def _drop(self, scene):
        used = self._used.get(scene, set())
        self._entries = {k: v for k, v in self._entries.items() if v[1] != scene or k in used}

    def clear(self):
        self._entries = {}
        self._frame = {}
        self._used = {}
        self._scene = None

    def __len__(self):
        return len(self._entries)


EXTRACTS = ExtractCache()
