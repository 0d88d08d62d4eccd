"""The viewport's and the rounded outline's numpy copy of el_radius_scale (addon/geometry/radius_scale.py)
against the shader's own function, evaluated on the GPU (glsl_eval): under uniform, non-uniform,
sheared and mirrored transforms, and for faces with no direction across the edge (the fallback
to the unit diagonal's stretch)."""
import importlib
import unittest

import numpy as np

import glsl_eval
import helpers


def cases(rng, count):
    """Transforms (N, 4, 4), face normals na, nb and edge vectors e (N, 3) of every kind."""
    m = np.tile(np.eye(4), (count, 1, 1))
    kind = np.arange(count) % 4
    lin = rng.normal(size=(count, 3, 3))                                           # sheared
    lin[kind == 0] = np.eye(3) * rng.uniform(0.01, 100.0, (np.sum(kind == 0), 1, 1))  # uniform
    lin[kind == 1] = np.eye(3) * rng.uniform(0.1, 10.0, (np.sum(kind == 1), 1, 3))    # non-uniform
    lin[kind == 3] = np.eye(3) * rng.uniform(0.1, 10.0, (np.sum(kind == 3), 1, 3)) * [-1.0, 1.0, 1.0]  # mirrored
    m[:, :3, :3] = lin
    m[:, :3, 3] = rng.normal(size=(count, 3)) * 10.0
    e = rng.normal(size=(count, 3))
    na, nb = rng.normal(size=(count, 3)), rng.normal(size=(count, 3))
    na /= np.linalg.norm(na, axis=1, keepdims=True)
    nb /= np.linalg.norm(nb, axis=1, keepdims=True)
    along = np.arange(count) % 16 == 5  # a face whose normal runs along the edge
    na[along] = e[along] / np.linalg.norm(e[along], axis=1, keepdims=True)
    return m, na, nb, e, along


class RadiusScale(unittest.TestCase):
    def test_numpy_copy_matches_the_shader(self):
        radius_scale = importlib.import_module(helpers.MODULE + ".geometry.radius_scale").radius_scale
        m, na, nb, e, along = cases(np.random.default_rng(7), 4000)
        glsl = glsl_eval.evaluate(glsl_eval.function_source("lighting.glsl", "el_radius_scale"),
                                  "el_radius_scale(mat4(m0, m1, m2, m3), na, nb, e), 0.0, 0.0, 0.0",
                                  {"m0": m[:, :, 0], "m1": m[:, :, 1], "m2": m[:, :, 2], "m3": m[:, :, 3],
                                   "na": na, "nb": nb, "e": e})[:, 0].astype(np.float64)
        ours = np.array([radius_scale(m[i], na[i:i + 1], nb[i:i + 1], e[i:i + 1])[0] for i in range(len(m))])
        rel = np.abs(glsl - ours) / ours
        print(f"radius scale: numpy against GLSL, relative difference {np.median(rel):.1e} median, "
              f"{rel.max():.1e} at most over {len(m)} cases ({along.sum()} with a normal along the edge)")
        self.assertTrue(np.isfinite(glsl).all())
        self.assertLess(float(rel.max()), 1e-4)
        # The fallback is the unit diagonal's stretch, not the faces' (which it would be by chance
        # only): the cases exercise both branches.
        diagonal = np.linalg.norm(m[:, :3, :3] @ np.full(3, 1.0 / np.sqrt(3.0)), axis=1)
        self.assertLess(float(np.abs(glsl[along] / diagonal[along] - 1.0).max()), 1e-4)
        self.assertGreater(float(np.abs(glsl[~along] / diagonal[~along] - 1.0).max()), 0.1)


if __name__ == "__main__":
    unittest.main()
