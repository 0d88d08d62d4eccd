"""Meshes small enough to know the answer, in the add-on's polygon form (radius_clamp.Polygons):
what the band ends', the radius clamp's and the corner patches' tests build."""
import numpy as np

from addon_modules import addon_module

radius_clamp = addon_module("geometry.radius_clamp")


def mesh(verts, polys):
    """positions, edges (first-seen order), polygons, loop triangles (a fan per polygon)."""
    positions = np.asarray(verts, np.float64)
    edge_index, edges, loop_vert, loop_edge, start, total, tris, tri_poly = {}, [], [], [], [], [], [], []
    for p, poly in enumerate(polys):
        start.append(len(loop_vert))
        total.append(len(poly))
        for i, v in enumerate(poly):
            w = poly[(i + 1) % len(poly)]
            key = (min(v, w), max(v, w))
            if key not in edge_index:
                edge_index[key] = len(edges)
                edges.append(key)
            loop_vert.append(v)
            loop_edge.append(edge_index[key])
        for i in range(1, len(poly) - 1):
            tris.append((poly[0], poly[i], poly[i + 1]))
            tri_poly.append(p)
    normal = []
    for p, poly in enumerate(polys):
        ring = positions[poly]
        n = np.cross(ring, np.roll(ring, -1, axis=0)).sum(axis=0)  # Newell's polygon normal
        normal.append(n / np.linalg.norm(n))
    polys_ = radius_clamp.Polygons(np.array(start), np.array(total), np.array(loop_vert), np.array(tri_poly),
                                   np.array(loop_edge), np.array(normal))
    return positions, np.array(edges), polys_, np.array(tris)


def edge_frame(positions, edges, polys, tris):
    """Per edge: N1 / N2 (N1's face runs edges[e, 0] -> edges[e, 1]; each triangle carries its
    polygon's normal, as the add-on gives the library) and its two triangles."""
    n = len(edges)
    normals = np.zeros((n, 6))
    faces = np.full((n, 2), -1)
    for t, (a, b, c) in enumerate(tris):
        nrm = polys.normal[polys.tri_poly[t]]
        for u, v in ((a, b), (b, c), (c, a)):
            key = (min(u, v), max(u, v))
            e = next((i for i, ed in enumerate(map(tuple, edges)) if ed == key), None)
            if e is None:
                continue  # a fan's diagonal
            forward = (u, v) == (edges[e, 0], edges[e, 1])
            normals[e, 0:3 if forward else 3] = nrm if forward else normals[e, 0:3]
            if not forward:
                normals[e, 3:] = nrm
            faces[e, 0 if forward else 1] = t
    return normals.astype(np.float32), faces


def box(cut=False):
    v = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]  # index 4x + 2y + z
    top = [1, 5, 7, 3]
    front = [0, 4, 5, 1]
    if cut:  # a vertex halfway along the top front edge (1 -> 5)
        v.append((0.5, 0.0, 1.0))
        top = [1, 8, 5, 7, 3]
        front = [0, 4, 5, 8, 1]
    polys = [[0, 2, 6, 4], top, front, [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]]
    return mesh(v, polys)
