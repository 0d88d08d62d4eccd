"""Silhouette lines on the rounded outline (addon/geometry/outline_lines.py, the library's
el_outline_lines): a rounded edge's silhouette end moves onto its fillet's outline point, in
closed form for a 90-degree edge; two moved segments that meet at a corner end where their lines
cross, or, round a corner patch's ball, on its circle with an arc of it between; an unmoved
silhouette they run on into ends at the fillet's foot. The library is held to the numpy reference
it replaced (outline_lines_reference.py) on boxes seen from many sides, through uniform,
non-uniform and perspective transforms; the reference's joins are pinned in closed form here."""
import dataclasses
import types
import unittest

import numpy as np

import outline_lines_reference as reference
from addon_modules import addon_module
from small_meshes import box as small_box
from small_meshes import edge_frame
from test_rounded_outline import extract_of

native = addon_module("bridge.native")
outline_lines = addon_module("geometry.outline_lines")


def on_rounded_outline(extract, edge_pairs, seg, matrix, camera):
    """The library's move of one instance's segments (el_outline_lines, with the records the
    add-on hands it: outline_lines.outline_of), as the reference's on_rounded_outline."""
    out = outline_lines.outline_of(extract).lines(edge_pairs, seg.p0, seg.p1, seg.n1, seg.n2, seg.taper, seg.faces,
                                                   seg.chain_links, matrix, camera)
    return dataclasses.replace(seg, p0=out["p0"], p1=out["p1"], n1=out["n1"], n2=out["n2"], taper=out["taper"],
                               faces=out["faces"], chain_links=out["links"])

R = 0.1
NA, NB = np.array([0.0, 0.0, 1.0]), np.array([0.0, -1.0, 0.0])  # top and front faces


def record(p0, p1, na=NA, nb=NB, radius=R):
    """One edge's strip record (rounded_outline.EDGE_TEXELS texels), its normals not turning."""
    r = np.zeros((1, 6, 4), np.float32)
    r[0, 0, :3], r[0, 0, 3], r[0, 1, :3] = na, radius, nb
    r[0, 2, :3], r[0, 3, :3] = p0, p1
    return r


def ortho(to_eye):
    v = np.asarray(to_eye, float)
    return camera_of(orthographic=True, view_dir=tuple(-v / np.linalg.norm(v)), eye=None)


def camera_of(**kw):
    """A passes.camera.Camera's fields; view and projection the identity unless given (they only
    size corner arcs and place the joins' crossings)."""
    base = dict(view=np.eye(4), projection=np.eye(4), width=100, height=100)
    return types.SimpleNamespace(**{**base, **kw})


def moves_of(rec, matrix, camera):
    """(2, N, 3) the library's moves of each record's two ends (p0, p1), as the reference's
    outline_moves gives them: one segment per record along its edge, alone (no corner, no foot)."""
    n = len(rec)
    outline = native.Outline(rec.reshape(n, -1), np.arange(2 * n).reshape(n, 2),
                             np.zeros((0, 4 * native.OUTLINE_CORNER_TEXELS)), np.zeros(0))
    p0, p1 = rec[:, 2, :3], rec[:, 3, :3]
    out = outline.lines(np.arange(2 * n).reshape(n, 2), p0, p1, np.zeros((n, 3)), np.zeros((n, 3)),
                        np.zeros((n, 2)), None, None, matrix, camera)
    return np.stack([out["p0"] - p0, out["p1"] - p1]).astype(np.float64)


