"""The world image's filter (addon/extract/environment_filter.py) against closed forms: a uniform image
gives itself in every tile; under radiance 1 above the horizon the irradiance tile holds
E / pi = (1 + sin elevation) / 2, and under radiance z it holds 2/3 n.z; a GGX level of a
linear image is a multiple of its direction's z; the row-pair FFT equals the direct sum over
every texel; the box filter keeps the mean by solid angle; level 0 faces +X at u = 1/2."""
import math
import unittest

import numpy as np

from addon_modules import addon_module

ef = addon_module("extract.environment_filter")


def tile(atlas, rect):
    x, y, w, h = rect
    return atlas.pixels[y:y + h, x:x + w, :3].astype(np.float64)


class EnvironmentFilter(unittest.TestCase):
    def test_a_uniform_image_gives_itself(self):
        atlas = ef.prefilter(np.full((100, 200, 3), (0.3, 0.5, 2.0), np.float32))
        for rect in atlas.levels + (atlas.irradiance,):
            np.testing.assert_allclose(tile(atlas, rect), np.broadcast_to((0.3, 0.5, 2.0), tile(atlas, rect).shape), rtol=1e-5)
        np.testing.assert_allclose(atlas.mean, (0.3, 0.5, 2.0), rtol=1e-6)

    def test_irradiance_of_a_lit_upper_hemisphere(self):
        d = ef.directions(1024, 512)
        atlas = ef.prefilter(np.repeat((d[..., 2:3] > 0.0).astype(np.float32), 3, axis=2))
        irr = tile(atlas, atlas.irradiance)[..., 0]
        n = ef.tile_directions(*atlas.irradiance[2:])
        # Measured: within 1.3e-3 (the 64 x 32 grid the convolution runs on).
        np.testing.assert_allclose(irr, (1.0 + n[..., 2]) / 2.0, atol=2e-3)
        self.assertAlmostEqual(atlas.mean[0], 0.5, places=6)

    def test_irradiance_of_a_linear_image(self):
        """Radiance 1 + z (non-negative, as world_light.py hands it in)."""
        d = ef.directions(1024, 512)
        atlas = ef.prefilter(np.repeat(1.0 + d[..., 2:3], 3, axis=2).astype(np.float32))
        n = ef.tile_directions(*atlas.irradiance[2:])
        # E / pi of 1 + z: 1 + (2/3) n.z (the integral of l max(n.l, 0) is 2 pi n / 3).
        np.testing.assert_allclose(tile(atlas, atlas.irradiance)[..., 0], 1.0 + 2.0 / 3.0 * n[..., 2], atol=3e-3)

    def test_a_ggx_level_of_a_linear_image_is_a_multiple_of_z(self):
        """A lobe symmetric about r maps radiance 1 + z to 1 + c r.z, c the lobe's mean cos."""
        d = ef.directions(1024, 512)
        atlas = ef.prefilter(np.repeat(1.0 + d[..., 2:3], 3, axis=2).astype(np.float32))
        for k, rect in enumerate(atlas.levels[1:], start=1):
            level = tile(atlas, rect)[..., 0] - 1.0
            z = ef.tile_directions(*rect[2:])[..., 2]
            c = np.sum(level * z) / np.sum(z * z)
            self.assertLess(c, 1.0)
            self.assertGreater(c, 0.3)
            np.testing.assert_allclose(level, c * z, atol=4e-3, err_msg=f"level {k}")
        grid = [ef.directions] + [ef.tile_directions] * (len(atlas.levels) - 1)  # level 0: the image's texels
        cs = [np.sum((tile(atlas, r)[..., 0] - 1.0) * g(*r[2:])[..., 2]) / np.sum(g(*r[2:])[..., 2] ** 2)
              for g, r in zip(grid, atlas.levels)]
        self.assertTrue(all(a > b for a, b in zip(cs, cs[1:])), f"rougher levels spread wider: {cs}")

    def test_the_fft_is_the_direct_sum(self):
        rng = np.random.default_rng(3)
        src = rng.random((32, 64, 3)).astype(np.float32)
        d = ef.directions(64, 32).reshape(-1, 3)
        out = ef.tile_directions(64, 17).reshape(-1, 3)
        sa = np.repeat(ef.solid_angles(64, 32), 64)
        for weight in (ef.ggx_weight(0.5), ef.ggx_weight(0.25), ef.cosine_weight):
            w = weight(out @ d.T) * sa[None, :]
            direct = (w @ src.reshape(-1, 3)) / w.sum(axis=1)[:, None]
            np.testing.assert_allclose(ef._convolve(src, weight, 17).reshape(-1, 3), direct, atol=1e-10)

    def test_the_filtered_tiles_hold_the_poles(self):
        """A floor's normal points exactly at the pole: the tiles' last row is E / pi there, the
        same in every column (brute force over the whole image)."""
        rng = np.random.default_rng(5)
        src = rng.random((128, 256, 3)).astype(np.float32) * np.linspace(0.2, 2.0, 256)[None, :, None]
        atlas = ef.prefilter(src)
        d = ef.directions(256, 128)
        w = np.maximum(d[..., 2], 0.0) * ef.solid_angles(256, 128)[:, None]
        up = (src * w[..., None]).sum(axis=(0, 1)) / w.sum()
        top = tile(atlas, atlas.irradiance)[-1]
        np.testing.assert_allclose(top, np.broadcast_to(up, top.shape), rtol=5e-3)
        self.assertLess(float(np.ptp(top, axis=0).max()), 1e-5, "one value in every column")

    def test_the_box_filter_keeps_the_mean(self):
        rng = np.random.default_rng(4)
        src = rng.random((300, 600, 3)).astype(np.float32)
        for w, h in ((512, 256), (128, 64), (37, 19)):
            out = ef.resample(src, w, h)
            def mean(img):
                sa = ef.solid_angles(img.shape[1], img.shape[0])
                return (img * sa[:, None, None]).sum(axis=(0, 1)) / (sa.sum() * img.shape[1])
            np.testing.assert_allclose(mean(out), mean(src), rtol=2e-3, err_msg=f"{w} x {h}")

    def test_blenders_mapping(self):
        d = ef.directions(8, 4)
        # u = 1/2 looks along +X, u = 3/4 along -Y (u = 1/2 - atan2(y, x) / 2 pi), rows bottom-up.
        np.testing.assert_allclose(d[1, 4], [math.cos(math.radians(22.5)) * math.cos(math.pi / 8.0),
                                             -math.cos(math.radians(22.5)) * math.sin(math.pi / 8.0),
                                             -math.sin(math.radians(22.5))], atol=1e-12)
        self.assertLess(d[0, 0, 2], 0.0, "row 0 is the bottom")
        self.assertLess(d[2, 6, 1], 0.0, "u = 13/16 points to -Y")

    def test_level_zero_keeps_the_image_within_its_width(self):
        small = ef.prefilter(np.ones((64, 128, 3), np.float32))
        self.assertEqual(small.levels[0], (0, 0, 128, 64))  # not enlarged
        self.assertEqual(small.pixels.shape, (64 + 64, 288, 4))  # the filtered tiles fit beside it
        self.assertEqual(ef.prefilter(np.ones((1024, 2048, 3), np.float32)).levels[0], (0, 0, 2048, 1024))
        self.assertEqual(ef.prefilter(np.ones((2048, 4096, 3), np.float32)).levels[0], (0, 0, 2048, 1024))


if __name__ == "__main__":
    unittest.main()
