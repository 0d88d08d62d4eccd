"""The line pass's visibility rule on the CPU (numpy), for output that must agree with the
rendered lines (the SVG output). A line-for-line port of the visibility block of
shaders/line.frag.glsl (docs/lines.md, "Visibility"); test_svg_output.py pins the two together.
"""
import numpy as np

from .passes.line_pass import OUTLINE_TYPES, REL_BIAS

__all__ = ("visible", "OUTLINE_TYPES")


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
    c = np.asarray(c, np.float32)
    z = np.asarray(z, np.float32)
    faces = np.asarray(faces, np.float32)
    n = len(z)
    inst = np.broadcast_to(np.asarray(instance_id, np.float32), (n,))
    outline = np.broadcast_to(np.asarray(outline, bool), (n,))
    q = np.floor(c).astype(np.int64)
    yc, xc = np.clip(q[:, 1], 0, h - 1), np.clip(q[:, 0], 0, w - 1)
    id_c = ids[yc, xc, :2]
    inv_c = depth[yc, xc]
    # The farthest of the 3x3 pixels that show something other than the centre pixel's face.
    inv_other = inv_c.copy()
    own = np.zeros(n, bool)
    for dy in (-1, 0, 1):
        y = np.clip(q[:, 1] + dy, 0, h - 1)
        for dx in (-1, 0, 1):
            x = np.clip(q[:, 0] + dx, 0, w - 1)
            fid = ids[y, x, 1]
            own |= (ids[y, x, 0] == inst) & (fid > 0.0) & ((fid == faces[:, 0]) | (fid == faces[:, 1]))
            other = np.any(ids[y, x, :2] != id_c, axis=1)
            inv_other = np.where(other, np.minimum(inv_other, depth[y, x]), inv_other)
    inv_shown = np.where(outline, inv_other, inv_c)
    world_per_px = (z if perspective else np.float32(1.0)) / np.float32(px_per_unit)
    bias = np.float32(0.5) * world_per_px + np.float32(REL_BIAS) * np.abs(z)
    with np.errstate(divide="ignore"):
        behind_ok = z <= np.float32(1.0) / np.where(inv_shown > 0.0, inv_shown, np.float32(1.0)) + bias
    return own | (inv_shown <= 0.0) | behind_ok
