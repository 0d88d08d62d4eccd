"""Which shadow maps a frame draws (docs/shadows.md): per light with Shadow on, its layers (square
tiles of one atlas texture) and each layer's world -> clip matrix, fitted to the scene and the camera.
A sun takes up to four cascades along the camera's depth, a spot within SPOT_SINGLE one
perspective layer, a point, area or wider spot light the six faces of a cube around it. Plain
numpy, no gpu: plain-Python tests import it. shadow_pass.py draws the plan, frame_data.py packs it
for shaders/shadows.glsl."""
import math
from dataclasses import dataclass

import numpy as np

from ..bridge import shader_specs
from ..geometry.closed_surfaces import box_corners

_SPEC = shader_specs.load("frame_data.json")
SHADOW = _SPEC["enums"]["EL_SHADOW"]
LIGHT = _SPEC["enums"]["EL_LIGHT"]
MAX_LAYERS = _SPEC["defines"]["EL_MAX_SHADOW_LAYERS"]
MAX_LIGHTS = _SPEC["defines"]["EL_MAX_LIGHTS"]
MAX_CASCADES = 4
# The atlas's largest side: the texture size every GPU Blender runs on offers.
ATLAS_MAX = 16384
# A spot up to this cone angle (radians) takes one perspective layer; a wider one a cube.
SPOT_SINGLE = math.radians(120.0)
# The cube faces in the order shadows.glsl picks them: +X, -X, +Y, -Y, +Z, -Z (forward, up).
CUBE_FACES = (((1, 0, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1)), ((0, 1, 0), (0, 0, 1)),
              ((0, -1, 0), (0, 0, 1)), ((0, 0, 1), (0, 1, 0)), ((0, 0, -1), (0, 1, 0)))


