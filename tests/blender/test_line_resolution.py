"""Lines at the screen's resolution (passes/line_pass.py, docs/lines.md): chains drawn as chords
that stay within TOLERANCE_PX of the segments they stand for, crease chains smaller than a pixel
skipped, and quads that the visibility rule hides everywhere never rasterised; each measured
against the line pass drawing every segment."""
import math
import unittest

import bmesh
import bpy
import numpy as np

import helpers
from test_line_visibility import off_part


def line_pass():
    return helpers.addon().passes.line_pass


class Settings:
    """Sets the line pass's module settings for a `with` block (the tests' reference: every
    segment drawn, nothing culled or skipped)."""

    def __init__(self, **values):
        self.values = values

    def __enter__(self):
        lp = line_pass()
        self.saved = {k: getattr(lp, k) for k in self.values}
        for k, v in self.values.items():
            setattr(lp, k, v)

    def __exit__(self, *exc):
        for k, v in self.saved.items():
            setattr(line_pass(), k, v)


def reference(**extra):
    """Every segment drawn, no crease chain skipped, no hidden quad culled."""
    return Settings(TOLERANCE_PX=-1.0, SUBPIXEL_PX=0.0, CULL_HIDDEN=False, **extra)


def alpha_of(rec):
    return rec["lines"][..., 3].copy()


def dilate(mask, r):
    out = np.zeros_like(mask)
    h, w = mask.shape
    R = int(math.ceil(r))
    for dy in range(-R, R + 1):
        for dx in range(-R, R + 1):
            if dx * dx + dy * dy <= r * r + 1e-9:
                out[max(-dy, 0):h + min(-dy, 0), max(-dx, 0):w + min(-dx, 0)] |= \
                    mask[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)]
    return out


def stray(a, b, r, hi=0.5, lo=0.1):
    """Pixels inked (alpha >= hi) in a with no pixel inked (alpha >= lo) in b within r pixels."""
    return int(((a >= hi) & ~dilate(b >= lo, r)).sum())


def project(cam, matrix, points):
    """Object points -> (pixel coordinates (x right, y up), view depths)."""
    p = np.c_[np.asarray(points, np.float64), np.ones(len(points))]
    v = p @ (np.asarray(cam.view, np.float64) @ np.asarray(matrix, np.float64)).T
    c = v @ np.asarray(cam.projection, np.float64).T
    return (c[:, :2] / c[:, 3:4] * 0.5 + 0.5) * np.array([cam.width, cam.height]), -v[:, 2]


def drawn_chords(nodes, matrix, cam, tolerance):
    """The vertex shader's choice (line.vert.glsl), ported: per segment record, the number of
    segments of the chord it draws (0: none). nodes: line_pass.LineNodes(...).nodes."""
    rec = nodes.reshape(len(nodes), -1, 4)
    tree, group = rec[:, 2].astype(np.float64), rec[:, 3].astype(np.float64)
    P = np.asarray(cam.projection, np.float64)
    f = max(abs(P[0, 0]) * cam.width, abs(P[1, 1]) * cam.height) * 0.5
    stretch = np.linalg.norm(np.asarray(matrix, np.float64)[:3, :3], 2)
    if cam.orthographic:
        k = np.full(len(rec), f * stretch)
    else:
        c = np.c_[group[:, :3], np.ones(len(rec))] @ (np.asarray(cam.view) @ np.asarray(matrix, np.float64)).T
        r = group[:, 3] * stretch
        z_min = -c[:, 2] - r
        tan = (np.linalg.norm(c[:, :2], axis=1) + r) / np.where(z_min > 0, z_min, 1.0)
        k = np.where(z_min > 1e-6 * np.maximum(r, 1e-6), f * stretch * np.sqrt(1 + tan * tan) / np.where(z_min > 0, z_min, 1.0), 1e30)
    fits = [(tree[:, j] >= 0) & (tree[:, j] * k <= tolerance) for j in range(3)]
    level = np.where(~fits[0], 0, np.where(~fits[1], 1, np.where(~fits[2], 2, 3)))
    code = tree[:, 3].astype(np.int64)
    count = np.where(level == 0, 1, (code >> (4 * np.maximum(level - 1, 0))) & 15)
    return np.where(tolerance < 0, 1, count)


def dense_scene():
    """fandisk seen small (~150 px) and a cylinder of 600 sides (rim segments ~0.7 px): chains
    of segments about a pixel long or shorter."""
    scene = helpers.empty_scene(640, 480, highlights=False)
    helpers.add_camera((7.2, -9.0, 6.6), (0.6, 0.0, 0.0), lens=50.0)
    helpers.add_sun()
    off_part("fandisk")
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=True, segments=600, radius1=0.6, radius2=0.6, depth=1.0)
    me = bpy.data.meshes.new("Drum")
    bm.to_mesh(me)
    bm.free()
    ob = bpy.data.objects.new("Drum", me)
    ob.location = (1.8, 0.5, 0.0)
    scene.collection.objects.link(ob)
    helpers.only_lines(scene, silhouette=1.5, crease=1.5, border=1.5)
    return scene


