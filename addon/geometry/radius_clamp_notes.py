"""What the radius clamp did to each material's edges, for the material panel's note: how many
of the edges a material rounds take a smaller radius than its own because their faces allow no
more (radius_clamp.py). edge_choice.choose counts them whenever it picks a geometry's rounded
edges and returns the counts with its choice (MeshExtract.clamps); host/clamp_notes.py keeps
what the panel shows. Nothing is written to the material or saved. No bpy: plain-Python tests
import it.
"""
import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class RadiusClamps:
    material: str          # the material's full name
    radius: float          # its Radius when counted
    rounded: int           # edges of the geometry the material rounds (on either face)
    clamped: int           # of those, edges its faces allow less than that radius
    smallest: float        # the smallest radius an edge was clamped to (inf: none)


def count(shading, sides, limit):
    """The counts of one geometry, a RadiusClamps for every material of `shading` (slot ->
    Shading), by name. sides: ((slot, picked, radius) of the rounded edges' first faces, the
    same of their second), arrays over the rounded edges, `picked` whether that face's material
    rounds the edge and `radius` the radius it asks; limit: each rounded edge's largest radius
    (radius_clamp). An edge counts once for each material of its two faces."""
    names = sorted({s.material for s in shading if s.material})
    if not names:
        return ()
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
    radius_of = {s.material: s.radius for s in shading if s.material}
    return tuple(RadiusClamps(name, radius_of[name], int(rounded[i]), int(clamped[i]), float(smallest[i]))
                 for i, name in enumerate(names))


def total(counts, material, radius):
    """(edges clamped, edges rounded, smallest clamped radius) of `material` (its full name) at
    `radius` over `counts` (RadiusClamps of any geometries); None when none counted it at that
    radius."""
    mine = [c for c in counts if c.material == material and c.radius == radius]
    if not mine:
        return None
    return (sum(c.clamped for c in mine), sum(c.rounded for c in mine), min(c.smallest for c in mine))