@dataclass(frozen=True)
class ShadowSettings:
    size: int = 1024      # a layer's width and height in texels
    soft: bool = True     # soft by the light's radius (PCSS); False: hard from the light's centre

    @property
    def max_layers(self):
        """Layers that fit the atlas at this size (16 at 4096 texels), at most MAX_LAYERS."""
        return min(MAX_LAYERS, (ATLAS_MAX // self.size) ** 2)


def atlas_grid(layers, size):
    """(layers per row, rows) of the atlas that holds `layers` tiles of `size`: as square as
    fits within ATLAS_MAX."""
    per_row = min(max(1, math.ceil(math.sqrt(layers))), ATLAS_MAX // size)
    return per_row, max(1, math.ceil(layers / per_row))


def settings_of(scene_settings):
    """The ShadowSettings of a scene's EdgeLight settings, or None with Shadows off."""
    if not scene_settings.use_shadows:
        return None
    return ShadowSettings(int(scene_settings.shadow_size), bool(scene_settings.soft_shadows))


@dataclass(frozen=True)
class LightShadow:
    first: int            # the light's first layer
    kind: int             # EL_SHADOW value
    count: int            # its layers
    radius: float         # the light's radius (a sun: tan of its angular radius)
    splits: tuple = ()    # a sun's cascades: the view depth each covers up to


@dataclass(frozen=True)
class ShadowPlan:
    size: int
    soft: bool
    lights: tuple         # per light of the frame (the first MAX_LIGHTS): LightShadow or None
    matrices: tuple       # per layer: world -> clip, 4 x 4 row-major
    left_out: int = 0     # lights with Shadow on that found no room in the layers

    @property
    def layers(self):
        return len(self.matrices)

    @property
    def per_row(self):
        """Layers per row of the atlas (atlas_grid)."""
        return atlas_grid(self.layers, self.size)[0]


def world_boxes(instances):
    """(n, 2, 3) world bounds of the instances that have bounds, and their indices."""
    picked = [i for i, inst in enumerate(instances) if inst.mesh.box is not None]
    if not picked:
        return np.zeros((0, 2, 3)), picked
    boxes = np.stack([np.asarray(instances[i].mesh.box, np.float64) for i in picked])
    mats = np.stack([np.asarray(instances[i].matrix, np.float64) for i in picked])
    corners = box_corners(boxes)                                   # (n, 8, 3)
    world = np.einsum("nij,nkj->nki", mats[:, :3, :3], corners) + mats[:, None, :3, 3]
    return np.stack([world.min(axis=1), world.max(axis=1)], axis=1), picked


def look(eye, forward, up):
    """World -> view (row-major) of an eye looking along `forward`, `up` roughly up."""
    f = np.asarray(forward, np.float64)
    f = f / np.linalg.norm(f)
    u = np.asarray(up, np.float64)
    if abs(np.dot(f, u)) > 0.99 * np.linalg.norm(u):
        u = np.array([1.0, 0.0, 0.0]) if abs(f[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    s = np.cross(f, u)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ np.asarray(eye, np.float64)
    return m


def perspective(tan_half, near, far):
    """View -> clip of a square frustum of half-width tan_half at distance 1 (OpenGL's)."""
    m = np.zeros((4, 4))
    m[0, 0] = m[1, 1] = 1.0 / tan_half
    m[2, 2] = -(far + near) / (far - near)
    m[2, 3] = -2.0 * far * near / (far - near)
    m[3, 2] = -1.0
    return m


def orthographic(x0, x1, y0, y1, near, far):
    m = np.eye(4)
    m[0, 0], m[1, 1], m[2, 2] = 2.0 / (x1 - x0), 2.0 / (y1 - y0), -2.0 / (far - near)
    m[0, 3], m[1, 3], m[2, 3] = -(x1 + x0) / (x1 - x0), -(y1 + y0) / (y1 - y0), -(far + near) / (far - near)
    return m


def camera_range(camera, scene_box):
    """The view depths [near, far] the camera sees of the scene's bounds, within its clip range;
    None where the scene lies wholly behind it."""
    p = np.asarray(camera.projection, np.float64)
    if camera.orthographic:
        near, far = (p[2, 3] + 1.0) / p[2, 2], (p[2, 3] - 1.0) / p[2, 2]
    else:
        near, far = p[2, 3] / (p[2, 2] - 1.0), p[2, 3] / (p[2, 2] + 1.0)
    depths = (box_corners(scene_box) - np.asarray(camera.eye)) @ np.asarray(camera.view_dir)
    lo, hi = max(near, float(depths.min())), min(far, float(depths.max()))
    if camera.orthographic:
        return (lo, hi) if hi > lo else None
    return (lo, hi) if hi > lo and hi > 0.0 else None


def cascade_splits(near, far, count, blend=0.75):
    """The far depth of each of `count` cascades over [near, far]: `blend` of the logarithmic
    split (each cascade as many texels per unit of depth relative to its distance) and the rest
    of the uniform one (the practical split scheme)."""
    i = np.arange(1, count + 1) / count
    log = near * (far / near) ** i
    return tuple(float(v) for v in blend * log + (1.0 - blend) * (near + (far - near) * i))


def slice_corners(camera, d0, d1):
    """(8, 3) world corners of the camera's frustum between view depths d0 and d1."""
    inv = np.linalg.inv(np.asarray(camera.projection, np.float64) @ np.asarray(camera.view, np.float64))
    out = []
    for x in (-1.0, 1.0):
        for y in (-1.0, 1.0):
            a = inv @ np.array([x, y, -1.0, 1.0])
            b = inv @ np.array([x, y, 1.0, 1.0])
            a, b = a[:3] / a[3], b[:3] / b[3]
            da, db = (a - camera.eye) @ camera.view_dir, (b - camera.eye) @ camera.view_dir
            for d in (d0, d1):  # view depth is linear along the line from near to far
                out.append(a + (b - a) * ((d - da) / (db - da)))
    return np.array(out)


def sun_cascades(light, camera, scene_box, size):
    """(matrices, splits) of a sun's cascades, or None where the camera sees none of the scene."""
    span = camera_range(camera, scene_box)
    if span is None:
        return None
    near, far = span
    if camera.orthographic:
        # Depth does not shrink the view: one cascade over the whole range, which may start
        # behind the eye (an orthographic viewport's clip range is centred on its pivot).
        splits = (far,)
    else:
        near = max(near, far * 1e-4)
        count = int(min(MAX_CASCADES, max(1, math.ceil(math.log2(far / near) / 2.0))))
        splits = cascade_splits(near, far, count)
    view = look((0.0, 0.0, 0.0), light.direction, (0.0, 0.0, 1.0))
    scene_pts = box_corners(scene_box) @ view[:3, :3].T
    z_near, z_far = -scene_pts[:, 2].max(), -scene_pts[:, 2].min()
    pad = 0.01 * max(z_far - z_near, 1e-3)
    matrices, d0 = [], near
    for d1 in splits:
        pts = slice_corners(camera, d0, d1) @ view[:3, :3].T
        centre = 0.5 * (pts.min(axis=0) + pts.max(axis=0))
        radius = float(np.linalg.norm(pts - centre, axis=1).max()) * (1.0 + 2.0 / size)
        # The cascade's window moves by whole texels: a moving camera does not make its edges crawl.
        texel = 2.0 * radius / size
        cx, cy = np.floor(centre[:2] / texel) * texel
        matrices.append(orthographic(cx - radius, cx + radius, cy - radius, cy + radius, z_near - pad, z_far + pad) @ view)
        d0 = d1
    return matrices, splits


def _reach(position, scene_box):
    """The farthest distance from `position` to the scene's bounds (> 0)."""
    return max(float(np.linalg.norm(box_corners(scene_box) - np.asarray(position), axis=1).max()), 1e-3)


def spot_layer(light, scene_box, size):
    far = _reach(light.position, scene_box) * 1.01
    tan_half = math.tan(min(math.acos(max(-1.0, min(1.0, light.spot_cos))) + 2.0 / size, math.radians(85.0)))
    return perspective(tan_half, far * 1e-4, far) @ look(light.position, light.direction, (0.0, 0.0, 1.0))


def cube_layers(light, scene_box, size):
    """The six faces (CUBE_FACES' order), each a little wider than 90 degrees so that a lookup
    near a face's border still has its neighbouring texels."""
    far = _reach(light.position, scene_box) * 1.01
    proj = perspective(1.0 + 2.0 / size, far * 1e-4, far)
    return [proj @ look(light.position, f, u) for f, u in CUBE_FACES]


def plan(scene, camera, settings):
    """The ShadowPlan of a frame: `scene` (scene_sync.SceneData), `camera` (camera.Camera),
    `settings` (ShadowSettings). Lights past MAX_LIGHTS are not drawn at all (frame_data)."""
    lights = scene.lights[:MAX_LIGHTS]
    casters = [inst for inst in scene.instances if getattr(inst, "casts_shadow", True)]
    boxes, _ = world_boxes(scene.instances)
    if not casters or not any(getattr(lt, "shadow", False) for lt in lights) or not len(boxes):
        return ShadowPlan(settings.size, settings.soft, (None,) * len(lights), ())
    scene_box = np.stack([boxes[:, 0].min(axis=0), boxes[:, 1].max(axis=0)])
    out, matrices, left_out = [], [], 0
    for light in lights:
        if not getattr(light, "shadow", False):
            out.append(None)
            continue
        splits = ()
        if light.kind == LIGHT["SUN"]:
            fitted = sun_cascades(light, camera.whole, scene_box, settings.size)
            if fitted is None:
                out.append(None)
                continue
            layers, splits = fitted
            kind = SHADOW["CASCADES"]
        elif light.kind == LIGHT["SPOT"] and math.acos(max(-1.0, min(1.0, light.spot_cos))) * 2.0 <= SPOT_SINGLE:
            layers, kind = [spot_layer(light, scene_box, settings.size)], SHADOW["SINGLE"]
        else:
            layers, kind = cube_layers(light, scene_box, settings.size), SHADOW["CUBE"]
        if len(matrices) + len(layers) > settings.max_layers:
            out.append(None)
            left_out += 1
            continue
        out.append(LightShadow(len(matrices), kind, len(layers), float(light.radius), splits))
        matrices += layers
    return ShadowPlan(settings.size, settings.soft, tuple(out), tuple(matrices), left_out)


def layer_casters(plan_, instances):
    """Per layer, the indices of the instances with Cast Shadow on whose world bounds its
    frustum may see (instances without bounds always)."""
    boxes, picked = world_boxes(instances)
    casts = np.array([getattr(instances[i], "casts_shadow", True) for i in picked], bool)
    unbounded = [i for i, inst in enumerate(instances) if inst.mesh.box is None and getattr(inst, "casts_shadow", True)]
    corners = box_corners(boxes)                                   # (n, 8, 3)
    homo = np.concatenate([corners, np.ones(corners.shape[:-1] + (1,))], axis=-1)
    out = []
    for m in plan_.matrices:
        clip = homo @ np.asarray(m, np.float64).T                  # (n, 8, 4)
        w = clip[..., 3:4]
        # Culled when every corner is outside one plane of the frustum.
        outside = np.concatenate([clip[..., :3] > w, clip[..., :3] < -w], axis=-1)   # (n, 8, 6)
        seen = ~np.any(np.all(outside, axis=1), axis=-1) & casts
        out.append(sorted(unbounded + [picked[k] for k in np.nonzero(seen)[0]]))
    return out


# A caster of at most this many triangles joins the frame's merged caster batch (world space,
# one draw per layer for all of them) instead of a draw of its own: a scene of many small parts
# costs one draw, not one per part. The batch holds at most MERGED_MAX triangles.
MERGE_TRIANGLES = 4096
MERGED_MAX = 1 << 20


def merged_casters(scene):
    """(indices of the casters in the merged batch, (3T, 3) float32 world corners) of the small
    casters, until MERGED_MAX triangles."""
    picked, parts, total = [], [], 0
    for i, inst in enumerate(scene.instances):
        count = len(inst.mesh.corner_pos) // 3
        if not getattr(inst, "casts_shadow", True) or count > MERGE_TRIANGLES or total + count > MERGED_MAX:
            continue
        if any(s.shadow == 'NONE' or (s.shadow == 'CUT' and s.texture is not None and s.texture.shadow_alpha)
               for s in inst.mesh.slot_shading):
            continue  # cast by its own slots' batches: cut by their images' alpha, or not at all (shadow_pass)
        m = np.asarray(inst.matrix, np.float64)
        parts.append((np.asarray(inst.mesh.corner_pos, np.float64) @ m[:3, :3].T + m[:3, 3]).astype(np.float32))
        picked.append(i)
        total += count
    return picked, (np.concatenate(parts) if parts else np.zeros((0, 3), np.float32))
