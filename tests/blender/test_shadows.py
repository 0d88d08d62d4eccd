"""Cast shadows (docs/shadows.md, shaders/shadows.glsl): where each kind of light puts the shadow
of a box on a floor, held pixel by pixel to Blender's own ray casts; soft shadows against the
fraction of the light a ray cast sees; the settings that turn a shadow off; a toon ramp's cel
shadow; the report when the lights outnumber the layers."""
import math
import unittest

import bpy
import numpy as np
from mathutils import Vector

import helpers
from test_toon import set_ramp

FLOOR, SIZE, PX = 8.0, 200, 200 / 8.0   # the floor's width, the image's, pixels per unit
LIGHT_AT = (1.0, 0.5, 5.0)


def floor_scene(kind, radius=0.0, samples=1, spot_deg=90.0, at=LIGHT_AT, dense=False, **settings):
    """An 8 x 8 floor at z = 0 under a box of side 1 floating at z 1..2, seen straight down by an
    orthographic camera that frames the floor; one light of `kind` (a local one at `at`, facing
    down), hard unless `radius`; no world light, so a shadow is black."""
    scene = helpers.empty_scene(SIZE, SIZE, highlights=False, samples=samples, **settings)
    helpers.set_world_color(scene, (0.0, 0.0, 0.0))
    # The box first: the floor, drawn into the maps after it, must not cover it (the maps' depth test).
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 1.5))
    box = bpy.context.object
    bpy.ops.mesh.primitive_plane_add(size=FLOOR)
    if dense:  # 6144 triangles, past shadow_plan.MERGE_TRIANGLES: drawn on its own, not merged
        mod = box.modifiers.new("Dense", 'SUBSURF')
        mod.subdivision_type, mod.levels, mod.render_levels = 'SIMPLE', 4, 4
    cam = helpers.add_camera((0.0, 0.0, 20.0), (0.0, 0.0, 0.0))
    cam.data.type, cam.data.ortho_scale = 'ORTHO', FLOOR
    data = bpy.data.lights.new("Light", kind)
    ob = bpy.data.objects.new("Light", data)
    scene.collection.objects.link(ob)
    if kind == 'SUN':
        data.energy, data.angle = 3.0, 2.0 * math.atan(radius)
        helpers.look_at(ob, (1.0, 0.5, 1.0), (0.0, 0.0, 0.0))
    else:
        data.energy = 2000.0
        if kind == 'AREA':
            data.shape, data.size = 'DISK', 2.0 * radius
        else:
            data.shadow_soft_size = radius
        if kind == 'SPOT':
            data.spot_size, data.spot_blend = math.radians(spot_deg), 0.0
        helpers.look_at(ob, at, (at[0], at[1], 0.0))
    return scene, ob, box


def floor_points():
    """The floor's world point under each pixel centre, (SIZE, SIZE, 3), rows bottom-up."""
    c = (np.arange(SIZE) + 0.5) / PX - FLOOR / 2.0
    x, y = np.meshgrid(c, c)
    return np.stack([x, y, np.zeros_like(x)], axis=-1)


def towards_light(light, p):
    """Unit direction and distance from floor point p to the light's centre."""
    if light.data.type == 'SUN':
        d = light.matrix_world.to_3x3() @ Vector((0.0, 0.0, 1.0))
        return d.normalized(), 1e4
    d = light.matrix_world.translation - Vector(p)
    return d.normalized(), d.length


