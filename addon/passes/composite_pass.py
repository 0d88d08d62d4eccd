"""Composite pass: lines over the highlight-blended surface, added to the result with a
sample's weight."""
from . import pass_state, shader_lib
from .lighting_inputs import NONE
from .targets import composite_outputs


def draw_composite(targets, background, full_screen, weight, lines=True, ubo=None, lighting=NONE):
    """Adds weight x the composited sample to the result (cleared by the caller), and the
    surface alone to surface_sum when the Surface pass is asked for; without `lines` the ink is
    left out (it goes to the Lines pass alone). With an environment in `lighting`, the background
    is the image along each pixel's ray (the frame block `ubo`'s clip_to_world)."""
    env = lighting.defines(shadows=False) if ubo is not None else {}
    shader = shader_lib.get("composite", {**composite_outputs(targets), **({} if lines else {"EL_NO_INK": 1}), **env})
    with pass_state.drawing("composite", targets.result_fb):
        shader.bind()
        pass_state.bind_inputs(shader, "composite", targets)
        if env:
            shader.uniform_block("frame", ubo)
            lighting.bind(shader, shadows=False)
        shader_lib.set_uniform(shader, "background", background)
        shader_lib.set_uniform(shader, "weight", weight)
        full_screen.draw(shader)
