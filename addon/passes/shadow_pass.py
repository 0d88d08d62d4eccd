"""Shadow pass: each layer of a frame's ShadowPlan (shadow_plan.py), the nearest depth its light
sees, into its square tile of one R32F atlas that the shading programs read
(shaders/shadows.glsl, with EL_SHADOWS). Tiles of one 2D texture rather than layers of an array:
a framebuffer on one layer of an array texture cannot be made from Python on 4.x (its attachment
dictionary is misread there). Drawn once per frame from each light's centre: the samples share
it, and a light's size softens the shadow in the lookup (docs/shadows.md)."""
import gpu
import numpy as np

from .. import compat
from ..extract import textures
from . import frame_data, material_data, shader_lib
from .shadow_plan import atlas_grid, layer_casters, merged_casters
from .texture_variants import SURFACE_MODES, texture_defines, texture_key

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
    fmt.attr_add(id="uv", comp_type='F32', len=2, fetch_mode='FLOAT')  # declared by the program; no cut here
    vbo = gpu.types.GPUVertBuf(fmt, len(corners))
    vbo.attr_fill("pos", np.ascontiguousarray(corners))
    vbo.attr_fill("uv", np.zeros((len(corners), 2), np.float32))
    return gpu.types.GPUBatch(type='TRIS', buf=vbo)


def cut_key(s):
    """The texture key (texture_variants.texture_key) of a slot that casts only where its image's
    alpha keeps it (its material's shadow mode 'CUT': compat.shadow_mode), cut by its shadow's
    own alpha mode (materials.BaseTexture.shadow_alpha), or None."""
    t = s.texture
    if s.shadow != 'CUT' or t is None or not t.shadow_alpha or t.source is None:
        return None
    return texture_key(s, SURFACE_MODES["PHONG"], alpha=False) + (int(t.shadow_alpha),)


def draw(plan, scene, gpu_meshes, maps):
    """Draws every layer of `plan` (ShadowPlan) with the surfaces of scene.instances that cast
    shadows; returns the atlas, or None when the plan has no layer."""
    if not plan.layers:
        maps.release()
        return None
    per_row = maps.fit(plan.size, plan.layers)
    shader = shader_lib.get("shadow")
    cut_shaders = {}
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
                gm = gpu_meshes[id(inst.mesh)]
                cut = []
                for slot, batch in gm.surface.items():
                    if gm.extract.slot_shading[slot].shadow == 'NONE':
                        continue  # its material casts none
                    key = cut_key(gm.extract.slot_shading[slot])
                    if key is None:
                        batch.draw(shader)
                    else:
                        cut.append((key, slot, batch))
                for key, slot, batch in cut:  # in the cutting variant, then back to the plain one
                    if key not in cut_shaders:
                        cut_shaders[key] = shader_lib.get("shadow", {**texture_defines(key), "EL_SHADOW_CUT": 1})
                    cutter = cut_shaders[key]
                    cutter.bind()
                    shader_lib.set_uniform(cutter, "light_matrix", frame_data.mat4(matrix))
                    shader_lib.set_uniform(cutter, "model", frame_data.mat4(inst.matrix))
                    s = gm.extract.slot_shading[slot]
                    shader_lib.set_block(cutter, "material", material_data.buffer(s))  # its threshold
                    shader_lib.set_sampler(cutter, "base_tex", textures.gpu_texture(s.texture.source.image))
                    batch.draw(cutter)
                if cut:
                    shader.bind()
        gpu.state.depth_test_set('NONE')
        gpu.state.depth_mask_set(False)
    return maps.maps