def occluded(scene, light, p, target=None):
    """Blender's ray cast from floor point p to the light's centre (or to `target`)."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    if target is None:
        d, dist = towards_light(light, p)
    else:
        v = Vector(target) - Vector(p)
        d, dist = v.normalized(), v.length
    hit = scene.ray_cast(depsgraph, Vector(p) + Vector((0.0, 0.0, 1e-4)), d, distance=dist)[0]
    return hit


def box_pixels(box):
    """Pixels that see the box (its top face, from straight above), where the floor is hidden."""
    pts = floor_points()
    lo, hi = np.array(box.location[:2]) - 0.5, np.array(box.location[:2]) + 0.5
    return np.all((pts[..., :2] > lo - 2.0 / PX) & (pts[..., :2] < hi + 2.0 / PX), axis=-1)


def reference_shadow(scene, light, box, step=1):
    """Per pixel (every `step`-th), whether Blender's ray cast finds the box between the floor
    and the light: None where the box hides the floor."""
    pts = floor_points()
    hidden = box_pixels(box)
    out = np.full((SIZE, SIZE), -1, np.int8)
    for j in range(0, SIZE, step):
        for i in range(0, SIZE, step):
            if not hidden[j, i]:
                out[j, i] = 1 if occluded(scene, light, pts[j, i]) else 0
    return out


def lit_fraction(scene):
    """The floor's luminance, and its fraction of the same render with the scene's Shadows off:
    1 where the light is unobstructed, whatever its falloff."""
    lum = helpers.render()["pixels"][..., :3].mean(axis=-1)
    scene.edgelight.use_shadows = False
    free = helpers.render()["pixels"][..., :3].mean(axis=-1)
    scene.edgelight.use_shadows = True
    # Where the light does not reach at all (outside a spot's cone) there is nothing to shadow: 1.
    return lum, np.where(free > 1e-6 * free.max(), lum / np.maximum(free, 1e-30), 1.0)


def near_boundary(mask, width=2):
    """Pixels within `width` of a change of `mask` (0/1), where a texel's blend is allowed."""
    m = mask.astype(bool)
    near = np.zeros_like(m)
    for dy in range(-width, width + 1):
        for dx in range(-width, width + 1):
            near |= np.roll(np.roll(m, dy, 0), dx, 1) != m
    return near


