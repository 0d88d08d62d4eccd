"""The largest radius an edge's faces allow, as the Bevel modifier's Clamp Overlap: a fillet of
radius r between faces whose normals differ by alpha sets back r * tan(alpha / 2) from the edge
on each face, and two fillets across a face must not overlap, so the setback may be at most half
the face's width across the edge (the farthest of its polygon's corners from the edge's line).
Past that the band stops meaning a fillet: it would run off its faces (docs/highlight_math.md,
"Radius clamp").
"""
from dataclasses import dataclass

import numpy as np

# Pairs (edge, polygon corner) expanded at once: bounds the temporary arrays on dense meshes.
_CHUNK = 1 << 21


@dataclass
class Polygons:
    """What the widths and the band ends (band_ends.py) need of a mesh's polygons."""
    start: np.ndarray        # per polygon: first loop
    total: np.ndarray        # per polygon: loop count
    loop_vert: np.ndarray    # per loop: vertex
    tri_poly: np.ndarray     # per loop triangle: its polygon
    loop_edge: np.ndarray = None  # per loop: the edge from its vertex to the next loop's
    normal: np.ndarray = None     # per polygon: unit normal as the file winds it (zero: no area)
    loop_lookup: tuple = None     # band_ends._loop_lookup's, built on first use


def widths(polys, positions, edges, faces):
    """(N, 2) width of each edge's faces across it; faces (N, 2) are triangle indices (-1: none,
    width 0). edges (N, 2) vertex indices."""
    out = np.zeros(faces.shape, np.float64)
    for side in range(2):
        has = np.flatnonzero(faces[:, side] >= 0)
        poly = polys.tri_poly[faces[has, side]]
        count = polys.total[poly]
        step = max(1, _CHUNK // max(int(count.max(initial=1)), 1))
        for lo in range(0, len(has), step):
            e, p, n = has[lo:lo + step], poly[lo:lo + step], count[lo:lo + step]
            pair = np.repeat(np.arange(len(e)), n)
            corner = np.arange(len(pair)) - np.repeat(np.cumsum(n) - n, n)
            v = positions[polys.loop_vert[polys.start[p][pair] + corner]].astype(np.float64)
            a = positions[edges[e, 0]].astype(np.float64)[pair]
            d = positions[edges[e, 1]].astype(np.float64)[pair] - a
            dist = np.linalg.norm(np.cross(d, v - a), axis=1) / np.maximum(np.linalg.norm(d, axis=1), 1e-30)
            w = np.zeros(len(e))
            np.maximum.at(w, pair, dist)
            out[e, side] = w
    return out


def max_radius(face_widths, angle_deg):
    """Per edge, the largest radius its faces allow (inf where the faces are nearly coplanar)."""
    half = np.radians(np.asarray(angle_deg, np.float64)) / 2.0
    setback = np.tan(np.clip(half, 0.0, np.radians(89.9)))
    narrow = np.min(face_widths, axis=1)
    return np.where(setback > 1e-9, 0.5 * narrow / np.maximum(setback, 1e-9), np.inf)
