"""The numpy copy of the shading normals a rounded edge's band runs between
(edge_data.shading_normals) that the add-on ran until the library took it over
(native/src/shading_normals.cpp, el_shading_normals): the reference test_pure_rules.py holds the
library to. Not loaded by the add-on."""
import numpy as np

MAX_SHADING_TURN_DEG = 20.0


def shading_normals(d, sel, normals):
    """(N, 2, 6) the two normals a rounded edge's arc runs between at each of its ends (p0, then
    p1), as the library gives them (N1, N2: `normals`, the faces' own), each turned to the normal
    the surface is shaded with on that side there: its triangle's corner normal at that end. A
    smooth-shaded curved face meets a fillet with its interpolated normal, not its flat one (the
    arc from the flat normal left a seam along every rounded edge of a smooth part), and that
    normal changes along the edge (a smooth cylinder's rim: one arc per edge made its bands
    dashes); on flat faces the two are the same. The edge keeps its faces' normals at both ends
    where a corner normal at either end is missing or turned too far, or where taking them would
    turn the arc round."""
    lib = np.array(normals[sel], np.float64).reshape(-1, 2, 3)
    out = np.repeat(lib[:, None], 2, axis=1)                               # (N, end, side, 3)
    if d.corner_nor is None or d.tri_verts is None or not len(sel):
        return out.reshape(-1, 2, 6).astype(np.float32)
    rows = np.arange(len(sel))
    e = (d.positions[d.edges[sel, 1]] - d.positions[d.edges[sel, 0]]).astype(np.float64)
    before = np.einsum("nk,nk->n", np.cross(lib[:, 0], lib[:, 1]), e)
    shaded_ends, kept = [], np.ones(len(sel), bool)
    for end in (0, 1):
        shaded = np.zeros_like(lib)
        for face in (d.face_a[sel], d.face_b[sel]):
            t = np.maximum(face, 0)
            corners = d.corner_nor[t].astype(np.float64)                   # (N, 3, 3)
            at_end = d.tri_verts[t] == d.edges[sel, end][:, None]          # (N, corner)
            nrm = np.einsum("nc,nck->nk", at_end.astype(np.float64), corners)
            length = np.linalg.norm(nrm, axis=1, keepdims=True)
            nrm = np.where((face >= 0)[:, None] & (length > 1e-6), nrm / np.maximum(length, 1e-30), 0.0)
            # Which of N1 / N2 this side is, and its sign: the library may have re-oriented the face.
            d1, d2 = np.einsum("nk,nk->n", nrm, lib[:, 0]), np.einsum("nk,nk->n", nrm, lib[:, 1])
            col = np.where(np.abs(d1) >= np.abs(d2), 0, 1)
            cos = np.einsum("nk,nk->n", nrm, lib[rows, col])
            take = np.abs(cos) >= np.cos(np.radians(MAX_SHADING_TURN_DEG))
            shaded[rows[take], col[take]] = nrm[take] * np.sign(cos[take])[:, None]
        keep = np.all(np.linalg.norm(shaded, axis=2) > 0.5, axis=1)
        # The same turn from N1 to N2 about the edge, so the fold's sign and the arc's order stand.
        after = np.einsum("nk,nk->n", np.cross(shaded[:, 0], shaded[:, 1]), e)
        keep &= (np.sign(before) == np.sign(after)) & (np.abs(after) > 1e-6 * np.linalg.norm(e, axis=1))
        shaded_ends.append(shaded)
        kept &= keep
    # Both ends or neither: one end falling back alone would add a turn Blender never shades.
    for end in (0, 1):
        out[kept, end] = shaded_ends[end][kept]
    return out.reshape(-1, 2, 6).astype(np.float32)
