"""Meshes small enough to know the answer, in the add-on's polygon form (radius_clamp.Polygons):
what the band ends' and the radius clamp's tests build."""
import numpy as np

from addon_modules import addon_module

radius_clamp = addon_module("radius_clamp")


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
