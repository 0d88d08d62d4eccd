"""The ink's copy of the fillet's outline point (the library's el_fillet_outline, with which
el_outline_lines moves silhouettes onto the rounded outline) against the shader's own function
(rounded_outline.glsl, el_fillet_outline: the strip the surface pass leaves out), evaluated on
the GPU (glsl_eval): the same silhouettes, the same outline point turned the same way, the same
C, for faces folded by 1 to 179 degrees seen from every side."""
import importlib
import unittest

import numpy as np

import glsl_eval
import helpers


def unit(a):
    return a / np.linalg.norm(a, axis=1, keepdims=True)


class FilletOutline(unittest.TestCase):
    def test_the_librarys_copy_matches_the_shader(self):
        fillet_outline = importlib.import_module(helpers.MODULE + ".bridge.native").fillet_outline
        rng = np.random.default_rng(11)
        na, nb, v = (unit(rng.normal(size=(6000, 3))) for _ in range(3))
        # Clear of the rule's boundaries, where float32 and float64 may judge a face either way:
        # a face seen edge-on, faces (nearly) parallel, or the edge seen end-on.
        clear = (np.abs(np.einsum("ij,ij->i", na, v)) > 1e-3) & (np.abs(np.einsum("ij,ij->i", nb, v)) > 1e-3) \
            & (np.linalg.norm(np.cross(np.cross(na, nb), v), axis=1) > 1e-3) & (np.einsum("ij,ij->i", na, nb) > -0.999)
        na, nb, v = na[clear], nb[clear], v[clear]
        functions = glsl_eval.function_source("rounded_outline.glsl", "el_fillet_outline")
        got = glsl_eval.evaluate(functions, "el_fillet_outline(na, nb, v, c_out)", {"na": na, "nb": nb, "v": v},
                                 before="vec3 c_out;")
        c = glsl_eval.evaluate(functions, "c_out, 0.0", {"na": na, "nb": nb, "v": v},
                               before="vec3 c_out; el_fillet_outline(na, nb, v, c_out);")[:, :3]
        p, c_ours, sil = fillet_outline(na, nb, v)
        print(f"fillet outline: {sil.sum()} silhouettes of {len(sil)}; P off by {np.abs(got[:, :3] - p).max():.1e}, "
              f"C by {np.abs(c - c_ours).max() / np.abs(c_ours).max():.1e} (relative)")
        self.assertGreater(sil.sum(), len(sil) // 4)
        self.assertLess(sil.sum(), len(sil) * 3 // 4)
        np.testing.assert_array_equal(got[:, 3] > 0.5, sil)
        self.assertLess(float(np.abs(got[:, :3] - p).max()), 1e-4)
        self.assertLess(float((np.abs(c - c_ours) / np.maximum(np.abs(c_ours), 1.0)).max()), 1e-3)
        # P turned towards the sharp edge: its image lies past the outline point, never inside.
        self.assertTrue((np.einsum("ij,ij->i", p[sil].astype(float), c_ours[sil]) >= 1.0 - 1e-5).all())


if __name__ == "__main__":
    unittest.main()
