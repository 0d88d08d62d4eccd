"""Mesh extractions kept from one final render to the next: an animation whose meshes do not
change, or a frame rendered again after a camera or light change, does not classify and choose
the edges of every mesh afresh (on a 400k-triangle grid that was 2 of a render's 4 seconds).

An extraction is reused for the same content, whichever object has it (copies of one part
under other names are one mesh): a fingerprint of every array the extraction reads from the
evaluated mesh (positions, topology, corner normals, edge marks, bevel weights, material
indices). The materials' shading and the
line settings are applied afresh on reuse, as the viewport does on a material change. Within a
render job (every frame of an animation) only what a scene's previous frame used is kept past
its frame change; when the job ends, what each scene's last frame used is kept if the scene's
Persistent Data is on (engine.py), else nothing; a file load and the add-on's unregistering drop
everything. No bpy: plain-Python tests import it.
"""
import hashlib
import threading

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
    """Kept values by key: (library, content fingerprint), each with the scene
    whose render kept it. Per scene, what its current frame used; the previous frame's unused
    ones are dropped when its frame changes, and a job's end keeps only what the last frame of
    each scene it rendered used (or nothing). Renders run on the render thread, file loads and
    unregistering on the main thread: one lock."""

    def __init__(self):
        self._lock = threading.Lock()
        self._reset()

    def begin(self, scene, frame):
        """A render of `scene` (its name) at `frame` starts (one per view layer)."""
        with self._lock:
            if self._frame.get(scene) != frame:
                if scene in self._frame:
                    self._drop(scene)
                self._frame[scene] = frame
                self._used[scene] = set()
            self._scene = scene

    def get(self, key):
        """The value kept for `key`, or None (also when no render has begun since a clear)."""
        with self._lock:
            entry = self._entries.get(key)
            if entry is None or self._scene not in self._used:
                return None
            self._entries[key] = (entry[0], self._scene)
            self._used[self._scene].add(key)
            return entry[0]

    def put(self, key, value):
        with self._lock:
            if self._scene in self._used:
                self._entries[key] = (value, self._scene)
                self._used[self._scene].add(key)

    def end_job(self, keep):
        """A render job ended: with `keep`, what the last frame of each scene it rendered used
        stays; the rest goes."""
        with self._lock:
            if not keep:
                self._reset()
                return
            for scene in list(self._frame):
                self._drop(scene)
            rendered = set(self._frame)
            self._entries = {k: v for k, v in self._entries.items() if v[1] in rendered}
            # The next job starts afresh: its first frame drops nothing when it begins.
            self._frame, self._used, self._scene = {}, {}, None

    def clear(self):
        with self._lock:
            self._reset()

    def _drop(self, scene):
        used = self._used.get(scene, set())
        self._entries = {k: v for k, v in self._entries.items() if v[1] != scene or k in used}

    def _reset(self):
        self._entries = {}
        self._frame = {}
        self._used = {}
        self._scene = None

    def __len__(self):
        return len(self._entries)


EXTRACTS = ExtractCache()
