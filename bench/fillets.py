"""Real rounded edges for comparisons: circular fillets by Blender's Bevel modifier (the ground
truth's and the fillet tests' references), optionally made exactly circular."""
import math

import bmesh
import bpy
import numpy as np


def add_fillets(s, radius, segments, exact=False, harden=True):
    """A circular fillet of radius r on every edge EdgeLight rounds (faces meeting at more than
    the material's angle). The Bevel modifier's OFFSET is the distance from the edge to where the
    fillet meets each face, r tan(a / 2) for a turn a between the face normals; one modifier has
    one width, so each edge carries it as a bevel weight tan(a / 2) / tan(a_max / 2).

    The modifier's profile 0.5 is a circle only at 90-degree folds (elsewhere a quarter circle
    mapped into the corner's skewed frame: an ellipse's arc); with `exact`, the modifier is
    applied and its fillets' vertices are moved onto the circles (make_circular). Hardened
    normals keep a large flat face flat next to its fillet (averaged with the fillet's first
    segment, its corners would tilt it); on smooth-shaded curved faces Blender 3.4 and 4.1+
    harden differently (a ring's fillet seen along its edges), and harden=False leaves the
    fillets' normals to the mesh's own smoothing."""
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
        axes = fillet_axes(me, picked, radius) if exact else None
        mod = ob.modifiers.new("Fillet", 'BEVEL')
        mod.offset_type = 'OFFSET'
        mod.width = radius * math.tan(0.5 * a_max)
        mod.segments = segments
        mod.profile = 0.5
        mod.limit_method = 'WEIGHT'
        mod.harden_normals = harden
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
        if exact:
            make_circular(ob, mod, axes, radius)
    s.edgelight.highlights = False  # the fillets are the rounding: the same surface shading only


def corner_normals(me):
    """(loops, 3) normals as Blender shades the mesh (the add-on's compat.corner_normals; the
    add-on's module name differs between Blender's legacy add-ons and extensions)."""
    out = np.zeros(len(me.loops) * 3, np.float32)
    if hasattr(me, "corner_normals"):  # 4.1+
        me.corner_normals.foreach_get("vector", out)
    else:
        me.calc_normals_split()
        me.loops.foreach_get("normal", out)
    return out.reshape(-1, 3).astype(float)


def fillet_axes(me, picked, radius):
    """Per rounded edge: the fillet's axis from end to end (a = c - phi r C at each end point c,
    C = (N1 + N2) / (1 + N1.N2), phi = +1 convex, -1 concave: docs/highlight_math.md, "Bands wider
    than a pixel"), the two faces' normals N1, N2, phi, and the normals the faces are shaded with
    at the edge's two ends, S1 and S2 at each (each face's corner normals there, where within 20
    degrees of its own; docs/highlight_math.md, "The arc's ends on smooth-shaded faces")."""
    shading = corner_normals(me)
    corner = {(p.index, me.loops[i].vertex_index): shading[i] for p in me.polygons for i in p.loop_indices}
    bm = bmesh.new()
    bm.from_mesh(me)
    rows = []
    for e, p in zip(bm.edges, picked):
        if not p:
            continue
        faces = list(e.link_faces)
        n = [np.array(f.normal[:], float) for f in faces]
        s = []  # [face][end]
        for f, nf in zip(faces, n):
            ends = [corner[(f.index, v.index)] / max(np.linalg.norm(corner[(f.index, v.index)]), 1e-30)
                    for v in e.verts]
            s.append([m if m @ nf > math.cos(math.radians(20.0)) else nf for m in ends])
        phi = 1.0 if e.is_convex else -1.0
        c = (n[0] + n[1]) / (1.0 + n[0] @ n[1])
        p0, p1 = (np.array(v.co[:], float) for v in e.verts)
        rows.append((p0 - phi * radius * c, p1 - phi * radius * c, n[0], n[1], *s[0], *s[1], phi))
    bm.free()
    keys = ("a0", "a1", "n1", "n2", "s1_0", "s1_1", "s2_0", "s2_1", "phi")
    axes = {k: np.array([r[i] for r in rows]) for i, k in enumerate(keys)}
    axes["dir"] = axes["a1"] - axes["a0"]
    return axes


def slerp(a, b, s):
    """Unit vectors a fraction s of the way from a to b along the great circle (rows)."""
    w = np.arccos(np.clip(np.einsum("ij,ij->i", a, b), -1.0, 1.0))
    sw = np.maximum(np.sin(w), 1e-12)
    k0 = np.where(w > 1e-6, np.sin((1.0 - s) * w) / sw, 1.0 - s)
    k1 = np.where(w > 1e-6, np.sin(s * w) / sw, s)
    out = k0[:, None] * a + k1[:, None] * b
    return out / np.linalg.norm(out, axis=1)[:, None]


def _against_circles(v, axes, alpha):
    """Vertices v (n, 3) against every fillet's circle (n, edges): t along the edge, the foot on
    the axis, the radial vector and its length, and whether the vertex sees the axis from inside
    the arc of normals (m = phi radial / |radial| = x N1 + y N2 with x, y >= 0) within the
    edge's span; p1 = m.N1."""
    a0, d, n1, n2, phi = axes["a0"], axes["dir"], axes["n1"], axes["n2"], axes["phi"]
    t = np.einsum("vej,ej->ve", v[:, None, :] - a0, d) / np.einsum("ej,ej->e", d, d)
    foot = a0 + t[..., None] * d
    radial = v[:, None, :] - foot
    dist = np.maximum(np.linalg.norm(radial, axis=2), 1e-30)
    m = phi[None, :, None] * radial / dist[..., None]
    g = np.cos(alpha)
    p1 = np.einsum("vej,ej->ve", m, n1)
    p2 = np.einsum("vej,ej->ve", m, n2)
    x = (p1 - g * p2) / np.maximum(1.0 - g * g, 1e-12)
    y = (p2 - g * p1) / np.maximum(1.0 - g * g, 1e-12)
    inside = (t >= -1e-6) & (t <= 1.0 + 1e-6) & (x >= -1e-6) & (y >= -1e-6)
    return {"t": t, "foot": foot, "radial": radial, "dist": dist, "p1": p1, "inside": inside}


