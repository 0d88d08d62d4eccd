"""The line pass's visibility rule on the CPU (numpy), for output that must agree with the
rendered lines (the SVG output). A line-for-line port of the visibility block of
shaders/line.frag.glsl (docs/lines.md, "Visibility"); test_svg_output.py pins the two together.
"""
import numpy as np

# Relative part of the depth bias (line.frag.glsl), against float rounding of depths.
REL_BIAS = 1e-4
# Line types that can lie on an outline: the background beside them does not hide them.
OUTLINE_TYPES = frozenset({"silhouette", "border", "contour", "wire"})


def clipped(z, projection):
    """Which points at view depth z lie outside the camera's clip range (line.frag.glsl's
    first test: |clip z| > clip w)."""
    p = np.asarray(projection, np.float64)
    zv = -np.asarray(z, np.float64)
    cz, cw = p[2, 2] * zv + p[2, 3], p[3, 2] * zv + p[3, 3]
    return np.abs(cz) > cw


def visible(c, z, faces, instance_id, outline, depth, ids, px_per_unit, perspective):
    """Which centre points of lines are visible.

    c: (N, 2) pixel coordinates of the points (x right, y up, pixel centres at .5: gl_FragCoord);
    z: (N,) their view depths; faces: (N, 2) the surface ids of the faces their segment lies on;
    instance_id: (N,) or scalar, the instance's id; outline: (N,) or scalar, whether the type can
    lie on an outline (OUTLINE_TYPES). depth: (h, w) the first sample's 1 / view depth (0 =
    empty); ids: (h, w, >= 2) its instance and face ids, both as read back (row 0 at the bottom).
    """
    h, w = depth.shape
    c, z, faces, inst, outline, q, world_per_px, bias = _points(c, z, faces, instance_id, outline, px_per_unit,
                                                                perspective)
    n = len(z)
    yc, xc = np.clip(q[:, 1], 0, h - 1), np.clip(q[:, 0], 0, w - 1)
    id_c = ids[yc, xc, :2]
    inv_c = depth[yc, xc]
    # The 3x3 pixels' ids and depths, k = (dy + 1) * 3 + (dx + 1) as in the shader.
    nid, ninv, own = [], [], np.zeros(n, bool)
    for dy in (-1, 0, 1):
        y = np.clip(q[:, 1] + dy, 0, h - 1)
        for dx in (-1, 0, 1):
            x = np.clip(q[:, 0] + dx, 0, w - 1)
            own |= _own_face(ids, y, x, inst, faces)
            nid.append(ids[y, x, :2])
            ninv.append(depth[y, x])
    same = [np.all(i == id_c, axis=1) for i in nid]
    # The centre face's step of 1/z per pixel (1/z is affine across a plane), from a pixel beside
    # the centre that shows the same face.
    right, left = (q[:, 0] < w - 1) & same[5], (q[:, 0] > 0) & same[3]
    up, down = (q[:, 1] < h - 1) & same[7], (q[:, 1] > 0) & same[1]
    gx = np.where(right, ninv[5] - inv_c, inv_c - ninv[3])
    gy = np.where(up, ninv[7] - inv_c, inv_c - ninv[1])
    has_gx, has_gy = right | left, up | down
    # The centre face continued along its plane to the line's point c, and whether the line lies
    # more than a footprint under it there.
    at_c = c - (q.astype(np.float32) + np.float32(0.5))
    inv_at = inv_c + at_c[:, 0] * gx + at_c[:, 1] * gy
    plane_at = (inv_c > 0.0) & has_gx & has_gy & (inv_at > 0.0)
    with np.errstate(divide="ignore"):
        under = plane_at & (z > np.float32(1.0) / np.where(plane_at, inv_at, np.float32(1.0)) + world_per_px + bias)
    # The farthest of the 3x3 pixels beyond an outline of the centre pixel's face: showing
    # something else, and not the continuation of its plane (a seam of one flat surface).
    inv_other = inv_c.copy()
    for k in range(9):
        dx, dy = k % 3 - 1, k // 3 - 1
        known = (inv_c > 0.0) & (ninv[k] > 0.0) & (has_gx if dx else True) & (has_gy if dy else True)
        plane = inv_c + (dx * gx if dx else np.float32(0.0)) + (dy * gy if dy else np.float32(0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            off = np.abs(np.float32(1.0) / np.where(known, ninv[k], np.float32(1.0))
                         - np.float32(1.0) / np.where(known & (plane > 0.0), plane, np.float32(1.0)))
        seam = known & (plane > 0.0) & (off <= bias)
        beyond = ~same[k] & ~seam
        inv_other = np.where(beyond, np.minimum(inv_other, ninv[k]), inv_other)
    # Empty space beyond (an outline against the background) overrules the centre face's plane.
    under &= inv_other > 0.0
    inv_shown = np.where(outline & ~under, inv_other, inv_c)
    with np.errstate(divide="ignore"):
        behind_ok = z <= np.float32(1.0) / np.where(inv_shown > 0.0, inv_shown, np.float32(1.0)) + bias
    return own | (inv_shown <= 0.0) | behind_ok


def past_outline(c, z, faces, instance_id, outline, depth, ids, px_per_unit, perspective):
    """Which centre points of lines lie past the part's rounded outline and are not drawn at all
    (line.frag's rule where the highlights draw fillets): of a type that lies between faces (not
    OUTLINE_TYPES), over a pixel that shows none of the segment's faces and nothing in front of
    the line (empty space, or a surface behind it). Arguments as for visible()."""
    h, w = depth.shape
    c, z, faces, inst, outline, q, _, bias = _points(c, z, faces, instance_id, outline, px_per_unit, perspective)
    y, x = np.clip(q[:, 1], 0, h - 1), np.clip(q[:, 0], 0, w - 1)
    inv = depth[y, x]
    with np.errstate(divide="ignore"):
        in_front = (inv > 0.0) & (np.float32(1.0) / np.where(inv > 0.0, inv, np.float32(1.0)) <= z + bias)
    return ~outline & ~_own_face(ids, y, x, inst, faces) & ~in_front


def _points(c, z, faces, instance_id, outline, px_per_unit, perspective):
    """The shader's inputs per point as float32 arrays (the instance id and outline flag one
    each), the pixel each lies in, and the world size of a pixel and the depth tolerance there."""
    c = np.asarray(c, np.float32)
    z = np.asarray(z, np.float32)
    faces = np.asarray(faces, np.float32)
    n = len(z)
    inst = np.broadcast_to(np.asarray(instance_id, np.float32), (n,))
    outline = np.broadcast_to(np.asarray(outline, bool), (n,))
    world_per_px = (z if perspective else np.float32(1.0)) / np.float32(px_per_unit)
    bias = np.float32(0.5) * world_per_px + np.float32(REL_BIAS) * np.abs(z)
    return c, z, faces, inst, outline, np.floor(c).astype(np.int64), world_per_px, bias


def _own_face(ids, y, x, inst, faces):
    """Whether pixel (y, x) shows one of the point's own faces, of its instance (el_own_face)."""
    fid = ids[y, x, 1]
    return (ids[y, x, 0] == inst) & (fid > 0.0) & ((fid == faces[:, 0]) | (fid == faces[:, 1]))
