"""Which shadow maps a frame draws (addon/passes/shadow_plan.py), against closed forms: a cube
face picked as shaders/shadows.glsl picks it sees the point inside its square, at a clip w equal
to the distance along its axis; a sun's cascades cover the camera's depth range in order and
each sees its slice of the view; a spot's layer holds its cone; what is culled lies outside;
the layer budget."""
import math
import unittest
from dataclasses import dataclass, field

import numpy as np

from addon_modules import addon_module

plan_mod = addon_module("passes.shadow_plan")
camera_mod = addon_module("passes.camera")


@dataclass
class Mesh:
    box: np.ndarray
    corner_pos: np.ndarray = field(default_factory=lambda: np.zeros((36, 3), np.float32))
    slot_shading: tuple = ()  # materials.Shading per slot: only its shadow mode and cut are read here


@dataclass
class Texture:
    shadow_alpha: int  # EL_ALPHA of its shadow: 0, the whole face casts


@dataclass
class Shading:
    shadow: str = 'OPAQUE'  # compat.shadow_mode
    texture: object = None


@dataclass
class Instance:
    mesh: Mesh
    matrix: np.ndarray
    casts_shadow: bool = True


@dataclass
class Light:
    kind: int
    position: tuple = (0.0, 0.0, 5.0)
    direction: tuple = (0.0, 0.0, -1.0)
    spot_cos: float = -1.0
    shadow: bool = True
    radius: float = 0.0


@dataclass
class Scene:
    instances: list
    lights: list
    reports: list = field(default_factory=list)


def box_at(centre, half=0.5):
    m = np.eye(4)
    m[:3, 3] = centre
    return Instance(Mesh(np.array([[-half] * 3, [half] * 3])), m)


def camera(eye=(8.0, -8.0, 6.0), target=(0.0, 0.0, 0.0), near=0.1, far=100.0, w=320, h=240):
    view = plan_mod.look(eye, np.subtract(target, eye), (0.0, 0.0, 1.0))
    proj = plan_mod.perspective(math.tan(math.radians(20.0)), near, far)
    proj[0, 0] *= h / w
    return camera_mod.from_view(view, proj, False, w, h)


def glsl_face(d):
    """shadows.glsl's el_shadow_layer for a cube: the face of the axis d lies furthest along."""
    a = np.abs(d)
    if a[0] >= a[1] and a[0] >= a[2]:
        return 0 if d[0] >= 0 else 1
    if a[1] >= a[2]:
        return 2 if d[1] >= 0 else 3
    return 4 if d[2] >= 0 else 5


LIGHT = plan_mod.LIGHT
SHADOW = plan_mod.SHADOW
SETTINGS = plan_mod.ShadowSettings(1024, True)


class CubeFaces(unittest.TestCase):
    def test_the_picked_face_sees_the_point_at_its_distance(self):
        scene = Scene([box_at((0.0, 0.0, 0.0)), box_at((3.0, 2.0, 1.0))], [Light(LIGHT["POINT"], (0.5, -0.3, 2.0))])
        p = plan_mod.plan(scene, camera(), SETTINGS)
        ls = p.lights[0]
        self.assertEqual((ls.kind, ls.count), (SHADOW["CUBE"], 6))
        rng = np.random.default_rng(1)
        origin = np.array(scene.lights[0].position)
        for d in rng.normal(size=(500, 3)) * rng.uniform(0.05, 4.0, size=(500, 1)):
            face = glsl_face(d)
            clip = np.asarray(p.matrices[ls.first + face]) @ np.r_[origin + d, 1.0]
            self.assertTrue(np.all(np.abs(clip[:2] / clip[3]) <= 1.0 + 1e-9), (d, face))
            self.assertAlmostEqual(clip[3], np.abs(d).max(), places=9)  # the distance along the face's axis