class ChordsWithinTolerance(unittest.TestCase):
    def test_chords_cover_each_segment_once_within_the_tolerance(self):
        """The bound itself (the chosen chords, on the CPU): every segment is stood for by
        exactly one drawn chord, and every point of it projects within TOLERANCE_PX of that
        chord, on a scene where most segments merge."""
        helpers.needs_gpu()
        dense_scene()
        rec = helpers.render()
        lp, cam = line_pass(), rec["camera"]
        segments = drawn = 0
        worst = 0.0
        for inst in rec["scene"].instances:
            seg = inst.mesh.lines.get("crease")
            if seg is None or not len(seg):
                continue
            nodes = lp.LineNodes(seg, chain_spheres=False)
            rec_ = nodes.nodes.reshape(len(nodes), -1, 4)
            count = drawn_chords(nodes.nodes, inst.matrix, cam, lp.TOLERANCE_PX)
            cover = np.zeros(len(count), int)
            for i in np.flatnonzero(count):
                cover[i:i + count[i]] += 1
            self.assertTrue(np.all(cover == 1), "a segment stood for by no chord or by two")
            segments += len(count)
            drawn += int((count > 0).sum())
            # The chord from a of record i to b of record i + count - 1 against the projected
            # ends of every segment it stands for.
            a2, _ = project(cam, inst.matrix, rec_[:, 0, :3])
            b2, _ = project(cam, inst.matrix, rec_[:, 1, :3])
            for i in np.flatnonzero(count > 1):
                j = i + count[i] - 1
                ca, cb = a2[i], b2[j]
                pts = np.r_[a2[i:j + 1], b2[i:j + 1]]
                ab = cb - ca
                t = np.clip(((pts - ca) @ ab) / max(ab @ ab, 1e-12), 0.0, 1.0)
                worst = max(worst, float(np.linalg.norm(pts - (ca + t[:, None] * ab), axis=1).max()))
        print(f"line resolution: {segments} crease segments drawn as {drawn} chords, farthest segment point "
              f"{worst:.3f} px from its chord (tolerance {lp.TOLERANCE_PX} px)")
        self.assertLessEqual(worst, lp.TOLERANCE_PX + 1e-3)
        self.assertLess(drawn, 0.5 * segments)  # the scene does merge: the bound is not vacuous

    def test_rendered_ink_within_a_pixel_of_every_segment_drawn(self):
        """The image: ink drawn from chords against ink drawn from every segment, each inked
        pixel (alpha >= 0.5) of one within 1 px of ink (alpha >= 0.1) of the other, and the
        coverage of a pixel changed by more than the tolerance only where visibility flips."""
        helpers.needs_gpu()
        dense_scene()
        with reference():
            ref = alpha_of(helpers.render())
        with Settings(SUBPIXEL_PX=0.0, CULL_HIDDEN=False):
            lod = alpha_of(helpers.render())
        d = np.abs(lod - ref)
        far = stray(lod, ref, 1.0) + stray(ref, lod, 1.0)
        print(f"line resolution: {int((ref >= 0.5).sum())} ink px; pixels off by > 0.25: {int((d > 0.25).sum())}, "
              f"max |d alpha| {d.max():.3f}; ink farther than 1 px from the other's: {far}")
        self.assertGreater(int((ref >= 0.5).sum()), 1000)
        self.assertEqual(far, 0)
        self.assertLessEqual(int((d > 0.25 + 1e-3).sum()), 0.01 * int((ref >= 0.5).sum()))


