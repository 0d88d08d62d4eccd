"""Shadow pass: each layer of a frame's ShadowPlan (shadow_plan.py), the nearest depth its light
sees, into its square tile of one R32F atlas that the shading programs read
(shaders/shadows.glsl, with EL_SHADOWS). Tiles of one 2D texture rather than layers of an array:
a framebuffer on one layer of an array texture cannot be made from Python on 4.x (its attachment
dictionary is misread there). Drawn once per frame from each light's centre: the samples share
it, and a light's size softens the shadow in the lookup (docs/shadows.md)."""
import gpu
import numpy as np

from .. import compat
from . import frame_data, shader_lib
from .shadow_plan import atlas_grid, layer_casters, merged_casters

# What a tile holds where nothing is drawn: farther than anything.
EMPTY = 3.0e38


class ShadowMaps:
    """The atlas and its depth buffer, kept between frames of one layout (the viewport's) and
    made again when a frame needs another."""

    def __init__(self):
        self.shape, self.maps, self.depth, self.fb = None, None, None, None

    def release(self):
        """Lets the atlas go (a frame with no shadow: Shadows turned off in the viewport)."""
        self.shape, self.maps, self.depth, self.fb = None, None, None, None

    def fit(self, size, layers):
        per_row, rows = atlas_grid(layers, size)
        shape = (per_row * size, rows * size)
        if shape != self.shape:
            self.shape = shape
            self.maps = compat.texture(shape, 'R32F')
            # Held here: a framebuffer does not keep its attachments alive, and a freed depth
            # texture leaves it without a depth test (the last caster drawn would win).
            self.depth = compat.texture(shape, 'DEPTH_COMPONENT32F')
            self.fb = gpu.types.GPUFrameBuffer(depth_slot=self.depth, color_slots=(self.maps,))
        return per_row


def _merged_batch(corners):
    if not len(corners):
        return None
    fmt = gpu.types.GPUVertFormat()
    fmt.attr_add(id="pos", comp_type='F32', len=3, fetch_mode='FLOAT')
    vbo = gpu.types.GPUVertBuf(fmt, len(corners))
    vbo.attr_fill("pos", np.ascontiguousarray(corners))
    return gpu.types.GPUBatch(type='TRIS', buf=vbo)


def draw(plan, scene, gpu_meshes, maps):
    """Draws every layer of `plan` (ShadowPlan) with the surfaces of scene.instances that cast
    shadows; returns the atlas, or None when the plan has no layer."""
    if not plan.layers:
        maps.release()
        return None
    per_row = maps.fit(plan.size, plan.layers)
    shader = shader_lib.get("shadow")
    merged, corners = merged_casters(scene)
    merged_batch = _merged_batch(corners)
    merged = set(merged)
    casters = layer_casters(plan, scene.instances)
    size = plan.size
    identity = frame_data.mat4(np.eye(4))
    with maps.fb.bind():
        gpu.state.depth_test_set('LESS_EQUAL')
        gpu.state.depth_mask_set(True)  # before the clear: a depth clear honours the write mask
        maps.fb.clear(color=(EMPTY, EMPTY, EMPTY, EMPTY), depth=1.0)
        gpu.state.blend_set('NONE')
        gpu.state.face_culling_set('NONE')  # both sides cast: thin walls, open meshes
        shader.bind()
        for layer, matrix in enumerate(plan.matrices):
            gpu.state.viewport_set((layer % per_row) * size, (layer // per_row) * size, size, size)
            shader_lib.set_uniform(shader, "light_matrix", frame_data.mat4(matrix))
            if merged_batch is not None and merged.intersection(casters[layer]):
                shader_lib.set_uniform(shader, "model", identity)
                merged_batch.draw(shader)
            for index in casters[layer]:
                if index in merged:
                    continue
                inst = scene.instances[index]
                shader_lib.set_uniform(shader, "model", frame_data.mat4(inst.matrix))
                for batch in gpu_meshes[id(inst.mesh)].surface.values():
                    batch.draw(shader)
        gpu.state.depth_test_set('NONE')
        gpu.state.depth_mask_set(False)
    return maps.maps
