"""The numpy copy of the surface pass's outline lists for wide faces (rounded_outline._fans) that
the add-on ran until the library took it over (native/src/outline_fans.cpp, el_outline_fans):
the reference test_rounded_outline.py holds the library to. Not loaded by the add-on."""
import numpy as np


def fans(tri_verts, tri_normal, order, item_verts, item_normals, per, ends=None, smooth_fold_deg=30.0):
    """(T, per) float32 lists, in batch order, of the items at each triangle's corners, flat
    with one of the item's faces (or the triangle's own side), own sides first: the strips and
    corners of a mesh whose faces are wider than its strips cross no other triangles. Grouped by
    triangle as generated, so nothing is sorted. item_verts (N, k): each item's vertices
    (an edge's two ends, a corner's one); `ends` (N, 2) an edge's ends, to tell its own sides."""
    iv = item_verts.reshape(-1)
    ii = np.repeat(np.arange(len(item_verts)), item_verts.shape[1])
    ok = iv >= 0
    iv, ii = iv[ok], ii[ok]
    by_v = np.argsort(iv, kind="stable")
    first = np.searchsorted(iv[by_v], np.arange(int(tri_verts.max()) + 2))
    tv = tri_verts[order]                                    # (T, 3) in batch order
    count = (first[tv + 1] - first[tv]).reshape(-1)          # items at each (triangle, corner)
    pair_tc = np.repeat(np.arange(tv.size), count)
    offs = np.arange(len(pair_tc)) - np.repeat(np.cumsum(count) - count, count)
    item = ii[by_v[first[tv.reshape(-1)][pair_tc] + offs]]
    t, c = pair_tc // 3, pair_tc % 3
    keep = np.ones(len(item), bool)
    own = np.zeros(len(item), bool)
    if ends is not None:
        v = tv[t, c]
        other = np.where(ends[item, 0] == v, ends[item, 1], ends[item, 0])
        at = np.stack([tv[t, k] == other for k in range(3)], axis=1)
        own = at.any(axis=1)
        # An own side is reached from both its ends: kept from the first.
        keep = ~(own & (np.argmax(at, axis=1) < c))
    cos_max = np.float32(np.cos(np.radians(smooth_fold_deg)))
    flat = np.abs(np.einsum("nj,nkj->nk", tri_normal[order[t]], item_normals[item])).max(axis=1) >= cos_max
    keep &= own | flat
    t, item, own = t[keep], item[keep], own[keep]
    # Slots: own sides first, then the others in the order met; pairs come grouped by triangle.
    out = np.zeros((len(tv), per), np.float32)
    for mask, base in ((own, None), (~own, np.bincount(t[own], minlength=len(tv)))):
        tm = t[mask]
        if not len(tm):
            continue
        starts = np.r_[True, tm[1:] != tm[:-1]]
        idx = np.arange(len(tm))
        slot = idx - np.maximum.accumulate(np.where(starts, idx, 0))
        if base is not None:
            slot = slot + base[tm]
        fit = slot < per
        out[tm[fit], slot[fit]] = item[mask][fit] + 1
    return out