class OutlinePoint(unittest.TestCase):
    def test_a_box_edge_seen_from_above_and_behind(self):
        """The top face towards the eye, the front face away: the fillet's axis lies r inside
        both faces, at (0, r, -r) from the edge, and its outline is the point of the circle
        whose normal is square to the view, on the sharp edge's side: (0, -0.8, 0.6) for a view
        from (0, 0.6, 0.8). The move is from the edge to that point, at both ends."""
        moves = moves_of(record((0, 0, 0), (1, 0, 0)), np.eye(4), ortho((0.0, 0.6, 0.8)))
        axis = np.array([0.0, R, -R])
        expected = axis + R * np.array([0.0, -0.8, 0.6])
        for end in (0, 1):
            np.testing.assert_allclose(moves[end, 0], expected, atol=1e-6)
        # On the fillet's circle, and its normal there square to the view.
        np.testing.assert_allclose(np.linalg.norm(moves[0, 0] - axis), R, rtol=1e-5)
        self.assertAlmostEqual(float(np.dot(moves[0, 0] - axis, (0.0, 0.6, 0.8))), 0.0, places=6)

    def test_the_faces_either_way_round(self):
        """N1 and N2 swapped (the edge's cross product the other way): the same point."""
        a = moves_of(record((0, 0, 0), (1, 0, 0)), np.eye(4), ortho((0.0, 0.6, 0.8)))
        b = moves_of(record((0, 0, 0), (1, 0, 0), NB, NA), np.eye(4), ortho((0.0, 0.6, 0.8)))
        np.testing.assert_allclose(a, b, atol=1e-6)

    def test_no_move_where_a_concave_fillet_meets_the_end(self):
        """A cut at p0 (a concave fillet fills the corner there: its end arc runs the outline
        out round it): that end stays on the sharp edge, the other moves as before."""
        rec = record((0, 0, 0), (1, 0, 0))
        rec[0, 2, 3] = -0.1
        moves = moves_of(rec, np.eye(4), ortho((0.0, 0.6, 0.8)))
        np.testing.assert_array_equal(moves[0], 0.0)
        np.testing.assert_allclose(moves[1, 0], np.array([0.0, R, -R]) + R * np.array([0.0, -0.8, 0.6]), atol=1e-6)

    def test_no_move_where_both_faces_face_the_eye(self):
        moves = moves_of(record((0, 0, 0), (1, 0, 0)), np.eye(4), ortho((0.0, -0.6, 0.8)))
        np.testing.assert_array_equal(moves, 0.0)

    def test_in_perspective_each_end_sees_the_eye_from_itself(self):
        """An eye far up the same direction gives the orthographic answer; one that sees the
        front face from one end and not from the other moves that end only."""
        far = camera_of(orthographic=False, view_dir=None, eye=tuple(np.array([0.5, 0.6, 0.8]) * 1e5))
        moves = moves_of(record((0, 0, 0), (1, 0, 0)), np.eye(4), far)
        np.testing.assert_allclose(moves[0, 0], (0.0, 0.02, -0.04), atol=1e-5)
        # From (0.5, 0.05, 10): behind the front face's plane (y > 0) from both ends, so both move;
        # from (0.5, -0.05, 10) in front of it: a silhouette nowhere.
        for y, moved in ((0.05, True), (-0.05, False)):
            eye = camera_of(orthographic=False, view_dir=None, eye=(0.5, y, 10.0))
            moves = moves_of(record((0, 0, 0), (1, 0, 0)), np.eye(4), eye)
            self.assertEqual(bool(np.abs(moves).max() > 1e-6), moved, y)

    def test_a_uniform_scale_keeps_the_object_space_move(self):
        """The radius is in object space (the Bevel modifier's Amount): under a uniform scale
        the fillet scales with the object, and its outline point stays where it was on it."""
        rec = record((0, 0, 0), (1, 0, 0))
        scaled = np.diag([3.0, 3.0, 3.0, 1.0])
        np.testing.assert_allclose(moves_of(rec, scaled, ortho((0.0, 0.6, 0.8))),
                                   moves_of(rec, np.eye(4), ortho((0.0, 0.6, 0.8))), atol=1e-6)


def join(p0, p1, d):
    """Segments 0 -> 1 and 1 -> 2 (p0, p1, directions d), seen along z: both joined in place."""
    p0, p1 = np.array(p0, np.float32), np.array(p1, np.float32)
    e1, e2 = reference._two_ends(np.array([[0, 1], [1, 2]]))
    reference._join_corners(e1, e2, np.arange(2), np.array(d, np.float32), p0, p1, np.eye(4))
    return p0, p1


