"""A reference for ink-line visibility written independently of EdgeLight's shaders and library:
feature edges found in numpy from Blender's own mesh data, sampled at sub-pixel spacing, each
sample's visibility decided by a ray cast from the camera (scene.ray_cast), then compared with the
rendered ink.

    recall: visible reference samples with ink within 2 px
    stray:  ink pixels farther than 3 px from every visible reference sample, over all ink pixels
"""
import bpy
import numpy as np


def _foreach(collection, prop, dtype, width=1):
    out = np.empty(len(collection) * width, dtype=dtype)
    collection.foreach_get(prop, out)
    return out.reshape(-1, width) if width > 1 else out


def feature_edges(ob, eye, crease_deg, orthographic_dir=None):
    """World-space (a, b, polygons, kind) of the object's silhouettes, creases and borders, by
    the add-on's definitions: a silhouette joins a face turned to the eye and one turned away, a
    crease's face normals differ by more than crease_deg, a border has one face."""
    me = ob.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh()
    m = np.array(ob.matrix_world, np.float64)
    co = _foreach(me.vertices, "co", np.float64, 3) @ m[:3, :3].T + m[:3, 3]
    edges = _foreach(me.edges, "vertices", np.int64, 2)
    loop_edge = _foreach(me.loops, "edge_index", np.int64)
    loop_vert = _foreach(me.loops, "vertex_index", np.int64)
    start = _foreach(me.polygons, "loop_start", np.int64)
    total = _foreach(me.polygons, "loop_total", np.int64)
    poly_of_loop = np.repeat(np.arange(len(start)), total)
    # World normals and a point of each polygon (Newell's method on the world positions).
    nxt = np.arange(len(loop_vert)) + 1
    ends = start[poly_of_loop] + total[poly_of_loop]
    nxt = np.where(nxt < ends, nxt, start[poly_of_loop])
    p, q = co[loop_vert], co[loop_vert[nxt]]
    cross = np.cross(p, q)
    normal = np.zeros((len(start), 3))
    np.add.at(normal, poly_of_loop, cross)
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-30)
    point = co[loop_vert[start]]
    ob.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh_clear()
    # Faces of each edge.
    faces_of = [[] for _ in range(len(edges))]
    for loop, e in enumerate(loop_edge):
        faces_of[e].append(poly_of_loop[loop])
    if orthographic_dir is None:
        facing = np.einsum("ij,ij->i", normal, np.asarray(eye)[None] - point) > 0.0
    else:
        facing = normal @ -np.asarray(orthographic_dir) > 0.0
    out = []
    cos_crease = np.cos(np.radians(crease_deg))
    for e, faces in enumerate(faces_of):
        a, b = co[edges[e, 0]], co[edges[e, 1]]
        if len(faces) == 1:
            out.append((a, b, tuple(faces), "border"))
        elif len(faces) == 2:
            f, g = faces
            if facing[f] != facing[g]:
                out.append((a, b, tuple(faces), "silhouette"))
            elif np.dot(normal[f], normal[g]) < cos_crease:
                out.append((a, b, tuple(faces), "crease"))
    return out


def project(rec, points):
    cam = rec["camera"]
    p = np.c_[np.asarray(points, np.float64), np.ones(len(points))]
    clip = (cam.projection @ cam.view @ p.T).T
    return (clip[:, :2] / clip[:, 3:4] * 0.5 + 0.5) * np.array([cam.width, cam.height])


def visible_samples(rec, ob, edges, spacing_px=0.5):
    """Pixel positions and line types of the edge samples a ray from the camera reaches."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    scene = bpy.context.scene
    cam = rec["camera"]
    eye = np.asarray(cam.eye, np.float64)
    xy_out, kinds = [], []
    for a, b, faces, kind in edges:
        sa, sb = project(rec, [a, b])
        n = max(2, int(np.ceil(np.linalg.norm(sb - sa) / spacing_px)) + 1)
        # Sample inside the segment: its ends are shared with other features.
        ts = (np.arange(n) + 0.5) / n
        for t in ts:
            x = a + t * (b - a)
            origin = eye if not cam.orthographic else x - np.asarray(cam.view_dir) * 1e4
            d = x - origin
            dist = np.linalg.norm(d)
            d /= dist
            hit, loc, _, index, hit_ob, _ = scene.ray_cast(depsgraph, tuple(origin), tuple(d), distance=dist * (1 + 1e-6))
            # Visible: nothing hit before the sample (to a relative tolerance), or what was hit
            # is one of the edge's own faces.
            if hit and not (hit_ob.original == ob and index in faces):
                if np.linalg.norm(np.asarray(loc) - origin) < dist * (1.0 - 1e-5):
                    continue
            xy_out.append(project(rec, [x])[0])
            kinds.append(kind)
    return np.array(xy_out).reshape(-1, 2), np.array(kinds)


def _near(mask, radius):
    """Pixels within `radius` (Chebyshev) of a true pixel of mask."""
    out = mask.copy()
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            out |= np.roll(np.roll(mask, dy, 0), dx, 1)
    return out


def compare(rec, samples, kinds, ink_threshold=0.25):
    """{"recall": {type: fraction}, "stray": fraction, "ink": pixels, "samples": count}."""
    ink = np.asarray(rec["lines"])[..., 3] > ink_threshold
    h, w = ink.shape
    # Samples just outside the frame still justify ink at its edge: a margin of 4 px.
    m = 4
    px = np.floor(samples).astype(int)
    keep = (px[:, 0] >= -m) & (px[:, 0] < w + m) & (px[:, 1] >= -m) & (px[:, 1] < h + m)
    ref = np.zeros((h + 2 * m, w + 2 * m), bool)
    ref[px[keep, 1] + m, px[keep, 0] + m] = True
    inside = (px[:, 0] >= 0) & (px[:, 0] < w) & (px[:, 1] >= 0) & (px[:, 1] < h)
    px, kinds = px[inside], kinds[inside]
    inked_near = _near(ink, 2)
    recall = {}
    for kind in np.unique(kinds):
        sel = kinds == kind
        recall[str(kind)] = float(inked_near[px[sel, 1], px[sel, 0]].mean())
    stray = ink & ~_near(ref, 3)[m:m + h, m:m + w]
    return {"recall": recall, "stray": float(stray.sum()) / max(int(ink.sum()), 1),
            "stray_pixels": int(stray.sum()), "ink": int(ink.sum()), "samples": int(len(px))}
