"""Ink lines as vector polylines in pixel coordinates of the render (for the SVG output).

Each segment is projected as the line pass's vertex shader does (shaders/line.vert.glsl),
sampled every SAMPLE_PX pixels, and each sample's visibility decided by the line pass's rule
(line_visibility.py). Runs of equal visibility and width are chained into the fewest polylines
(through shared ends, straight on through junctions, across gaps the round caps already ink),
and each polyline is simplified (Douglas-Peucker) to TOLERANCE_PX (which also merges collinear
runs: their inner points lie on the line).
"""
from dataclasses import dataclass, field

import numpy as np

from . import line_visibility

SAMPLE_PX = 1.0      # visibility is decided once per this many pixels along a segment
TOLERANCE_PX = 0.25  # Douglas-Peucker: no dropped point is farther than this from the polyline
WIDTH_STEP_PX = 0.25  # tapered and scene-unit widths are stepped to multiples of this
_NEAR = 1e-6         # clip w below which a point is behind the eye (as the vertex shader)


@dataclass
class Stroke:
    """Polylines of one line type drawn alike: visible or hidden, one width (pixels)."""
    hidden: bool
    width: float
    polylines: list = field(default_factory=list)   # (k, 2) arrays, x right, y down


def project(seg, matrix, camera):
    """Screen ends (N, 2) x2 (y up), view depths (N,) x2 and the kept parameter range [t0, t1]
    of each segment, clipped to the part in front of the eye; `keep` marks those with one."""
    m = np.asarray(matrix, np.float64)
    vp = np.asarray(camera.view, np.float64) @ m
    pr = np.asarray(camera.projection, np.float64)
    ends = []
    for p in (seg.p0, seg.p1):
        h = np.c_[np.asarray(p, np.float64), np.ones(len(p))]
        v = h @ vp.T
        ends.append((v, v @ pr.T))
    (v0, c0), (v1, c1) = ends
    w0, w1 = c0[:, 3], c1[:, 3]
    keep = (w0 >= _NEAR) | (w1 >= _NEAR)
    with np.errstate(divide="ignore", invalid="ignore"):
        tc = (_NEAR - w0) / (w1 - w0)
    t0 = np.where(w0 < _NEAR, tc, 0.0)
    t1 = np.where(w1 < _NEAR, tc, 1.0)
    size = np.array([camera.width, camera.height], np.float64)

    def at(t):
        c = c0 + t[:, None] * (c1 - c0)
        z = -(v0[:, 2] + t * (v1[:, 2] - v0[:, 2]))
        with np.errstate(divide="ignore", invalid="ignore"):
            return (c[:, :2] / c[:, 3:4] * 0.5 + 0.5) * size, z
    (sa, za), (sb, zb) = at(t0), at(t1)
    return sa, sb, za, zb, t0, t1, keep


def half_widths(style, z, taper_t, camera):
    """The vertex shader's el_line_half_width, per end."""
    w = np.full(len(z), style.width, np.float64)
    if style.scene_units:
        ppu = camera.px_per_unit / np.maximum(z, 1e-20) if not camera.orthographic else camera.px_per_unit
        w = np.maximum(w * ppu, style.min_pixels)
    f = np.clip(taper_t / style.taper, 0.0, 1.0) if style.taper > 0.0 else 1.0
    return 0.5 * w * f