class SunCascades(unittest.TestCase):
    def test_cascades_cover_the_view_in_order_and_see_their_slices(self):
        floor = Instance(Mesh(np.array([[-20.0, -20.0, -0.01], [20.0, 20.0, 0.0]])), np.eye(4))
        scene = Scene([floor, box_at((0.0, 0.0, 1.0))], [Light(LIGHT["SUN"], direction=(-0.3, 0.2, -1.0))])
        cam = camera()
        p = plan_mod.plan(scene, cam, SETTINGS)
        ls = p.lights[0]
        self.assertEqual(ls.kind, SHADOW["CASCADES"])
        self.assertEqual(ls.count, 4)
        near, far = plan_mod.camera_range(cam, np.array([[-20.0, -20.0, -0.01], [20.0, 20.0, 1.5]]))
        self.assertTrue(np.all(np.diff(ls.splits) > 0))
        self.assertAlmostEqual(ls.splits[-1], far, places=6)
        d0 = max(near, far * 1e-4)
        for c, d1 in enumerate(ls.splits):
            m = np.asarray(p.matrices[ls.first + c])
            self.assertEqual(tuple(m[3]), (0.0, 0.0, 0.0, 1.0))  # orthographic: shadows.glsl's test
            for corner in plan_mod.slice_corners(cam, d0, d1):
                clip = m @ np.r_[corner, 1.0]
                self.assertTrue(np.all(np.abs(clip[:2]) <= 1.0), (c, corner))
            d0 = d1
        # The whole scene lies within every cascade's depth range: what casts from outside the
        # view still casts.
        for c in range(ls.count):
            m = np.asarray(p.matrices[ls.first + c])
            corners = plan_mod.box_corners(np.array([[-20.0, -20.0, -0.01], [20.0, 20.0, 1.5]]))
            z = (m @ np.c_[corners, np.ones(8)].T)[2]
            self.assertTrue(np.all(np.abs(z) <= 1.0))

    def test_an_orthographic_view_takes_one_cascade_over_its_whole_depth(self):
        """An orthographic viewport's clip range is centred on its pivot: what it sees may lie
        behind the eye, and one cascade holds all of it."""
        floor = Instance(Mesh(np.array([[-20.0, -20.0, -0.01], [20.0, 20.0, 0.0]])), np.eye(4))
        view = plan_mod.look((0.0, -3.0, 1.0), (0.0, 1.0, -0.2), (0.0, 0.0, 1.0))
        proj = plan_mod.orthographic(-4.0, 4.0, -3.0, 3.0, -50.0, 50.0)
        cam = camera_mod.from_view(view, proj, True, 320, 240)
        p = plan_mod.plan(Scene([floor], [Light(LIGHT["SUN"], direction=(-0.3, 0.2, -1.0))]), cam, SETTINGS)
        ls = p.lights[0]
        self.assertEqual(ls.count, 1)
        near, far = plan_mod.camera_range(cam, floor.mesh.box)
        self.assertLess(near, 0.0)
        m = np.asarray(p.matrices[ls.first])
        for corner in plan_mod.slice_corners(cam, near, far):
            clip = m @ np.r_[corner, 1.0]
            self.assertTrue(np.all(np.abs(clip[:2]) <= 1.0), corner)

    def test_the_practical_split(self):
        s = plan_mod.cascade_splits(1.0, 16.0, 2, blend=1.0)
        np.testing.assert_allclose(s, (4.0, 16.0))           # logarithmic: equal ratios
        s = plan_mod.cascade_splits(1.0, 16.0, 3, blend=0.0)
        np.testing.assert_allclose(s, (6.0, 11.0, 16.0))     # uniform


