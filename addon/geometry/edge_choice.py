"""Which edges each material rounds (the material's Rounded Edges settings, materials.Shading),
from one mesh's edge data (edge_data.EdgeData): the rule, in one function. No bpy: plain-Python
tests import it.
"""
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..bridge import native
from . import band_ends, corner_patches, radius_clamp, radius_clamp_notes
from .edge_data import mean_and_turn, shading_normals, surface_ids


@dataclass
class EdgeSet:
    """Chosen edges of one material slot, object space."""
    p0: np.ndarray
    p1: np.ndarray
    n1: np.ndarray
    n2: np.ndarray
    radius: np.ndarray
    faces: np.ndarray = None           # (N, 2) float32 surface ids of its two faces (band visibility)
    ends: np.ndarray = None            # (N, 4) float32 where its band ends on each face (band_ends.py)
    corners: object = None             # corner_patches.Corners where three of its edges meet (the first's slot)
    turn: np.ndarray = None            # (N, 6) float32 how N1, N2 change along it (edge_data.mean_and_turn)
    verts: np.ndarray = None           # (N, 2) its vertices (the mesh's), p0's then p1's

    def __len__(self):
        return len(self.radius)


class Choice(NamedTuple):
    """What choose returns: the chosen edges by slot, and what the radius clamp did to each
    material's (radius_clamp_notes.RadiusClamps, for the material panel's note)."""
    edges: dict
    clamps: tuple


def same_edges(a, b):
    """Whether two choices' edges (Choice.edges) draw the same edges (slots, counts, radii, positions)."""
    if a.keys() != b.keys():
        return False
    return all(len(a[k]) == len(b[k]) and np.array_equal(a[k].radius, b[k].radius) and np.array_equal(a[k].p0, b[k].p0)
               for k in a)


def choice_key(shading):
    """What choose reads of the slots' shading (the material's name for the radius clamp
    notes): equal keys choose the same edges and record the same notes."""
    return tuple((s.enabled, s.radius, s.K, s.rules, s.angle_deg, s.material) for s in shading)


def choose(d, shading):
    """Edges each material rounds (a Choice). An edge between two materials is rounded when both
    enable rounding and either one's rule picks it; it takes the smaller radius and the shading
    of the material of its first face."""
    flags, angles, normals, edges, positions = d.flags, d.angles, d.normals, d.edges, d.positions
    face_a, face_b, tri_slot, sharp = d.face_a, d.face_b, d.tri_slot, d.sharp
    # The rule (the library's el_edge_rules): rounded where manifold with two faces, both faces'
    # materials round edges, and either one's rules pick it; the smaller radius of those that do.
    bits = {'ANGLE': native.RULE_ANGLE, 'SHARP': native.RULE_SHARP, 'BEVEL': native.RULE_BEVEL}
    r = native.edge_rules(flags, angles, face_a, face_b, sharp, d.bevel, tri_slot,
                          [(s.enabled, s.radius, s.K, sum(bits[b] for b in s.rules), s.angle_deg) for s in shading])
    chosen, radius = r["chosen"], r["radius"]
    slot_a, slot_b, pick_a, pick_b, rad_a, rad_b = (r[k].astype(np.int64) if k.startswith("slot") else r[k]
                                                    for k in ("slot_a", "slot_b", "pick_a", "pick_b", "rad_a", "rad_b"))
    ok = ((flags & native.EDGE_MANIFOLD) != 0) & ((flags & native.EDGE_DEGENERATE) == 0) & (face_b >= 0)
    # No larger than the faces allow (Clamp Overlap): past that a band is no fillet's image.
    picked_edges = np.flatnonzero(chosen)
    # A face is its smooth patch, up to the next rounded, sharp or open edge: a fillet runs on
    # across the facets of a triangulated curved surface, and ends where the patch does.
    stop = ~ok | chosen | sharp | (angles > radius_clamp.SMOOTH_FOLD_DEG)
    if d.polygons is not None and len(picked_edges):
        # What the largest radius either side asks needs (the panel's note compares each side's).
        asked = np.maximum(np.where(pick_a, rad_a, 0.0), np.where(pick_b, rad_b, 0.0))[picked_edges]
        need = 2.0 * asked * radius_clamp.setback(angles[picked_edges])
        # Polygons' widths only where a cheap lower bound of them leaves the clamp in doubt.
        polys_of = d.edge_polygons()
        widths = radius_clamp.width_bounds(d.polygons, positions, edges[picked_edges], polys_of[picked_edges])
        doubt = np.flatnonzero(widths.min(axis=1) < need)
        widths[doubt] = d.widths_of(picked_edges[doubt])
        widths = radius_clamp.across_patches(d.polygons, positions, edges, polys_of, stop, picked_edges, widths, need)
        limit = radius_clamp.max_radius(widths, angles[picked_edges])
        radius[picked_edges] = np.minimum(radius[picked_edges], limit).astype(np.float32)
    else:
        limit = np.full(len(picked_edges), np.inf)
    # For the material panel's note (radius_clamp_notes): nothing is written to the materials.
    e = picked_edges
    clamps = radius_clamp_notes.count(shading, ((slot_a[e], pick_a[e], rad_a[e]), (slot_b[e], pick_b[e], rad_b[e])), limit)
    convex = (flags & native.EDGE_CONVEX) != 0
    corners = corner_patches.find(edges, positions, normals, convex, chosen, radius, stop)
    # A patch takes one material's shading: where the three bands have different ones, their
    # mitres stand.
    one_slot = np.all(slot_a[corners.edges] == slot_a[corners.edges[:, :1]], axis=1)
    corners = corners.subset(np.flatnonzero(one_slot))
    corners.faces = surface_ids(d, np.concatenate([face_a[corners.edges], face_b[corners.edges]], axis=1))
    corner_slot = slot_a[corners.edges[:, 0]]
    out = {}
    for slot in np.unique(slot_a[chosen]):
        sel = np.flatnonzero(chosen & (slot_a == slot))
        faces = np.stack([face_a[sel], face_b[sel]], axis=1)
        shaded, turn = mean_and_turn(shading_normals(d, sel, normals))
        out[int(slot)] = EdgeSet(positions[edges[sel, 0]], positions[edges[sel, 1]],
                                 np.ascontiguousarray(shaded[:, :3]), np.ascontiguousarray(shaded[:, 3:]),
                                 radius[sel], surface_ids(d, faces),
                                 band_ends.end_angles(d.polygons, positions, normals, edges, sel, faces, chosen,
                                                      ~stop, d.edge_polygons()),
                                 corners.subset(np.flatnonzero(corner_slot == slot)), turn, edges[sel])
    return Choice(out, clamps)
