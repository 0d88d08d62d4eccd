"""The FrameData uniform block of a sample: camera, viewport, world and lights, packed by member
name in the layout shaders/frame_data.json gives (shader_specs.Block)."""
import numpy as np

from ..bridge import shader_specs

# The block's layout and the light limit, read from the one description the shaders are built from.
FRAME_DATA = shader_specs.Block("frame_data.json")
MAX_LIGHTS = FRAME_DATA.defines["EL_MAX_LIGHTS"]


def mat4(m):
    """numpy row-major 4x4 -> std140 column-major floats."""
    return np.asarray(m, dtype=np.float32).T.reshape(-1)


def pack(camera, projection, scene, shadows=None, sample=0):
    """The FrameData block's floats (members: shaders/frame_data.json). `shadows`: the frame's
    shadow_plan.ShadowPlan (None: no light casts); `sample`: the sample's number."""
    lights = scene.lights[:MAX_LIGHTS]
    clip = np.asarray(projection, np.float64) @ np.asarray(camera.view, np.float64)
    return FRAME_DATA.pack({
        **_shadow_members(shadows, sample),
        **_environment_members(getattr(scene, "environment", None)),
        "clip_to_world": mat4(np.linalg.inv(clip)),
        "view": mat4(camera.view),
        "projection": mat4(projection),
        "eye": (*camera.eye, 0.0 if camera.orthographic else 1.0),
        "view_dir": (*camera.view_dir, 0.0),
        "viewport": (camera.width, camera.height, 1.0 / camera.width, 1.0 / camera.height),
        "ambient": (*scene.ambient, 1.0),
        "camera": (camera.px_per_unit, len(lights), float(sample), 0.0),
        "frame_pixel": (*getattr(camera, "pixel_origin", (0, 0)), 0.0, 0.0),
        "light_color": [(*light.color, light.kind) for light in lights],
        "light_position": [(*light.position, 0.0) for light in lights],
        "light_direction": [(*light.direction, light.spot_cos) for light in lights],
        "light_spot": [(light.spot_blend, 0.0, 0.0, 0.0) for light in lights],
    })


def _environment_members(env):
    """The world image's members (world_light.Environment; shaders/environment.glsl)."""
    if env is None:
        return {}
    atlas = env.atlas
    rotation = np.eye(4)
    rotation[:3, :3] = env.rotation
    return {
        "env": (float(len(atlas.levels)), env.strength, 0.0, 0.0),
        "env_level": [tuple(float(v) for v in r) for r in atlas.levels],
        "env_irradiance": tuple(float(v) for v in atlas.irradiance),
        "env_rotation": mat4(rotation),
    }


def _shadow_members(plan, sample):
    if plan is None or not plan.layers:
        return {}
    return {
        "light_shadow": [(ls.first, ls.kind, ls.count, ls.radius) if ls else (0.0, 0.0, 0.0, 0.0) for ls in plan.lights],
        "shadow_split": [(tuple(ls.splits) + (0.0,) * 4)[:4] if ls else (0.0,) * 4 for ls in plan.lights],
        "shadow_map": (plan.size, 1.0 if plan.soft else 0.0, float(sample), plan.per_row),
        "shadow_matrix": [mat4(m) for m in plan.matrices],
    }