class SubpixelCreases(unittest.TestCase):
    def render_cubes(self, **lines):
        """A cube 2 units across near the camera, a cube 0.05 across (a few pixels) and a row
        of cubes 0.004 across (half a pixel) far from it."""
        import scene_zoo as zoo
        scene = helpers.empty_scene(480, 360, highlights=False)
        helpers.add_camera((0.0, -12.0, 0.0), (0.0, 0.0, 0.0), lens=50.0)
        helpers.add_sun()
        big = zoo.box("Big", 2.0)
        big.location = (-2.5, 0.0, 0.0)
        small = zoo.box("Small", 0.05)
        small.location = (0.0, 0.0, 1.5)
        tiny = []
        for k in range(7):
            ob = zoo.box(f"Tiny{k}", 0.004)
            ob.location = (0.4 * k, 0.0, -1.0)
            ob.rotation_euler = (0.5, 0.3, 0.2 * k)
            tiny.append(ob)
        big.rotation_euler = small.rotation_euler = (0.5, 0.3, 0.4)
        helpers.only_lines(scene, **lines)
        rec = helpers.render()
        alpha = alpha_of(rec)
        cam = rec["camera"]

        def ink_near(ob, r):
            xy, _ = project(cam, np.eye(4), [tuple(ob.location)])
            x0, y0 = int(xy[0, 0]), int(xy[0, 1])
            return float(alpha[max(y0 - r, 0):y0 + r + 1, max(x0 - r, 0):x0 + r + 1].sum())
        return (alpha, ink_near(big, 60), ink_near(small, 4), sum(ink_near(t, 3) for t in tiny))

    def test_crease_chains_under_a_pixel_are_skipped_and_the_others_stay(self):
        helpers.needs_gpu()
        with reference():
            ref, ref_big, ref_small, ref_tiny = self.render_cubes(crease=1.5)
        with Settings(CULL_HIDDEN=False):
            got, big, small, tiny = self.render_cubes(crease=1.5)
        print(f"sub-pixel creases: ink at the tiny cubes {ref_tiny:.1f} -> {tiny:.1f}, "
              f"small cube {ref_small:.1f} -> {small:.1f}, big cube {ref_big:.1f} -> {big:.1f}")
        self.assertGreater(ref_tiny, 1.0)  # drawn without the rule: dots of ink
        self.assertEqual(tiny, 0.0)
        self.assertGreater(small, 1.0)
        self.assertAlmostEqual(small, ref_small, delta=1e-3 * ref_small)
        self.assertGreater(big, 100.0)
        self.assertAlmostEqual(big, ref_big, delta=1e-3 * ref_big)

    def test_silhouettes_of_sub_pixel_parts_stay(self):
        """Only creases are skipped: a part smaller than a pixel keeps its outline's dot."""
        helpers.needs_gpu()
        _, _, _, tiny = self.render_cubes(crease=1.5, silhouette=1.5)
        self.assertGreater(tiny, 1.0)


class HiddenQuadsCulled(unittest.TestCase):
    """Culling a quad before it is rasterised changes no pixel: the vertex shader's test is a
    conservative copy of the fragment shader's rule (line.vert.glsl, el_line_may_show)."""

    def same_with_and_without(self, label, hidden='OFF'):
        bpy.context.scene.edgelight.hidden_lines = hidden
        with Settings(CULL_HIDDEN=False):
            ref = alpha_of(helpers.render())
        with Settings(CULL_HIDDEN=True):
            got = alpha_of(helpers.render())
        d = float(np.abs(got - ref).max())
        print(f"hidden quads culled, {label} ({hidden}): {int((ref > 0).sum())} ink px, max |d alpha| {d:.2e}")
        self.assertGreater(int((ref > 0).sum()), 100, label)
        self.assertLessEqual(d, 1e-6, label)

    def test_a_grid_of_cubes(self):
        helpers.needs_gpu()
        import scene_zoo as zoo
        scene = helpers.empty_scene(480, 360, highlights=False)
        helpers.add_camera((9.0, -11.0, 7.0), (2.0, 2.0, 2.0), lens=50.0)
        helpers.add_sun()
        for k in range(64):
            ob = zoo.box(f"Box{k}", 1.0)
            ob.location = (1.6 * (k % 4), 1.6 * (k // 4 % 4), 1.6 * (k // 16))
        helpers.only_lines(scene, silhouette=2.0, crease=2.0, border=2.0)
        self.same_with_and_without("4 x 4 x 4 cubes")
        self.same_with_and_without("4 x 4 x 4 cubes", 'DIMMED')

    def test_thin_walls_and_a_dense_part(self):
        helpers.needs_gpu()
        from test_line_visibility import tube
        scene = helpers.empty_scene(480, 360, highlights=False)
        helpers.add_camera((5.0, -2.0, 0.6), (0.0, 0.0, 0.8), lens=50.0)
        helpers.add_sun()
        tube("Tube", wall=0.02)
        helpers.only_lines(scene, silhouette=1.5, crease=1.5, border=1.5)
        self.same_with_and_without("hollow tube at a grazing angle")
        scene = helpers.empty_scene(480, 360, highlights=False)
        helpers.add_camera((2.6, -3.2, 1.6), lens=50.0)
        helpers.add_sun()
        off_part("cow")
        helpers.only_lines(scene, silhouette=1.5, crease=1.5, border=1.5, contour=1.5)
        self.same_with_and_without("cow")


if __name__ == "__main__":
    unittest.main()