class Corners(unittest.TestCase):
    """The reference's joins (outline_lines_reference.py), in closed form."""

    def test_two_moved_segments_end_where_their_lines_cross(self):
        """Segments 0 -> 1 along x and 1 -> 2 along y meet at vertex 1; moved square to
        themselves by 0.1 (into the corner), each overshoots the other. Both end at (0.9, 0.1),
        seen along z (the clip matrix the identity)."""
        p0, p1 = join([[0.0, 0.1, 0.0], [0.9, 0.0, 0.0]], [[1.0, 0.1, 0.0], [0.9, 1.0, 0.0]], [[1, 0, 0], [0, 1, 0]])
        np.testing.assert_allclose(p1[0], (0.9, 0.1, 0.0), atol=1e-6)
        np.testing.assert_allclose(p0[1], (0.9, 0.1, 0.0), atol=1e-6)
        np.testing.assert_allclose(p0[0], (0.0, 0.1, 0.0))  # free ends stay
        np.testing.assert_allclose(p1[1], (0.9, 1.0, 0.0))

    def test_skew_lines_end_where_their_images_cross(self):
        """The same corner with the second line moved 0.3 towards the eye (z), seen along z:
        both ends at one point on the first line whose image is the crossing, (0.9, 0.1, 0)."""
        p0, p1 = join([[0.0, 0.1, 0.0], [0.9, 0.0, 0.3]], [[1.0, 0.1, 0.0], [0.9, 1.0, 0.3]], [[1, 0, 0], [0, 1, 0]])
        np.testing.assert_allclose(p1[0], (0.9, 0.1, 0.0), atol=1e-6)
        np.testing.assert_array_equal(p0[1], p1[0])

    def test_segments_that_nearly_continue_each_other_meet_halfway(self):
        """Along a smooth rim the two lines cross far off or not at all: the ends meet at their
        mean."""
        p0, p1 = join([[0.0, 0.0, 0.0], [1.0, 0.02, 0.0]], [[1.0, 0.0, 0.0], [2.0, 0.05, 0.0]],
                      [[1.0, 0.0, 0.0], [1.0, 0.03, 0.0]])
        np.testing.assert_allclose(p1[0], (1.0, 0.01, 0.0), atol=1e-6)
        np.testing.assert_allclose(p0[1], (1.0, 0.01, 0.0), atol=1e-6)


class ToTheFoot(unittest.TestCase):
    """The reference's foot, in closed form."""

    def test_an_unmoved_side_ends_at_the_fillets_foot(self):
        """Segment 0 -> 1 moved (its end at vertex 1 now at (1, 0.1, 0.05)), 1 -> 2 not (a side
        running from vertex 1 at (1, 0, 0) down to (1, -1, 0)), the setback 0.1: the side ends
        at the foot (1, -0.1, 0), along its own line, and a segment from the foot to the moved
        end, with the moved one's faces, follows it in its chain."""
        links = np.zeros(2, [("chain", "<u4"), ("s0", "<f4"), ("s1", "<f4")])
        links["s0"], links["s1"] = (0.0, 1.0), (1.0, 2.0)
        seg = Segments(np.array([[0.0, 0.1, 0.05], [1.0, -1.0, 0.0]], np.float32),
                       np.array([[1.0, 0.1, 0.05], [1.0, 0.0, 0.0]], np.float32),
                       np.zeros((2, 3), np.float32), np.zeros((2, 3), np.float32), np.zeros((2, 2), np.float32),
                       np.array([[1.0, 2.0], [3.0, 4.0]], np.float32), links)
        out = reference._to_the_foot(seg, np.array([[0, 1], [2, 1]]), np.array([True, True, False, False]),
                                         np.array([0.1, 0.0]))
        self.assertEqual(len(out.p0), 3)
        np.testing.assert_allclose(out.p1[1], (1.0, -0.1, 0.0), atol=1e-6)   # the side's end, at the foot
        np.testing.assert_allclose(out.p0[1], (1.0, -1.0, 0.0))             # its far end stays
        np.testing.assert_allclose(out.p0[2], (1.0, -0.1, 0.0), atol=1e-6)   # foot -> moved end
        np.testing.assert_allclose(out.p1[2], (1.0, 0.1, 0.05), atol=1e-6)
        np.testing.assert_array_equal(out.faces[2], (1.0, 2.0))
        self.assertEqual((out.chain_links["s0"][2], out.chain_links["s1"][2]), (2.0, 2.0))


@dataclasses.dataclass
class Segments:
    """The fields of lines.LineSegments (lines.py loads the library; this test does not)."""
    p0: np.ndarray
    p1: np.ndarray
    n1: np.ndarray
    n2: np.ndarray
    taper: np.ndarray
    faces: np.ndarray = None
    chain_links: np.ndarray = None


