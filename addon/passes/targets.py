"""The frame's float render targets (shaders/passes.json), the variants of the programs that
write into them, and reading them back."""
import gpu
import numpy as np

from .. import compat
from ..bridge import shader_specs
from . import batches, pass_state, shader_lib
from .lighting_inputs import EnvironmentMaps
from .shadow_pass import ShadowMaps


class Targets:
    """Float render targets of one size (shaders/passes.json: one attribute per target), reused
    across samples and frames. surface_depth holds 1 / view depth (0 = empty); surface_id which
    instance and face covers each pixel (first sample, for the edge and line passes).

    normal / surface_sum: extra attachments for the Normal and Surface render passes, made only
    when a render asks for them (their programs are variants that write them, so a render
    without those passes pays nothing)."""

    def __init__(self, width, height, normal=False, surface_sum=False):
        self.size = (width, height)
        wanted = {"normal": normal, "surface_sum": surface_sum}
        for name in pass_state.target_names():
            setattr(self, name, pass_state.texture(name, self.size) if wanted.get(name, True) else None)
        self.surface_fb = pass_state.framebuffer(self, "surface", surface_outputs(self, ids=False))
        self.surface_ids_fb = pass_state.framebuffer(self, "surface", surface_outputs(self, ids=True))
        self.highlight_fb = pass_state.framebuffer(self, "edge_highlight")
        self.result_fb = pass_state.framebuffer(self, "composite", composite_outputs(self))
        self.line_fb = gpu.types.GPUFrameBuffer(depth_slot=self.line_depth, color_slots=(self.lines,))
        self.lines_empty = False  # the line target holds no stroke (cleared, none drawn since)
        self.shadow_maps = ShadowMaps()  # the lights' shadow maps, of their own size (shadow_pass.py)
        self.environment = EnvironmentMaps()  # the world image's filtered atlas (lighting_inputs.py)


def surface_outputs(targets, ids):
    """Defines of the surface variant that also writes the Normal pass (when `targets` has its
    target) and which instance and face covers each pixel (`ids`)."""
    return {**({"EL_NORMAL_PASS": 1} if targets.normal is not None else {}), **({"EL_SURFACE_IDS": 1} if ids else {})}


def composite_outputs(targets):
    """Defines of the composite variant that also writes the Surface pass when asked for."""
    return {"EL_SURFACE_PASS": 1} if targets.surface_sum is not None else {}


def read(texture, width, height, channels=4):
    """(height, width, channels) float32 of a target, rows bottom-up; waits for the queued draws."""
    buf = gpu.types.Buffer('FLOAT', width * height * channels)
    fb = gpu.types.GPUFrameBuffer(color_slots=(texture,))
    with fb.bind():
        fb.read_color(0, 0, width, height, channels, 0, 'FLOAT', data=buf)
    return np.asarray(buf, dtype=np.float32).reshape(height, width, channels)


def unbind_targets():
    """Rebinds the texture units the passes used to a 1 x 1 texture: the driver frees a deleted
    texture only once nothing has it bound, and Blender leaves units bound until its next
    draw, so a finished render's targets (0.6 GB at 4K) would otherwise outlive it."""
    tiny = compat.texture((1, 1), 'RGBA32F')
    fb = gpu.types.GPUFrameBuffer(color_slots=(compat.texture((1, 1), 'RGBA32F'),))
    shader = shader_lib.get("composite")
    with fb.bind():
        shader.bind()
        for _, name in shader_specs.program("composite")["samplers"]:
            shader_lib.set_sampler(shader, name, tiny)
        shader_lib.set_uniform(shader, "background", (0.0, 0.0, 0.0, 0.0))
        shader_lib.set_uniform(shader, "weight", 0.0)
        batches.fullscreen_batch().draw(shader)
