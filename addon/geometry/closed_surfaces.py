"""Whether a mesh's surface is closed, so that its back faces never show while the eye is
outside it. A closed surface's inside is hidden from any eye outside the solid by the faces it
looks through first; its back faces show only through the rounded outline's strips, which leave
out front faces near a silhouette (docs/highlight_math.md, "The fillet's outline"), where the
part's inside would show instead of what lies behind it. No bpy: plain-Python tests import it."""
import numpy as np


def oriented_triangles(tri_verts, flips):
    """(T, 3) each triangle's vertices in the winding the library oriented it to (its
    component's, outward where the component is closed: el_mesh_create)."""
    tv = np.asarray(tri_verts, np.int64)
    flipped = np.asarray(flips, bool)
    return np.where(flipped[:, None], tv[:, [0, 2, 1]], tv)


def is_closed(tri_verts, flips):
    """Whether every side of every triangle, in the oriented winding, meets exactly one other
    triangle's side running the other way: a closed, consistently oriented surface (each of its
    components closed, and so wound outwards by the library)."""
    tv = oriented_triangles(tri_verts, flips)
    if not len(tv):
        return False
    a, b = tv.reshape(-1), np.roll(tv, -1, axis=1).reshape(-1)
    if np.any(a == b):
        return False
    n = np.int64(max(int(tv.max()) + 1, 1))
    ahead, back = np.sort(a * n + b), np.sort(b * n + a)
    return bool(np.all(ahead[1:] != ahead[:-1]) and np.array_equal(ahead, back))


def bounds(positions):
    """(2, 3) the object-space bounding box of points (N, 3)."""
    p = np.asarray(positions, np.float64)
    return np.stack([p.min(axis=0), p.max(axis=0)])


def box_corners(boxes):
    """(..., 8, 3) corners of (..., 2, 3) boxes (low corner, high corner)."""
    pick = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], bool)  # (8, 3): hi where set
    return np.where(pick, boxes[..., 1:2, :], boxes[..., 0:1, :])


def hidden_back_faces(box, matrix, clip_matrix):
    """Whether an instance's back faces are hidden (to be culled): its bounding box (object
    space) under `matrix` lies wholly in front of the camera's near plane (clip_matrix: the
    camera's projection times its view), so the eye, and the near plane that would cut the
    surface open, lie outside the solid. Boxes (..., 2, 3) and matrices (..., 4, 4) stacked:
    one answer per instance, all at once."""
    corners = box_corners(np.asarray(box, np.float64))                                    # (..., 8, 3)
    corners = np.concatenate([corners, np.ones(corners.shape[:-1] + (1,))], axis=-1)
    full = np.asarray(clip_matrix, np.float64) @ np.asarray(matrix, np.float64)
    clip = np.einsum("...ck,...jk->...cj", corners, full)
    front = (clip[..., 2] > -clip[..., 3] + 1e-6 * np.abs(clip[..., 3])) & (clip[..., 3] > 0.0)
    return np.all(front, axis=-1)