def sample_runs(seg, matrix, instance_id, kind, style, camera, depth, ids, rounded=False):
    """Runs of equal visibility and stepped width along each segment: (a, b, hidden, width)
    arrays, a / b the run's ends in pixels (y up). `rounded`: the fillets' outline was drawn
    (frame.LineRecord.rounded)."""
    sa, sb, za, zb, t0, t1, keep = project(seg, matrix, camera)
    taper = np.asarray(seg.taper, np.float64)
    ta = taper[:, 0] + t0 * (taper[:, 1] - taper[:, 0])
    tb = taper[:, 0] + t1 * (taper[:, 1] - taper[:, 0])
    ra, rb = half_widths(style, za, ta, camera), half_widths(style, zb, tb, camera)
    keep &= np.all(np.isfinite(sa), 1) & np.all(np.isfinite(sb), 1)
    # Only what can reach the image.
    size = np.array([camera.width, camera.height])
    reach = np.maximum(ra, rb)[:, None] + 1.0
    keep &= np.all(np.maximum(sa, sb) >= -reach, 1) & np.all(np.minimum(sa, sb) <= size + reach, 1)
    idx = np.flatnonzero(keep)
    empty = np.zeros((0, 2)), np.zeros((0, 2)), np.zeros(0, bool), np.zeros(0)
    if len(idx) == 0:
        return empty
    sa, sb, za, zb, ra, rb = sa[idx], sb[idx], za[idx], zb[idx], ra[idx], rb[idx]
    faces = (seg.faces if seg.faces is not None else np.zeros((len(seg), 2), np.float32))[idx]
    n = np.maximum(1, np.ceil(np.linalg.norm(sb - sa, axis=1) / SAMPLE_PX)).astype(np.int64)
    s = np.repeat(np.arange(len(idx)), n)                       # segment of each piece
    k = np.arange(len(s)) - np.repeat(np.cumsum(n) - n, n)       # piece within its segment
    nn = n[s].astype(np.float64)
    t = (k + 0.5) / nn                                           # the piece's centre
    c = sa[s] + t[:, None] * (sb[s] - sa[s])
    if camera.orthographic:
        z = za[s] + t * (zb[s] - za[s])
    else:
        z = 1.0 / (1.0 / za[s] + t * (1.0 / zb[s] - 1.0 / za[s]))
    vis = line_visibility.visible(c, z, faces[s], instance_id, kind in line_visibility.OUTLINE_TYPES,
                                  depth, ids, camera.px_per_unit, not camera.orthographic)
    width = np.round(2.0 * (ra[s] + t * (rb[s] - ra[s])) / WIDTH_STEP_PX) * WIDTH_STEP_PX
    # Outside the camera's clip range a line is not drawn at all, nor is a crease past the
    # part's rounded outline (line_visibility.past_outline).
    clipped = line_visibility.clipped(z, camera.projection)
    if rounded:
        clipped |= line_visibility.past_outline(c, z, faces[s], instance_id, kind in line_visibility.OUTLINE_TYPES,
                                                depth, ids, camera.px_per_unit, not camera.orthographic)
    # A run starts where the segment, the visibility, the width or the clipping changes.
    start = np.ones(len(s), bool)
    start[1:] = ((s[1:] != s[:-1]) | (vis[1:] != vis[:-1]) | (width[1:] != width[:-1])
                 | (clipped[1:] != clipped[:-1]))
    first = np.flatnonzero(start)
    last = np.r_[first[1:], len(s)] - 1
    inside = ~clipped[first]  # outside the camera's clip range a line is not drawn at all
    first, last = first[inside], last[inside]
    rs = s[first]
    a = sa[rs] + (k[first] / nn[first])[:, None] * (sb[rs] - sa[rs])
    b = sa[rs] + ((k[last] + 1) / nn[last])[:, None] * (sb[rs] - sa[rs])
    return a, b, ~vis[first], width[first]


def _weld(pts, join):
    """Node of each point: points equal to 1/1024 px are one node, and with `join` > 0 so are
    points closer than `join` (grid cells of that size: close pairs are in the same or a
    neighbouring cell; their nodes joined by label propagation). Node numbers are labels, not
    consecutive."""
    key = np.round(pts * 1024.0).astype(np.int64)
    _, node = np.unique(key, axis=0, return_inverse=True)
    node = node.reshape(-1)
    if join <= 0.0 or len(pts) < 2:
        return node
    cell = np.floor(pts / join).astype(np.int64)
    cell -= cell.min(axis=0)
    width = int(cell[:, 1].max()) + 3
    code = (cell[:, 0] + 1) * width + (cell[:, 1] + 1)
    order = np.argsort(code, kind="stable")
    sorted_code = code[order]
    pairs_i, pairs_j = [], []
    # Each pair once: the same cell (i < j), and four of the eight neighbours.
    for dx, dy in ((0, 0), (1, -1), (1, 0), (1, 1), (0, 1)):
        target = code + dx * width + dy
        lo = np.searchsorted(sorted_code, target, side="left")
        hi = np.searchsorted(sorted_code, target, side="right")
        count = hi - lo
        i = np.repeat(np.arange(len(pts)), count)
        j = order[np.repeat(lo, count) + (np.arange(len(i)) - np.repeat(np.cumsum(count) - count, count))]
        keep = (i < j) if (dx, dy) == (0, 0) else np.ones(len(i), bool)
        i, j = i[keep], j[keep]
        close = np.hypot(*(pts[i] - pts[j]).T) < join
        pairs_i.append(node[i[close]])
        pairs_j.append(node[j[close]])
    u, v = np.concatenate(pairs_i), np.concatenate(pairs_j)
    if not len(u):
        return node
    label = np.arange(node.max() + 1)
    while True:  # each node takes the least label of its close ones, until none changes
        m = np.minimum(label[u], label[v])
        new = label.copy()
        np.minimum.at(new, u, m)
        np.minimum.at(new, v, m)
        new = new[new]  # jump along the labels
        if np.array_equal(new, label):
            return label[node]
        label = new