def box_silhouettes(to_eye, radius=0.1):
    """A unit box's extract (every edge rounded at `radius`, corner patches) and its silhouette
    segments seen along -to_eye, orthographically, 200 x 200 pixels over 2 units."""
    positions, edges, polys, tris = small_box()
    ex, _ = extract_of(positions, edges, polys, tris, np.ones(len(edges), bool), radius=radius, corners=True)
    ex.edge_data.positions = positions
    normals, _ = edge_frame(positions, edges, polys, tris)
    v = np.asarray(to_eye, float) / np.linalg.norm(to_eye)
    front = normals.reshape(-1, 2, 3) @ v > 0.0
    sil = np.flatnonzero(front[:, 0] != front[:, 1])
    seg = Segments(positions[edges[sil, 0]].astype(np.float32), positions[edges[sil, 1]].astype(np.float32),
                   normals[sil, :3], normals[sil, 3:], np.zeros((len(sil), 2), np.float32),
                   np.ones((len(sil), 2), np.float32))
    up = np.cross(v, (0.0, 0.0, 1.0))
    x = up / np.linalg.norm(up)
    y = np.cross(v, x)
    view = np.eye(4)
    view[:3, :3] = np.stack([x, y, v])
    view[:3, 3] = -view[:3, :3] @ (0.5, 0.5, 0.5)
    camera = types.SimpleNamespace(orthographic=True, view_dir=tuple(-v), eye=None, view=view,
                                   projection=np.diag([1.0, 1.0, -0.1, 1.0]), width=200, height=200)
    return ex, edges[sil], seg, camera


class CornerArcs(unittest.TestCase):
    def test_a_box_corner_is_the_balls_circle(self):
        """A box seen along (1, 2, 3) outlines a hexagon, each of its corners a corner patch's
        ball (centre r inside its three faces) 10 px wide: the two moved silhouettes end on the
        ball's circle (the centre plus r times each one's outline direction), and an arc of it,
        square to the view, joins them in pieces whose chords stay within 0.25 px of it."""
        ex, pairs, seg, camera = box_silhouettes((1.0, 2.0, 3.0))
        out = on_rounded_outline(ex, pairs, seg, np.eye(4), camera)
        n = len(seg.p0)
        self.assertEqual(n, 6)
        arcs = slice(n, None)
        self.assertGreater(len(out.p0) - n, 6, "an arc of several pieces at each of the six corners")
        v = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
        corners = [c for c in np.ndindex(2, 2, 2) if c not in ((0, 0, 0), (1, 1, 1))]
        centres = np.array([np.where(np.array(c) == 1, 0.9, 0.1) for c in corners])
        for ends in (out.p0[arcs], out.p1[arcs]):
            off = ends[:, None, :] - centres[None]
            near = np.argmin(np.linalg.norm(off, axis=2), axis=1)
            off = off[np.arange(len(ends)), near]
            np.testing.assert_allclose(np.linalg.norm(off, axis=1), 0.1, atol=1e-5)
            np.testing.assert_allclose(off @ v, 0.0, atol=1e-5)
        # One closed stroke: every end meets exactly one other.
        ends = np.concatenate([out.p0, out.p1]).astype(np.float64)
        gap = np.linalg.norm(ends[:, None] - ends[None], axis=2) + np.eye(len(ends))
        self.assertLess(float(gap.min(axis=1).max()), 1e-6)
        # Chords within 0.25 px (1 px = 0.01 here) of the circle: their midpoints' depth inside it.
        mid = 0.5 * (out.p0[arcs] + out.p1[arcs])
        inside = 0.1 - np.linalg.norm(mid[:, None, :] - centres[None], axis=2).min(axis=1)
        self.assertLess(float(inside.max()), 0.0025 + 1e-6)

    def test_a_corner_without_a_ball_keeps_its_crossing(self):
        """With the patch at (1, 0, 0) left out (a third edge there not rounded, say), its two
        silhouettes end where their images cross, and the other five corners still round."""
        ex, pairs, seg, camera = box_silhouettes((1.0, 2.0, 3.0))
        every = len(on_rounded_outline(ex, pairs, seg, np.eye(4), camera).p0) - 6
        ex, pairs, seg, camera = box_silhouettes((1.0, 2.0, 3.0))
        edges = ex.edges[0]
        keep = np.flatnonzero(~np.all(edges.corners.position == (1.0, 0.0, 0.0), axis=1))
        self.assertEqual(len(keep), len(edges.corners) - 1)
        edges.corners = edges.corners.subset(keep)
        out = on_rounded_outline(ex, pairs, seg, np.eye(4), camera)
        ends = np.concatenate([out.p0[:6], out.p1[:6]]).astype(np.float64)
        near = np.linalg.norm(ends - (1.0, 0.0, 0.0), axis=1) < 0.3
        self.assertEqual(int(near.sum()), 2)
        np.testing.assert_allclose(ends[near][0], ends[near][1], atol=1e-6)
        self.assertTrue(5 <= len(out.p0) - 6 < every, "five arcs, one piece or more each")

    def test_no_arc_where_the_ball_is_under_a_pixel(self):
        """r 0.005: the ball's circle is a pixel wide; the lines join where they cross."""
        ex, pairs, seg, camera = box_silhouettes((1.0, 2.0, 3.0), radius=0.005)
        out = on_rounded_outline(ex, pairs, seg, np.eye(4), camera)
        self.assertEqual(len(out.p0), len(seg.p0))


