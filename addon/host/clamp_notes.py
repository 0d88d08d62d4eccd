"""What the material panel's radius clamp note reads (ui.radius_clamp_note): the counts each
geometry's edge choice made (MeshExtract.clamps, geometry/radius_clamp_notes.py), for the
geometries the Rendered viewport holds, else for those of the last final render. Its owners
write it, the data going one way: the engine after a render's extraction (rendered), the
viewport when it extracts an object or chooses its edges again (hold). The panel only reads.
Nothing is written to the materials. No bpy."""
import threading
import weakref

from ..geometry.radius_clamp_notes import total


class ClampNotes:
    """The counts, per geometry (its edge data: copies of one extraction share it). A held
    geometry counts while something else keeps it alive (weakly referenced); a render's are kept
    until the next render. Renders run on the render thread, panels draw on the main one: one
    lock."""

    def __init__(self):
        self._lock = threading.Lock()
        self._held = {}        # id(edge data) -> (weakref to it, its counts)
        self._rendered = {}    # view layer -> {id(edge data): counts} of its last final render

    def hold(self, extract):
        """The viewport draws `extract` (scene_sync.MeshExtract): its counts replace what an
        earlier choice of the same geometry counted."""
        geometry = extract.edge_data
        if geometry is None:
            return
        with self._lock:
            self._held = {k: v for k, v in self._held.items() if v[0]() is not None}
            self._held[id(geometry)] = (weakref.ref(geometry), tuple(extract.clamps))

    def rendered(self, layer, extracts):
        """A final render of view layer `layer` drew `extracts` (each geometry once, however many
        instances): they replace what its last render counted."""
        counts = {id(ex.edge_data): tuple(ex.clamps) for ex in extracts if ex.edge_data is not None}
        with self._lock:
            self._rendered[layer] = counts

    def radius_clamps(self, material):
        """(edges clamped, edges rounded, smallest clamped radius) of `material` (a bpy
        Material) at its current Radius, over the held geometries, else over the last render's;
        None when nothing counted it at that radius."""
        name, radius = material.name_full, float(material.edgelight.radius)
        with self._lock:
            held = [c for ref, counts in self._held.values() if ref() is not None for c in counts]
            # Each geometry once, however many view layers drew it.
            rendered = [c for counts in {k: v for layer in self._rendered.values() for k, v in layer.items()}.values()
                        for c in counts]
        mine = [c for c in held if c.material == name]
        return total(mine or rendered, name, radius)

    def clear(self):
        with self._lock:
            self._held, self._rendered = {}, {}


NOTES = ClampNotes()