def chain(a, b, join=0.0):
    """Runs (a[i] -> b[i]) joined into the fewest paths: a list of polylines (arrays of points).

    Ends equal to 1/1024 px meet; so do ends closer than `join` (pixels), the gap bridged: two
    round caps closer than a stroke's width overlap, so the line pass inks it as one stroke. A path goes on through
    a node while an unused run leaves it, taking the straightest (a crossing is two paths, a T
    one path and a branch), so a junction cuts no stroke in pieces."""
    n = len(a)
    if n == 0:
        return []
    pts = np.r_[a, b].astype(np.float64)
    node = _weld(pts, join)
    adj = {}
    for e, v in enumerate(node.tolist()):
        adj.setdefault(v, []).append(e)  # end e: run e % n, its a (e < n) or b
    used = np.zeros(n, bool)

    # The unit direction leaving each end through its run (zero for a run of no length).
    d = pts[n:] - pts[:n]
    length = np.hypot(d[:, 0], d[:, 1])
    unit = np.where(length[:, None] > 0.0, d / np.where(length > 0.0, length, 1.0)[:, None], 0.0)
    leave = np.r_[unit, -unit]
    node_of = node.tolist()

    def walk(e):
        """The path from end e through its run and on; returns its points."""
        path = [pts[e]]
        while True:
            r = e % n
            other = e + n if e < n else e - n
            used[r] = True
            if np.hypot(*(pts[other] - path[-1])) > 0.0:
                path.append(pts[other])
            candidates = [f for f in adj[node_of[other]] if not used[f % n]]
            if not candidates:
                return np.array(path)
            # The straightest on: the first of the largest cosines, as max() took it.
            if len(candidates) > 1:
                h, c = leave[e], leave[candidates]
                e = candidates[int(np.argmax(c[:, 0] * h[0] + c[:, 1] * h[1]))]
            else:
                e = candidates[0]
            if np.hypot(*(pts[e] - path[-1])) > 0.0:  # a bridged gap
                path.append(pts[e])

    out = []
    # Open paths from the nodes of odd degree (each is some path's end), then what is left:
    # closed loops, from any end.
    for v in [v for v, es in adj.items() if len(es) % 2 == 1]:
        for e in adj[v]:
            if not used[e % n]:
                out.append(walk(e))
    for e in range(n):
        if not used[e]:
            out.append(walk(e))
    return out


def simplify(p, tol=TOLERANCE_PX):
    """Douglas-Peucker on a polyline (k, 2): the kept points."""
    if len(p) <= 2:
        return p
    keep = np.zeros(len(p), bool)
    keep[0] = keep[-1] = True
    stack = [(0, len(p) - 1)]
    while stack:
        i, j = stack.pop()
        if j <= i + 1:
            continue
        a, b = p[i], p[j]
        d = b - a
        q = p[i + 1:j] - a
        ll = float(d @ d)
        if ll > 1e-12:
            dist = np.abs(q[:, 0] * d[1] - q[:, 1] * d[0]) / np.sqrt(ll)
        else:
            dist = np.linalg.norm(q, axis=1)
        m = int(np.argmax(dist))
        if dist[m] > tol:
            keep[i + 1 + m] = True
            stack += [(i, i + 1 + m), (i + 1 + m, j)]
    return p[keep]


SLIVER_PX = 3.0  # a piece this short beside an earlier type's stroke is that stroke's edge


def _distance_to_segments(points, a, b):
    """(k, m): each point's (k, 2) distance to each segment a[i] -> b[i]."""
    d = b - a
    ll = np.maximum((d * d).sum(axis=1), 1e-12)
    t = np.clip(((points[:, None, :] - a[None]) * d[None]).sum(axis=2) / ll[None], 0.0, 1.0)
    q = a[None] + t[..., None] * d[None]
    return np.sqrt(((points[:, None, :] - q) ** 2).sum(axis=2))


def _length(p):
    return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum()) if len(p) > 1 else 0.0


def _segment_grid(a, b, cell):
    """{grid cell: segments passing through it}: each segment's cells along its length (points
    every half cell, and both ends), not its bounding box."""
    n = np.maximum(1, np.ceil(np.linalg.norm(b - a, axis=1) / (0.5 * cell))).astype(np.int64)
    seg = np.repeat(np.arange(len(a)), n + 1)
    t = (np.arange(len(seg)) - np.repeat(np.cumsum(n + 1) - (n + 1), n + 1)) / np.repeat(n, n + 1)
    pts = a[seg] + t[:, None] * (b[seg] - a[seg])
    cells = np.floor(pts / cell).astype(np.int64)
    grid = {}
    for (cx, cy), i in set(zip(map(tuple, cells.tolist()), seg.tolist())):
        grid.setdefault((cx, cy), []).append(i)
    return grid


