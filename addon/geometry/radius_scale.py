"""How a rounded edge's radius, in object space as the Bevel modifier's Amount is, scales into
world units under an object's transform: the numpy side of lighting.glsl's el_radius_scale, for
the CPU's copy of what the shaders decide in the viewport's edge culling (the library has its own
for silhouettes on the rounded outline: native/src/outline_lines.cpp, held to the numpy reference
tests/addon/outline_lines_reference.py). No bpy: plain-Python tests import it."""
import numpy as np


def radius_scale(m, na, nb, e):
    """Per edge, how its radius scales into world units under m (lighting.glsl, el_radius_scale:
    the mean stretch of its two faces' directions square to it, object space)."""
    lin = np.asarray(m, np.float64)[:3, :3]
    gram = lin.T @ lin
    if np.allclose(gram, np.eye(3) * gram[0, 0], rtol=0.0, atol=1e-12 * max(gram[0, 0], 1e-300)):
        return np.full(len(e), np.sqrt(gram[0, 0]))  # a uniform scale s: every edge's is s
    u = e / np.maximum(np.linalg.norm(e, axis=1, keepdims=True), 1e-30)
    da, db = np.cross(na, u), np.cross(nb, u)
    la, lb = np.linalg.norm(da, axis=1), np.linalg.norm(db, axis=1)
    ok = (la > 1e-6) & (lb > 1e-6)
    out = np.full(len(e), np.linalg.norm(lin @ np.full(3, 1.0 / np.sqrt(3.0))))
    sa = np.linalg.norm(da[ok] @ lin.T, axis=1) / la[ok]
    sb = np.linalg.norm(db[ok] @ lin.T, axis=1) / lb[ok]
    out[ok] = 0.5 * (sa + sb)
    return out

