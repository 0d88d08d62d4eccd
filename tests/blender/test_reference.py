"""The edge highlight shader against the native double-precision reference integral."""
import math
import os
import sys
import unittest

import bpy
import numpy as np

import helpers

sys.path.insert(0, os.path.join(helpers.ROOT, "bench"))
import edge_methods  # noqa: E402

A, B = np.array((-1.0, -1.0, 1.0)), np.array((1.0, -1.0, 1.0))  # cube sample's glinting edge
N1, N2 = (0.0, 0.0, 1.0), (0.0, -1.0, 0.0)                      # top face, front face
# Stated tolerance: the float32 shader path (table + closed form + Gauss-Legendre) against the
# adaptive double quadrature, relative to the pixel's highlight colour.
RELATIVE_TOLERANCE = 1e-4  # measured: 4.3e-6 on llvmpipe


def render_whole_arc(resolution):
    """These tests check the arc integral itself, which the whole-arc method applies to every
    pixel of a band; bands wider than a pixel otherwise shade each pixel with its own part of
    the arc (test_wide_edges.py checks that)."""
    with edge_methods.method("whole"):  # the benchmarks' variant (bench/edge_methods.py)
        return helpers.render(resolution=resolution)


def blinn_norm(n):
    return (n + 8.0) / (8.0 * math.pi)


class ShaderMatchesReference(unittest.TestCase):
    def test_highlight_colour_and_weight(self):
        native = helpers.addon().bridge.native
        helpers.open_sample("cube")
        mat = bpy.data.materials["Cube"]
        mat.edgelight.radius = 0.05  # a few pixels wide: many pixels to compare
        rec = render_whole_arc((640, 480))
        cam, scene = rec["camera"], rec["scene"]
        hl = rec["highlight"]
        shading = scene.instances[0].mesh.slot_shading[0]
        light = scene.lights[0]
        s0, s1 = helpers.project(rec, [A, B])
        d = (s1 - s0) / np.linalg.norm(s1 - s0)
        nrm = np.array([-d[1], d[0]])
        w0 = (cam.projection @ cam.view @ np.r_[A, 1.0])[3]
        w1 = (cam.projection @ cam.view @ np.r_[B, 1.0])[3]
        ys, xs = np.nonzero(hl[..., 3] > 0.2)
        checked, worst_rel, worst_w = 0, 0.0, 0.0
        for x, y in zip(xs, ys):
            pc = np.array([x + 0.5, y + 0.5])
            u = np.dot(pc - s0, d) / np.linalg.norm(s1 - s0)
            across = np.dot(pc - s0, nrm)
            if not 0.1 < u < 0.9 or abs(across) > 8.0:
                continue  # this edge only, away from the corners
            t = (u / w1) / ((1.0 - u) / w0 + u / w1)  # perspective-correct, as the rasteriser
            X = A + t * (B - A)
            inp = native.HighlightInput()
            inp.point[:] = X.tolist()
            inp.edge_dir[:] = (B - A).tolist()
            inp.n1[:], inp.n2[:] = N1, N2
            inp.eye[:] = list(cam.eye)
            inp.projection = native.PERSPECTIVE
            inp.light[:] = [-c for c in light.direction]
            inp.shininess = shading.shininess
            inp.radius = shading.radius
            inp.K = cam.px_per_unit
            ref = native.highlight_reference(inp)
            expected = (helpers.world_on_arc(inp, np.array(cam.eye) - X, shading, scene.ambient)
                        + np.array(light.color) * (np.array(shading.base_color) * ref.diffuse / math.pi
                                                   + np.array(shading.tint) * shading.spec_color
                                                   * blinn_norm(shading.shininess) * ref.specular))
            got = hl[y, x, :3] / hl[y, x, 3]
            rel = np.max(np.abs(got - expected)) / max(np.max(expected), 1e-6)
            worst_rel = max(worst_rel, rel)
            # Coverage of the pixel by the band of the reference's width around the line.
            # Unclamped W of the paper: K r_e / (d r_max), the band's width in pixels.
            w_px = cam.px_per_unit * shading.radius / (np.linalg.norm(np.array(cam.eye) - X) * ref.r_max)
            cover = np.clip(min(across + 0.5, 0.5 * w_px) - max(across - 0.5, -0.5 * w_px), 0.0, 1.0)
            worst_w = max(worst_w, abs(hl[y, x, 3] - cover))
            checked += 1
        print(f"checked {checked} pixels: worst colour error {worst_rel:.2e} (relative), worst weight error {worst_w:.2e}")
        self.assertGreater(checked, 100)
        self.assertLess(worst_rel, RELATIVE_TOLERANCE)
        self.assertLess(worst_w, 1e-3)  # measured: 2e-5


class ShortEdgesMatchReference(unittest.TestCase):
    def test_edges_under_16_px_carry_the_midpoint_colour(self):
        """Short edges are shaded once in the vertex shader, at their midpoint."""
        native = helpers.addon().bridge.native
        helpers.open_sample("cube")
        bpy.data.materials["Cube"].edgelight.radius = 0.2  # wide enough to cover whole pixels
        rec = render_whole_arc((48, 36))
        cam, scene, hl = rec["camera"], rec["scene"], rec["highlight"]
        s0, s1 = helpers.project(rec, [A, B])
        self.assertLess(np.linalg.norm(s1 - s0), 16.0, "the edge is short on screen")
        shading, light = scene.instances[0].mesh.slot_shading[0], scene.lights[0]
        mid = 0.5 * (A + B)
        inp = native.HighlightInput()
        inp.point[:] = mid.tolist()
        inp.edge_dir[:] = (B - A).tolist()
        inp.n1[:], inp.n2[:] = N1, N2
        inp.eye[:] = list(cam.eye)
        inp.projection = native.PERSPECTIVE
        inp.light[:] = [-c for c in light.direction]
        inp.shininess, inp.radius, inp.K = shading.shininess, shading.radius, cam.px_per_unit
        ref = native.highlight_reference(inp)
        expected = (helpers.world_on_arc(inp, np.array(cam.eye) - mid, shading, scene.ambient)
                    + np.array(light.color) * (np.array(shading.base_color) * ref.diffuse / math.pi
                                               + np.array(shading.tint) * shading.spec_color
                                               * blinn_norm(shading.shininess) * ref.specular))
        d = (s1 - s0) / np.linalg.norm(s1 - s0)
        nrm = np.array([-d[1], d[0]])
        checked = 0
        for y, x in zip(*np.nonzero(hl[..., 3] > 0.5)):
            pc = np.array([x + 0.5, y + 0.5])
            u = np.dot(pc - s0, d) / np.linalg.norm(s1 - s0)
            if 0.3 < u < 0.7 and abs(np.dot(pc - s0, nrm)) < 0.5:
                got = hl[y, x, :3] / hl[y, x, 3]
                self.assertLess(np.max(np.abs(got - expected)) / np.max(expected), RELATIVE_TOLERANCE, (x, y, got, expected))
                checked += 1
        self.assertGreater(checked, 2)


if __name__ == "__main__":
    unittest.main()
