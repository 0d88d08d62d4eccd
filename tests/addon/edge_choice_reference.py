"""The numpy copy of which edges each material slot rounds (the rule in edge_choice.choose)
that the add-on ran until the library took it over (native/src/edge_rules.cpp, el_edge_rules): the
reference test_pure_rules.py holds the library to. Not loaded by the add-on."""
import numpy as np

MANIFOLD, DEGENERATE = 1 << 2, 1 << 7  # EL_EDGE_MANIFOLD, EL_EDGE_DEGENERATE


def rules(d, shading):
    """(chosen, radius, slot_a, slot_b, pick_a, pick_b, rad_a, rad_b) per edge of edge data `d`."""
    flags, angles, face_a, face_b, tri_slot, sharp, bevel = d.flags, d.angles, d.face_a, d.face_b, d.tri_slot, \
        d.sharp, d.bevel
    ok = ((flags & MANIFOLD) != 0) & ((flags & DEGENERATE) == 0) & (face_b >= 0)
    slot_a = np.where(face_a >= 0, tri_slot[np.maximum(face_a, 0)], 0)
    slot_b = np.where(face_b >= 0, tri_slot[np.maximum(face_b, 0)], 0)

    def picked(slot):
        enabled = np.array([s.enabled and s.radius > 0.0 and s.K > 0.0 for s in shading])[slot]
        by_angle = np.array(['ANGLE' in s.rules for s in shading])[slot] & (angles > np.array([s.angle_deg for s in shading])[slot])
        by_sharp = np.array(['SHARP' in s.rules for s in shading])[slot] & sharp
        by_bevel = np.array(['BEVEL' in s.rules for s in shading])[slot] & (bevel > 0.0)
        radius = np.array([s.radius for s in shading], np.float32)[slot]
        # Picked by bevel weight alone: the weight scales the radius (like the Bevel modifier).
        radius = np.where(by_bevel & ~(by_angle | by_sharp), radius * bevel, radius)
        return enabled, by_angle | by_sharp | by_bevel, radius

    en_a, pick_a, rad_a = picked(slot_a)
    en_b, pick_b, rad_b = picked(slot_b)
    chosen = ok & en_a & en_b & (pick_a | pick_b)
    radius = np.minimum(np.where(pick_a, rad_a, np.inf), np.where(pick_b, rad_b, np.inf)).astype(np.float32)
    return chosen, radius, slot_a, slot_b, pick_a, pick_b, rad_a, rad_b