class SpotAndCulling(unittest.TestCase):
    def test_a_spot_cone_fits_its_one_layer(self):
        half = math.radians(40.0)
        scene = Scene([box_at((0.0, 0.0, 0.0))], [Light(LIGHT["SPOT"], (0.0, 0.0, 5.0), (0.0, 0.0, -1.0), math.cos(half))])
        p = plan_mod.plan(scene, camera(), SETTINGS)
        ls = p.lights[0]
        self.assertEqual((ls.kind, ls.count), (SHADOW["SINGLE"], 1))
        m = np.asarray(p.matrices[ls.first])
        for a in np.linspace(0.0, 2.0 * math.pi, 13):
            d = np.array([math.sin(half) * math.cos(a), math.sin(half) * math.sin(a), -math.cos(half)])
            clip = m @ np.r_[np.array([0.0, 0.0, 5.0]) + 3.0 * d, 1.0]
            self.assertTrue(np.all(np.abs(clip[:2] / clip[3]) < 1.0))
            self.assertAlmostEqual(clip[3], 3.0 * math.cos(half), places=9)
        wide = Scene(scene.instances, [Light(LIGHT["SPOT"], (0.0, 0.0, 5.0), (0.0, 0.0, -1.0), math.cos(math.radians(80.0)))])
        self.assertEqual(plan_mod.plan(wide, camera(), SETTINGS).lights[0].kind, SHADOW["CUBE"])

    def test_casters_outside_a_layer_and_those_that_cast_nothing_are_left_out(self):
        inside, outside, hidden = box_at((0.0, 0.0, 0.0)), box_at((0.0, 0.0, 50.0)), box_at((0.5, 0.0, 0.0))
        hidden.casts_shadow = False
        scene = Scene([inside, outside, hidden], [Light(LIGHT["SPOT"], (0.0, 0.0, 5.0), (0.0, 0.0, -1.0), math.cos(0.5))])
        p = plan_mod.plan(scene, camera(), SETTINGS)
        self.assertEqual(plan_mod.layer_casters(p, scene.instances), [[0]])

    def test_lights_past_the_layer_budget(self):
        lights = [Light(LIGHT["POINT"], (float(k), 0.0, 5.0)) for k in range(7)] + [Light(LIGHT["POINT"], shadow=False)]
        p = plan_mod.plan(Scene([box_at((0.0, 0.0, 0.0))], lights), camera(), SETTINGS)
        self.assertEqual(plan_mod.MAX_LAYERS, 32)
        self.assertEqual(p.layers, 30)                       # five cubes
        self.assertEqual(p.left_out, 2)
        self.assertEqual([ls is not None for ls in p.lights], [True] * 5 + [False] * 3)

    def test_nothing_to_draw(self):
        scene = Scene([box_at((0.0, 0.0, 0.0))], [Light(LIGHT["POINT"], shadow=False)])
        self.assertEqual(plan_mod.plan(scene, camera(), SETTINGS).layers, 0)


class MergedCasters(unittest.TestCase):
    def test_small_casters_in_world_space_large_hidden_and_alpha_cut_ones_on_their_own(self):
        rng = np.random.default_rng(3)
        small = box_at((1.0, 2.0, 3.0))
        small.mesh.corner_pos = rng.normal(size=(36, 3)).astype(np.float32)
        small.matrix[:3, :3] = [[0.0, -2.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.5]]
        large = box_at((0.0, 0.0, 0.0))
        large.mesh.corner_pos = np.zeros((3 * (plan_mod.MERGE_TRIANGLES + 1), 3), np.float32)
        hidden = box_at((5.0, 0.0, 0.0))
        hidden.casts_shadow = False
        cut = box_at((-5.0, 0.0, 0.0))  # an image's alpha cuts a slot: its own draws cut it (shadow_pass.cut_key)
        cut.mesh.slot_shading = (Shading(), Shading('CUT', Texture(shadow_alpha=1)))
        none = box_at((-7.0, 0.0, 0.0))  # a slot whose material casts none
        none.mesh.slot_shading = (Shading('NONE'),)
        plain = box_at((-6.0, 0.0, 0.0))  # shadows that would cut, but no image's alpha: the whole face
        plain.mesh.slot_shading = (Shading('CUT'), Shading('CUT', Texture(shadow_alpha=0)))
        picked, corners = plan_mod.merged_casters(Scene([large, small, hidden, cut, plain, none], []))
        self.assertEqual(picked, [1, 4])
        corners = corners[:len(small.mesh.corner_pos)]
        want = small.mesh.corner_pos.astype(np.float64) @ small.matrix[:3, :3].T + small.matrix[:3, 3]
        np.testing.assert_allclose(corners, want, rtol=1e-6, atol=1e-6)


if __name__ == "__main__":
    unittest.main()