def box_view(to_eye, matrix, radius=0.1, rounded="all", perspective=False, rng=None):
    """A unit box's extract (its edges `rounded`: "all", or "top", the four at z = 1, with corner
    patches where three meet), seen along -to_eye through `matrix` (orthographic, or in
    perspective from 4 units away), 320 x 240 pixels: (extract, vertex pairs, segments with faces
    and chain records (one chain, some run backwards), camera)."""
    positions, edges, polys, tris = small_box()
    mask = np.ones(len(edges), bool) if rounded == "all" else np.all(positions[edges][:, :, 2] == 1.0, axis=1)
    ex, _ = extract_of(positions, edges, polys, tris, mask, radius=radius, corners=True)
    ex.edge_data.positions = positions
    normals, _ = edge_frame(positions, edges, polys, tris)
    m = np.asarray(matrix, np.float64)
    v = np.asarray(to_eye, float) / np.linalg.norm(to_eye)
    centre = m[:3, :3] @ (0.5, 0.5, 0.5) + m[:3, 3]
    eye = centre + 4.0 * v * np.linalg.norm(m[:3, :3], 2)
    inv = np.linalg.inv(m[:3, :3])
    if perspective:
        eye_obj = inv @ (eye - m[:3, 3])
        towards = eye_obj[None] - positions[edges[:, 0]]
    else:
        towards = np.broadcast_to(inv @ v, (len(edges), 3))
    front = np.einsum("nsk,nk->ns", normals.reshape(-1, 2, 3), towards) > 0.0
    sil = np.flatnonzero(front[:, 0] != front[:, 1])
    links = np.zeros(len(sil), native.CHAIN_LINK)
    links["s0"], links["s1"] = np.arange(len(sil)), np.arange(len(sil)) + 1.0
    back = rng.random(len(sil)) < 0.5
    links["s0"][back], links["s1"][back] = links["s1"][back], links["s0"][back]
    seg = Segments(positions[edges[sil, 0]].astype(np.float32), positions[edges[sil, 1]].astype(np.float32),
                   normals[sil, :3], normals[sil, 3:], rng.random((len(sil), 2)).astype(np.float32),
                   (rng.integers(1, 12, (len(sil), 2))).astype(np.float32), links)
    x = np.cross((0.0, 0.0, 1.0), v) if abs(v[2]) < 0.99 else np.array([1.0, 0.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(v, x)
    view = np.eye(4)
    view[:3, :3] = np.stack([x, y, v])
    view[:3, 3] = -view[:3, :3] @ eye
    if perspective:
        f, near, far = 1.0 / np.tan(np.radians(20.0)), 0.1, 100.0
        projection = np.array([[f * 0.75, 0, 0, 0], [0, f, 0, 0],
                               [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)], [0, 0, -1, 0]])
    else:
        s = 1.0 / (1.2 * np.linalg.norm(m[:3, :3], 2))
        projection = np.diag([s * 0.75, s, -0.01, 1.0])
    camera = types.SimpleNamespace(orthographic=not perspective, view_dir=tuple(-v), eye=tuple(eye), view=view,
                                   projection=projection, width=320, height=240)
    return ex, edges[sil], seg, camera


def rotation(axis, degrees):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    t = np.radians(degrees)
    return np.eye(3) + np.sin(t) * k + (1 - np.cos(t)) * k @ k


class AgainstTheReference(unittest.TestCase):
    def test_the_library_gives_the_references_segments(self):
        """Boxes rounded all round (corner arcs, crossings) and on the top only (moved rims running
        into unmoved sides: feet), r from a sub-pixel 0.005 to 0.3, seen from 24 sides each,
        orthographically and in perspective, through the identity, a uniform scale and shift, and
        a rotated non-uniform scale: the library's segments are the reference's, in number and
        order, their ends within 2e-5 of a unit box, the rest (normals, taper, faces, chain
        records) exact."""
        rng = np.random.default_rng(7)
        shear = np.eye(4)
        shear[:3, :3] = rotation((1, 2, 0.5), 35.0) @ np.diag([2.0, 0.6, 1.3])
        shear[:3, 3] = (3.0, -1.0, 0.5)
        uniform = np.diag([2.5, 2.5, 2.5, 1.0])
        uniform[:3, 3] = (-4.0, 2.0, 1.0)
        counts = {"cases": 0, "appended": 0, "moved": 0}
        for matrix in (np.eye(4), uniform, shear):
            for rounded, radius in (("all", 0.1), ("all", 0.005), ("top", 0.3), ("top", 0.1)):
                for perspective in (False, True):
                    for to_eye in rng.normal(size=(24, 3)):
                        ex, pairs, seg, camera = box_view(to_eye, matrix, radius, rounded, perspective, rng)
                        ours = on_rounded_outline(ex, pairs, seg, matrix, camera)
                        ref = reference.on_rounded_outline(ex, pairs, dataclasses.replace(seg), matrix, camera)
                        where = f"{rounded} r {radius}, perspective {perspective}, to eye {to_eye}, matrix\n{matrix}"
                        self.assertEqual(len(ours.p0), len(ref.p0), where)
                        for name in ("p0", "p1"):
                            np.testing.assert_allclose(getattr(ours, name), getattr(ref, name), atol=2e-5, err_msg=where)
                        for name in ("n1", "n2", "taper", "faces"):
                            np.testing.assert_array_equal(getattr(ours, name), getattr(ref, name), err_msg=where)
                        for name in ("chain", "s0", "s1"):
                            np.testing.assert_array_equal(ours.chain_links[name], ref.chain_links[name], err_msg=where)
                        counts["cases"] += 1
                        counts["appended"] += len(ours.p0) - len(seg.p0)
                        counts["moved"] += int(np.any(ours.p0[:len(seg.p0)] != seg.p0, axis=1).sum())
        print(f"against the reference: {counts}")
        self.assertGreater(counts["appended"], 500, "arcs and feet were made")
        self.assertGreater(counts["moved"], 500, "ends were moved")

    def test_without_faces_or_chains(self):
        """Segments without faces or chain records (each its own chain): the same as the reference."""
        rng = np.random.default_rng(3)
        for rounded in ("all", "top"):
            ex, pairs, seg, camera = box_view((1.0, -2.0, 1.5), np.eye(4), 0.1, rounded, True, rng)
            seg = dataclasses.replace(seg, faces=None, chain_links=None)
            ours = on_rounded_outline(ex, pairs, seg, np.eye(4), camera)
            ref = reference.on_rounded_outline(ex, pairs, seg, np.eye(4), camera)
            self.assertGreater(len(ours.p0), len(seg.p0))
            self.assertIsNone(ours.faces)
            self.assertIsNone(ours.chain_links)
            np.testing.assert_allclose(ours.p0, ref.p0, atol=2e-5)
            np.testing.assert_allclose(ours.p1, ref.p1, atol=2e-5)


class FilletOutline(unittest.TestCase):
    def test_the_library_and_the_reference_agree(self):
        """el_fillet_outline against the reference's numpy copy (itself held to the shader's
        el_fillet_outline on the GPU: tests/blender/test_fillet_outline.py)."""
        rng = np.random.default_rng(5)
        na, nb, v = (x / np.linalg.norm(x, axis=1, keepdims=True) for x in rng.normal(size=(3, 4000, 3)))
        p, c, sil = native.fillet_outline(na, nb, v)
        rp, rc, rsil = reference.fillet_outline(na.astype(np.float32).astype(float), nb.astype(np.float32).astype(float),
                                                v.astype(np.float32).astype(float))
        np.testing.assert_array_equal(sil, rsil)
        np.testing.assert_allclose(p, rp, atol=1e-6)
        np.testing.assert_allclose(c, rc, rtol=1e-6, atol=1e-6)


if __name__ == "__main__":
    unittest.main()