class WhereTheShadowFalls(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def check_against_rays(self, kind, **kw):
        scene, light, box = floor_scene(kind, **kw)
        lum, lit = lit_fraction(scene)
        ref = reference_shadow(scene, light, box)
        shadow = ref == 1
        self.assertGreater(shadow.sum(), 0.01 * SIZE * SIZE, "the box casts a shadow on the floor")
        judged = (ref >= 0) & ~near_boundary(shadow)
        agree = ((lit < 0.5) == shadow)[judged].mean()
        print(f"{kind} {kw}: {shadow.sum()} shadowed pixels by ray casts, agreement {agree:.5f}, "
              f"in shadow at most {lum[judged & shadow].max():.2e}, lit at least {lit[judged & ~shadow].min():.4f} of unshadowed")
        self.assertGreater(agree, 0.999)
        self.assertLess(lum[judged & shadow].max(), 1e-4, "a hard shadow with no world light is black")
        np.testing.assert_allclose(lit[judged & ~shadow], 1.0, atol=1e-4, err_msg="lit where nothing is in the way")

    def test_a_sun_shadow(self):
        self.check_against_rays('SUN')

    def test_a_point_light_shadow(self):
        self.check_against_rays('POINT')
        # Low and to the side: the shadow falls in the cube's +Y face, the floor near the light in -Z.
        self.check_against_rays('POINT', at=(0.3, -2.5, 2.6))
        # A caster too large for the merged batch: its own draws, with its own matrix.
        self.check_against_rays('POINT', at=(0.3, -2.5, 2.6), dense=True)

    def test_a_spot_light_shadow_in_one_map_and_in_a_cube(self):
        self.check_against_rays('SPOT', spot_deg=90.0)     # one perspective layer
        self.check_against_rays('SPOT', spot_deg=160.0)    # past shadow_plan.SPOT_SINGLE: a cube

    def test_an_area_light_shadow(self):
        self.check_against_rays('AREA')

    def test_the_settings_that_turn_a_shadow_off(self):
        """The light's Shadow, the object's Ray Visibility > Shadow and the scene's Shadows each
        leave the floor lit where the shadow fell."""
        scene, light, box = floor_scene('POINT')
        lum = helpers.render()["pixels"][..., :3].mean(axis=-1)
        self.assertLess(lum[~box_pixels(box)].min(), 1e-4, "with all of them on, the shadow is there")
        for off in ("light", "object", "scene"):
            scene, light, box = floor_scene('POINT')
            if off == "light":
                light.data.use_shadow = False
            elif off == "object":
                box.visible_shadow = False
            else:
                scene.edgelight.use_shadows = False
            rec = helpers.render()
            lum = rec["pixels"][..., :3].mean(axis=-1)
            floor = ~box_pixels(box)
            print(f"shadow off by the {off}: darkest floor pixel {lum[floor].min():.4f}")
            self.assertGreater(lum[floor].min(), 0.01, off)


class SoftShadows(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def test_a_point_light_of_radius_half_a_unit(self):
        """Across the shadow's edge, the lit fraction follows the share of the light's disk that
        ray casts from the floor reach (64 points on the disk facing each floor point)."""
        radius = 0.5
        scene, light, box = floor_scene('POINT', radius=radius, samples=16)
        _, lit = lit_fraction(scene)
        pts = floor_points()
        # The row through the box's centre, on the side away from the light (-x): shadow, then
        # penumbra, then light.
        row = SIZE // 2 + int(round(0.0 * PX))
        cols = [i for i in range(SIZE) if pts[row, i, 0] < -0.6]
        centre = np.array(LIGHT_AT)
        golden = math.pi * (3.0 - math.sqrt(5.0))
        ref, ours = [], []
        for i in cols:
            p = pts[row, i]
            to = centre - p
            w = to / np.linalg.norm(to)
            u = np.cross(w, (0.0, 0.0, 1.0) if abs(w[2]) < 0.9 else (1.0, 0.0, 0.0))
            u /= np.linalg.norm(u)
            v = np.cross(w, u)
            seen = 0
            for k in range(64):
                r, a = radius * math.sqrt((k + 0.5) / 64), k * golden
                seen += not occluded(scene, light, p, centre + r * (math.cos(a) * u + math.sin(a) * v))
            ref.append(seen / 64.0)
            ours.append(lit[row, i])
        ours, ref = np.array(ours), np.array(ref)
        penumbra = (ref > 0.05) & (ref < 0.95)
        print(f"penumbra: {penumbra.sum()} px by ray casts, {((ours > 0.05) & (ours < 0.95)).sum()} px drawn; "
              f"mean |difference| {np.abs(ours - ref).mean():.3f}, max {np.abs(ours - ref).max():.3f}")
        self.assertGreater(penumbra.sum(), 4, "the light's size makes a penumbra")
        self.assertGreater(((ours > 0.05) & (ours < 0.95)).sum(), 0.5 * penumbra.sum())
        self.assertLess(np.abs(ours - ref).mean(), 0.06)
        self.assertLess(np.abs(ours - ref).max(), 0.35)

    def test_hard_shadows_when_soft_is_off(self):
        scene, light, box = floor_scene('POINT', radius=0.5, samples=4, soft_shadows=False)
        _, lit = lit_fraction(scene)
        ref = reference_shadow(scene, light, box, step=1)  # from the light's centre
        shadow = ref == 1
        judged = (ref >= 0) & ~near_boundary(shadow)
        grey = judged & (lit > 1e-3) & (lit < 0.999)
        print(f"soft off: {grey.sum()} grey pixels of {judged.sum()} away from the edge")
        self.assertEqual(grey.sum(), 0, "no penumbra away from the edge")


class ToonShadow(unittest.TestCase):
    def test_a_cel_shadow_on_the_floor(self):
        """A two-band ramp on the floor: where the box's shadow falls the floor takes the ramp's
        dark colour exactly, elsewhere its light one."""
        helpers.needs_gpu()
        dark, light_c = (0.1, 0.05, 0.2), (0.9, 0.6, 0.3)
        scene, light, box = floor_scene('SUN')
        floor = bpy.data.objects["Plane"]
        mat = bpy.data.materials.new("Cel")
        mat.use_nodes = True
        floor.data.materials.append(mat)
        set_ramp(mat, [(0.0, dark), (0.5, light_c)])
        rec = helpers.render()
        px = rec["pixels"][..., :3]
        ref = reference_shadow(scene, light, box)
        shadow = ref == 1
        judged = (ref >= 0) & ~near_boundary(shadow, 3)
        for mask, want, name in ((judged & shadow, dark, "shadow"), (judged & (ref == 0), light_c, "lit")):
            got = px[mask]
            print(f"cel {name}: {len(got)} pixels, colours {np.unique(got.round(4), axis=0).tolist()[:4]}")
            self.assertGreater(len(got), 50)
            np.testing.assert_allclose(got, np.broadcast_to(want, got.shape), atol=1e-5, err_msg=name)


class TooManyShadows(unittest.TestCase):
    def test_lights_past_the_layers_are_reported(self):
        """Six point lights need 36 cube faces, past the 32 layers: the sixth casts none and the
        render says so."""
        helpers.needs_gpu()
        scene, light, box = floor_scene('POINT')
        for k in range(5):
            ob = bpy.data.objects.new(f"More{k}", bpy.data.lights.new(f"More{k}", 'POINT'))
            ob.location = (k - 2.0, -2.0, 4.0)
            scene.collection.objects.link(ob)
        rec = helpers.render()
        said = " ".join(message for _, message in rec.get("messages", []))
        print("reports:", said)
        self.assertIn("1 light cast no shadow", said)


if __name__ == "__main__":
    unittest.main()
