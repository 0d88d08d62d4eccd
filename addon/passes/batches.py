"""GPU batches of one extracted mesh: surface triangles and edge quads, per material slot."""
import gpu
import numpy as np

from . import shader_lib


def _vertbuf(attrs):
    fmt = gpu.types.GPUVertFormat()
    for name, array in attrs.items():
        fmt.attr_add(id=name, comp_type='F32', len=array.shape[1], fetch_mode='FLOAT')
    count = len(next(iter(attrs.values())))
    vbo = gpu.types.GPUVertBuf(fmt, count)
    for name, array in attrs.items():
        vbo.attr_fill(name, np.ascontiguousarray(array, dtype=np.float32))
    return vbo


def surface_batches(extract):
    out = {}
    for slot, tris in extract.slot_triangles.items():
        corners = (tris[:, None] * 3 + np.arange(3)).reshape(-1)
        vbo = _vertbuf({"pos": extract.corner_pos[corners], "nor": extract.corner_nor[corners]})
        out[slot] = gpu.types.GPUBatch(type='TRIS', buf=vbo)
    return out


# Corner table of an edge quad: (end, side) for its 4 vertices, two triangles. Both triangles
# start at corner 0 and end at corner 3, so whichever vertex provides flat varyings (first or
# last, by backend: 3.4's OpenGL uses the last) it is 0 or 3, and only those two corners shade a
# short edge (edge_highlight.vert.glsl).
_QUAD_CORNERS = np.array([[0, -1], [0, 1], [1, -1], [1, 1]], dtype=np.float32)
_QUAD_TRIS = np.array([0, 1, 3, 0, 2, 3], dtype=np.int32)


def edge_batches(extract):
    out = {}
    for slot, e in extract.edges.items():
        n = len(e)
        if n == 0:
            continue
        rep = lambda a: np.repeat(a, 4, axis=0)  # noqa: E731 - one value per quad corner
        corner = np.zeros((n * 4, 4), dtype=np.float32)
        corner[:, :2] = np.tile(_QUAD_CORNERS, (n, 1))
        corner[:, 2] = rep(e.radius)
        vbo = _vertbuf({"p0": rep(e.p0), "p1": rep(e.p1), "n1": rep(e.n1), "n2": rep(e.n2), "corner": corner})
        idx = (np.arange(n, dtype=np.int32)[:, None] * 4 + _QUAD_TRIS).reshape(-1, 3)
        out[slot] = gpu.types.GPUBatch(type='TRIS', buf=vbo, elem=gpu.types.GPUIndexBuf(type='TRIS', seq=idx))
    return out


class GpuMesh:
    """Everything the passes draw for one extracted mesh, built in the GPU context."""

    def __init__(self, extract):
        self.extract = extract
        self.surface = surface_batches(extract)
        self.rebuild_edges()

    def rebuild_edges(self):
        self.edges = edge_batches(self.extract)
        self.edge_count = sum(len(e) for e in self.extract.edges.values())


def fullscreen_batch():
    shader = shader_lib.get("composite")
    from gpu_extras.batch import batch_for_shader
    return batch_for_shader(shader, 'TRIS', {"pos": [(-1.0, -1.0), (3.0, -1.0), (-1.0, 3.0)]})
