"""CAD-like parts built by script (bmesh), for the highlight's ground truth (bench/ground_truth.py)
and the tests that pin it (tests/blender/test_fillet_parts.py). Each returns a bmesh with outward
normals, sized about 2 units, centred near the origin; the caller owns (and frees) it."""
import math

import bmesh


def _prism(profile, depth, bm=None):
    """The closed xz-polygon `profile` (counter-clockwise seen from -y) extruded along y over
    [-depth / 2, depth / 2]: two n-gon caps and one quad per side."""
    bm = bm or bmesh.new()
    a = [bm.verts.new((x, -0.5 * depth, z)) for x, z in profile]
    b = [bm.verts.new((x, 0.5 * depth, z)) for x, z in profile]
    bm.faces.new(a[::-1])
    bm.faces.new(b)
    for i in range(len(profile)):
        j = (i + 1) % len(profile)
        bm.faces.new((a[i], a[j], b[j], b[i]))
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces[:])
    return bm


def l_step():
    """A step: one concave edge (x = 0, z = 0, along y) between five convex ones."""
    return _prism([(-1, -1), (1, -1), (1, 0), (0, 0), (0, 1), (-1, 1)], 2.0)