def make_circular(ob, mod, axes, radius, tol=0.15):
    """Applies the Bevel modifier `mod` with its new faces tagged (an extra slot holding the first
    slot's material: a part of several materials gets its fillets in the first) and moves each
    vertex of those faces that lies on a fillet radially onto the fillet's circle (radius r about
    its axis): within tol r of the circle, seeing the axis from inside the arc of normals N1..N2
    (concave: -N1..-N2), and within the fillet's span along the edge (its rails' ends, plus a
    tenth of r); near several circles, onto the nearest. Those corners of the new faces get the
    shading normal a fraction s of the way from S1 to S2, s the point's angle along the arc and
    S1, S2 the faces' shading normals at its place along the edge (N1, N2 on flat faces: the
    circle's own normal). The original faces, and the patches where fillets meet, keep the
    modifier's positions and normals. Holds on straight fillets; on chains of short edges along a
    curved crease, and where unclamped fillets overlap, it creases the mesh
    (docs/highlight_math.md, "The reference's fillets")."""
    me = ob.data
    if not me.materials:
        me.materials.append(None)
    tag = len(me.materials)
    me.materials.append(me.materials[0])
    mod.material = tag
    dg = bpy.context.evaluated_depsgraph_get()
    ev = ob.evaluated_get(dg)
    normals = corner_normals(ev.data)
    me = bpy.data.meshes.new_from_object(ev, preserve_all_data_layers=True, depsgraph=dg)
    ob.modifiers.remove(mod)
    co = np.zeros(len(me.vertices) * 3)
    me.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3)
    loop_vert = np.zeros(len(me.loops), int)
    me.loops.foreach_get("vertex_index", loop_vert)
    material = np.zeros(len(me.polygons), int)
    me.polygons.foreach_get("material_index", material)
    loop_total = np.zeros(len(me.polygons), int)
    me.polygons.foreach_get("loop_total", loop_total)
    tagged_loop = np.repeat(material == tag, loop_total)  # a new mesh keeps its loops face by face
    on_fillet_face = np.zeros(len(co), bool)
    on_fillet_face[loop_vert[tagged_loop]] = True
    on_own_face = np.zeros(len(co), bool)
    on_own_face[loop_vert[~tagged_loop]] = True
    alpha = np.arccos(np.clip(np.einsum("ej,ej->e", axes["n1"], axes["n2"]), -1.0, 1.0))
    # Each fillet's span along its edge: where its rails (the vertices it shares with the faces,
    # on the circle's ends) lie. Beyond them are the patches where fillets meet, which the
    # circle does not describe (a ball's vertices near a cylinder's end would be pulled onto it).
    t_lo = np.full(len(alpha), np.inf)
    t_hi = np.full(len(alpha), -np.inf)
    rails = np.nonzero(on_fillet_face & on_own_face)[0]
    for k0 in range(0, len(rails), 1024):
        f = _against_circles(co[rails[k0:k0 + 1024]], axes, alpha)
        on = f["inside"] & (np.abs(f["dist"] - radius) <= 1e-3 * radius)
        t_lo = np.minimum(t_lo, np.where(on, f["t"], np.inf).min(axis=0))
        t_hi = np.maximum(t_hi, np.where(on, f["t"], -np.inf).max(axis=0))
    # A tenth of r past the rails' ends: a mitred end's profile leans past them (left out, its
    # vertices twisted the strip's shading into a dark thread), a ball's points there are within
    # half a percent of r of the cylinder.
    margin = 0.1 * radius / np.linalg.norm(axes["dir"], axis=1)
    shade = np.zeros_like(co)
    fit = np.zeros(len(co), bool)
    candidates = np.nonzero(on_fillet_face)[0]
    for k0 in range(0, len(candidates), 1024):
        idx = candidates[k0:k0 + 1024]
        f = _against_circles(co[idx], axes, alpha)
        t = f["t"]
        within = f["inside"] & (t >= t_lo - margin) & (t <= t_hi + margin)
        miss = np.where(within, np.abs(f["dist"] - radius), np.inf)
        best = np.argmin(miss, axis=1)
        rows = np.arange(len(best))
        on = miss[rows, best] <= tol * radius
        onto = f["foot"] + radius * f["radial"] / f["dist"][..., None]  # each circle's nearest point
        r, e = rows[on], best[on]
        k = idx[on]
        co[k] = onto[r, e]
        s = np.arccos(np.clip(f["p1"][r, e], -1.0, 1.0)) / np.maximum(alpha[e], 1e-12)
        along = np.clip(t[r, e], 0.0, 1.0)[:, None]
        side = [axes[f"s{i}_0"][e] * (1.0 - along) + axes[f"s{i}_1"][e] * along for i in (1, 2)]
        side = [x / np.linalg.norm(x, axis=1)[:, None] for x in side]
        shade[k] = slerp(side[0], side[1], np.clip(s, 0.0, 1.0))
        fit[k] = True
    me.vertices.foreach_set("co", co.ravel())
    exact = tagged_loop & fit[loop_vert]
    normals[exact] = shade[loop_vert[exact]]
    if hasattr(me, "use_auto_smooth"):
        me.use_auto_smooth = True
    me.normals_split_custom_set(normals.tolist())
    me.update()
    ob.data = me
