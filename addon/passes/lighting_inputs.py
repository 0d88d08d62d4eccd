"""What the shading programs look up besides the frame block: the lights' shadow maps
(shadow_pass.py, shaders/shadows.glsl) and the world's environment atlas (shaders/environment.glsl),
with the defines of the program variants that read them: a frame without either draws the
programs that have no such code."""
from dataclasses import dataclass

import numpy as np

from .. import compat
from . import shader_lib


@dataclass(frozen=True)
class LightingInputs:
    shadow_maps: object = None  # the shadow atlas (GPUTexture), None: no light casts
    env_map: object = None      # the environment atlas (GPUTexture), None: a uniform world

    def defines(self, shadows=True):
        """The variant's defines; `shadows` False for a program that reads no shadow (the
        composite's background)."""
        out = {"EL_SHADOWS": 1} if shadows and self.shadow_maps is not None else {}
        if self.env_map is not None:
            out["EL_ENVIRONMENT"] = 1
        return out

    def bind(self, shader, shadows=True):
        if shadows and self.shadow_maps is not None:
            shader_lib.set_sampler(shader, "shadow_maps", self.shadow_maps)
        if self.env_map is not None:
            shader_lib.set_sampler(shader, "env_map", self.env_map)


NONE = LightingInputs()


class EnvironmentMaps:
    """The GPU texture of the world's environment atlas (world_light.Environment), kept while
    the world keeps its image (the viewport redraws with it) and let go when it has none."""

    def __init__(self):
        self.key, self.texture = None, None

    def texture_of(self, environment):
        if environment is None:
            self.key, self.texture = None, None
            return None
        if environment.key != self.key:
            px = np.ascontiguousarray(environment.atlas.pixels, np.float32)
            h, w = px.shape[:2]
            import gpu
            buf = gpu.types.Buffer('FLOAT', px.size, px.reshape(-1))
            self.key, self.texture = environment.key, compat.texture((w, h), 'RGBA32F', buf)
        return self.texture
