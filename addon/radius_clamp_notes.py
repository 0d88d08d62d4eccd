"""What the material panel says about the radius clamp (ui.py, through materials.radius_clamps):
per material, how many of the edges it rounds take a smaller radius than its own because their
faces allow no more (radius_clamp.py). edge_choice.choose_edges records each geometry's counts
whenever it picks that geometry's rounded edges (extraction, or a material change in the
viewport). Nothing is written to the material or saved. No bpy: plain-Python tests import it.
"""
import math
import weakref
from dataclasses import dataclass

import numpy as np

# material name -> {id(geometry's edge data): RadiusClamps}
_clamps = {}


@dataclass(frozen=True)
class RadiusClamps:
    radius: float          # the material's Radius when counted
    rounded: int           # edges of the geometry the material rounds (on either face)
    clamped: int           # of those, edges its faces allow less than that radius
    smallest: float        # the smallest radius an edge was clamped to (inf: none)
    geometry: object       # weakref to the geometry's edge data: alive while it is drawn


def record_radius_clamps(geometry, shading, sides, limit):
    """Records one geometry's counts for every material of `shading` (slot -> Shading).
    sides: ((slot, picked, radius) of the rounded edges' first faces, the same of their second),
    arrays over the rounded edges, `picked` whether that face's material rounds the edge and
    `radius` the radius it asks; limit: each rounded edge's largest radius (radius_clamp).
    An edge counts once for each material of its two faces."""
    for name in list(_clamps):  # geometries freed since the last call (a re-extracted mesh)
        entries = _clamps[name]
        for key in [k for k, e in entries.items() if e.geometry() is None]:
            del entries[key]
        if not entries:
            del _clamps[name]
    names = sorted({s.material for s in shading if s.material})
    if not names:
        return
    index = {name: i for i, name in enumerate(names)}
    of_slot = np.array([index.get(s.material, -1) for s in shading])
    (slot_a, pick_a, rad_a), (slot_b, pick_b, rad_b) = sides
    limit = np.asarray(limit, np.float64)
    mat_a, mat_b = of_slot[np.asarray(slot_a)], of_slot[np.asarray(slot_b)]
    rad_a = np.where(pick_a, np.asarray(rad_a, np.float64), math.inf)
    rad_b = np.where(pick_b, np.asarray(rad_b, np.float64), math.inf)
    # Clamped: the edge's radius (the smaller one its faces ask) is past the limit; it counts
    # for the faces' materials that asked more than the limit.
    cut = np.minimum(rad_a, rad_b) > limit
    over_a, over_b = cut & (rad_a > limit), cut & (rad_b > limit)
    second = mat_b != mat_a  # the second face's material is another one
    rounded, clamped, smallest = np.zeros(len(names), int), np.zeros(len(names), int), np.full(len(names), math.inf)
    for mat, touch, over in ((mat_a, np.ones(len(limit), bool), over_a | (over_b & ~second)),
                             (mat_b, second, over_b & second)):
        has = mat >= 0
        rounded += np.bincount(mat[has & touch], minlength=len(names))
        clamped += np.bincount(mat[has & over], minlength=len(names))
        np.minimum.at(smallest, mat[has & over], limit[has & over])
    ref = weakref.ref(geometry)
    radius_of = {s.material: s.radius for s in shading if s.material}
    for i, name in enumerate(names):
        _clamps.setdefault(name, {})[id(geometry)] = RadiusClamps(radius_of[name], int(rounded[i]), int(clamped[i]),
                                                                  float(smallest[i]), ref)


def radius_clamps(material):
    """(edges clamped, edges rounded, smallest clamped radius) of `material` over the geometries
    EdgeLight holds (the Rendered viewport's), else over those of the last render; None when
    nothing was counted at the material's current radius."""
    entries = list(_clamps.get(material.name_full, {}).values())
    live = [e for e in entries if e.geometry() is not None]
    radius = float(material.edgelight.radius)
    entries = [e for e in (live or entries) if e.radius == radius]
    if not entries:
        return None
    return (sum(e.clamped for e in entries), sum(e.rounded for e in entries), min(e.smallest for e in entries))
