"""Real rounded edges for comparisons: circular fillets by Blender's Bevel modifier (used by
bench/ground_truth.py and tests/blender/test_wide_edges.py)."""
import math

import bmesh


def add_fillets(s, radius, segments):
    """A circular fillet of radius r on every edge EdgeLight rounds (faces meeting at more than
    the material's angle). The Bevel modifier's OFFSET is the distance from the edge to where the
    fillet meets each face, r tan(a / 2) for a turn a between the face normals; one modifier has
    one width, so each edge carries it as a bevel weight tan(a / 2) / tan(a_max / 2)."""
    for ob in [o for o in s.objects if o.type == 'MESH']:
        me = ob.data
        threshold = ob.active_material.edgelight.angle if ob.active_material else math.radians(30.0)
        bm = bmesh.new()
        bm.from_mesh(me)
        angles = [e.calc_face_angle(0.0) if len(e.link_faces) == 2 else 0.0 for e in bm.edges]
        bm.free()
        picked = [a > threshold for a in angles]
        a_max = max(a for a, p in zip(angles, picked) if p)
        weights = [math.tan(0.5 * a) / math.tan(0.5 * a_max) if p else 0.0 for a, p in zip(angles, picked)]
        if hasattr(me.edges[0], "bevel_weight"):  # 3.x; 4.0+ keeps it in an edge attribute
            if hasattr(me, "use_customdata_edge_bevel"):
                me.use_customdata_edge_bevel = True
            for e, w in zip(me.edges, weights):
                e.bevel_weight = w
        else:
            attr = me.attributes.get("bevel_weight_edge") or me.attributes.new("bevel_weight_edge", 'FLOAT', 'EDGE')
            attr.data.foreach_set("value", weights)
        for poly in me.polygons:
            poly.use_smooth = True
        if hasattr(me, "use_auto_smooth"):  # before 4.1: custom (hardened) normals need it
            me.use_auto_smooth = True
        mod = ob.modifiers.new("Fillet", 'BEVEL')
        mod.offset_type = 'OFFSET'
        mod.width = radius * math.tan(0.5 * a_max)
        mod.segments = segments
        mod.profile = 0.5
        mod.limit_method = 'WEIGHT'
        mod.harden_normals = True
        mod.miter_outer = 'MITER_ARC'
        # Bevel stops a fillet where it would overlap its neighbours; on a dense mesh (fandisk's
        # creases are chains of short edges between thin triangles) that cut every fillet short of
        # r at a pixel or two, and the reference stopped being rounded at all.
        mod.use_clamp_overlap = False
        # Loop slide (on by default) keeps a fillet's rails on the unbevelled edges at its ends
        # and gives up even widths for it: on a triangulated face (joint, anchor) the diagonals
        # at an end vertex pulled a 90-degree fillet's setbacks from r, r to 0.58 r, 0.39 r.
        # Off, every cross-section meets both faces r tan(a / 2) from the edge.
        mod.loop_slide = False
    s.edgelight.highlights = False  # the fillets are the rounding: the same surface shading only
