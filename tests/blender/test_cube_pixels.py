"""Pixels of the cube sample (the paper's figure 3): the glinting edge, everything else exact."""
import unittest

import bpy
import numpy as np

import helpers

# The top-front edge of the cube sample: its bisector is the half vector (make_samples.py).
A, B = (-1.0, -1.0, 1.0), (1.0, -1.0, 1.0)
TS = np.linspace(0.15, 0.85, 15)
BAND = np.arange(-3.0, 3.5, 0.5)


class CubePixels(unittest.TestCase):
    def render(self, **material):
        helpers.open_sample("cube")
        for key, value in material.items():
            setattr(bpy.data.materials["Cube"].edgelight, key, value)
        return helpers.render(resolution=(640, 480))

    def test_glint_is_brighter_than_both_faces(self):
        rec = self.render()
        lum = helpers.luminance(rec["pixels"][..., :3])[..., None]
        prof = helpers.edge_profile(rec, lum, A, B, TS, np.r_[-12.0, BAND, 12.0])[..., 0]
        faces = np.maximum(prof[:, 0], prof[:, -1])
        glint = prof[:, 1:-1].max(axis=1)
        margin = glint - faces
        print(f"glint margin over the brighter face: min {margin.min():.3f} mean {margin.mean():.3f}")
        self.assertTrue((margin > 0.05).all(), margin)  # measured: min 0.07 on this sample

    def test_pixels_off_edges_equal_the_surface_pass(self):
        rec = self.render()
        px, surf, hl = rec["pixels"], rec["surface"], rec["highlight"]
        off = (helpers.highlight_change(rec) == 0.0) & (surf[..., 3] == 1.0)
        on_object = surf[..., 3] == 1.0
        self.assertGreater(off.sum(), 0.95 * on_object.sum())
        self.assertTrue(np.array_equal(px[off][:, :3], surf[off][:, :3]))
        self.assertGreater((hl[..., 3] > 0).sum(), 500, "the edges were drawn")

    def test_k_zero_is_the_surface_image_bit_for_bit(self):
        with_k0 = self.render(K=0.0)["pixels"]
        helpers.open_sample("cube", highlights=False)
        surface_only = helpers.render(resolution=(640, 480))["pixels"]
        self.assertTrue(np.array_equal(with_k0, surface_only))
        helpers.open_sample("cube")
        full = helpers.render(resolution=(640, 480))["pixels"]
        self.assertFalse(np.array_equal(full, surface_only), "the highlight changes the image")

    def test_larger_radius_never_darkens_the_glint(self):
        totals = []
        for r in (0.0025, 0.005, 0.01, 0.02, 0.04, 0.08):
            rec = self.render(radius=r)
            lum = helpers.luminance(rec["pixels"][..., :3])[..., None]
            totals.append(helpers.edge_profile(rec, lum, A, B, TS, np.arange(-8.0, 8.5, 0.5))[..., 0].sum())
        print("edge brightness by radius:", np.round(totals, 2))
        self.assertTrue(all(b >= a - 1e-4 for a, b in zip(totals, totals[1:])), totals)
        self.assertGreater(totals[-1], totals[0] + 1.0)


if __name__ == "__main__":
    unittest.main()