def drop_slivers(out, order):
    """Leaves out visible pieces at most SLIVER_PX long whose ink touches the visible ink of a type
    drawn before theirs (`order`: the draw order) all along: where a crease runs on the rounded
    outline, its visibility samples pass and fail by turns beside the silhouette drawn there, and
    each pass was a polyline of its own (fandisk: 97 of 119 crease polylines, each about 1 px).
    The earlier type wins that ink in the line pass; the file keeps its strokes whole."""
    drawn_a, drawn_b, drawn_w = [], [], []
    cell = 4.0 * SLIVER_PX
    for kind in order:
        groups = out.get(kind, ())
        short = any(_length(p) <= SLIVER_PX for g in groups if not g.hidden for p in g.polylines)
        if drawn_a and short:
            a, b, w = np.concatenate(drawn_a), np.concatenate(drawn_b), np.concatenate(drawn_w)
            grid = _segment_grid(a, b, cell)
            for st in (g for g in groups if not g.hidden):
                kept = []
                for p in st.polylines:
                    if _length(p) <= SLIVER_PX:
                        # Past the touching distance by half a cell: the grid holds points of
                        # each segment every half cell.
                        reach = SLIVER_PX + 0.5 * cell
                        c0 = np.floor((p.min(axis=0) - reach) / cell).astype(np.int64)
                        c1 = np.floor((p.max(axis=0) + reach) / cell).astype(np.int64)
                        near = sorted({i for cx in range(c0[0], c1[0] + 1) for cy in range(c0[1], c1[1] + 1)
                                       for i in grid.get((cx, cy), ())})
                        # Every point touches the ink of some earlier segment, at its own width.
                        if near and np.all((_distance_to_segments(p, a[near], b[near])
                                            <= 0.5 * (w[near][None] + st.width)).any(axis=1)):
                            continue
                    kept.append(p)
                st.polylines = kept
        for st in (g for g in groups if not g.hidden):
            for p in st.polylines:
                if len(p) > 1:
                    drawn_a.append(p[:-1])
                    drawn_b.append(p[1:])
                    drawn_w.append(np.full(len(p) - 1, st.width))
    for kind in list(out):
        out[kind] = [g for g in out[kind] if g.polylines]
        if not out[kind]:
            del out[kind]
    return out


def strokes(instances, settings, camera, depth, ids, rounded=False):
    """type -> [Stroke] for the drawn types of `settings` (LineSettings).

    instances: [(matrix, {type: LineSegments}, instance id)]; depth / ids: the first sample's
    surface_depth and surface_id as read back. Hidden runs are kept only when hidden lines are
    drawn (dimmed). Coordinates are flipped to SVG's (y down)."""
    out = {}
    for kind, style in settings.styles:
        parts = [sample_runs(segs[kind], matrix, iid, kind, style, camera, depth, ids, rounded)
                 for matrix, segs, iid in instances if kind in segs and len(segs[kind])]
        if not parts:
            continue
        a, b, hidden, width = (np.concatenate(x) for x in zip(*parts))
        wanted = (width > 0.0) & (~hidden | (settings.hidden_opacity > 0.0))
        groups = []
        for h, w in sorted(set(zip(hidden[wanted].tolist(), width[wanted].tolist()))):
            sel = wanted & (hidden == h) & (width == w)
            st = Stroke(h, w)
            # Ends closer than the width: their round caps overlap, one stroke in the raster.
            for poly in chain(a[sel], b[sel], join=w):
                poly = np.c_[poly[:, 0], camera.height - poly[:, 1]]
                st.polylines.append(simplify(poly))
            groups.append(st)
        if groups:
            out[kind] = groups
    return drop_slivers(out, [kind for kind, _ in settings.styles])


def instances_of(scene, view_segments):
    """[(matrix, {type: LineSegments}, instance id)] of a frame: each instance's static line sets
    and its view-dependent ones (frame.view_line_segments)."""
    out = []
    for i, inst in enumerate(scene.instances):
        if inst.holdout:  # a hole in the image has no ink
            continue
        segs = dict(inst.mesh.lines)
        if view_segments and i < len(view_segments) and view_segments[i]:
            segs.update(view_segments[i])
        out.append((inst.matrix, segs, i + 1))
    return out

