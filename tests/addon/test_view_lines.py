"""The view lines of many instances in one library call (el_view_lines, lines.silhouettes): the
same segments as each instance's own native view, chains, taper values and move onto the rounded
outline (el_view_update, el_mesh_chain_edges, lines.taper_params, el_outline_lines), instances
in parallel; an instance with a singular transform gets none and the library's message, the
others theirs."""
import types
import unittest

import numpy as np

from addon_modules import addon_module
from small_meshes import box as small_box
from small_meshes import mesh as small_mesh
from test_rounded_outline import extract_of

native = addon_module("bridge.native")
lines = addon_module("linework.lines")
outline_lines = addon_module("geometry.outline_lines")


def camera(perspective):
    v = np.array([0.4, -0.7, 0.6])
    v /= np.linalg.norm(v)
    eye = 30.0 * v
    x = np.cross((0.0, 0.0, 1.0), v)
    x /= np.linalg.norm(x)
    view = np.eye(4)
    view[:3, :3] = np.stack([x, np.cross(v, x), v])
    view[:3, 3] = -view[:3, :3] @ eye
    f = 1.0 / np.tan(np.radians(25.0))
    projection = np.array([[f, 0, 0, 0], [0, f, 0, 0], [0, 0, -1.002, -0.2002], [0, 0, -1, 0]]) if perspective \
        else np.diag([0.08, 0.08, -0.01, 1.0])
    return types.SimpleNamespace(orthographic=not perspective, eye=tuple(eye), view_dir=tuple(-v), view=view,
                                 projection=projection, width=640, height=480)


def matrices(count, rng):
    """Boxes on a grid, turned and scaled each its own way (some non-uniformly, some mirrored)."""
    out = np.repeat(np.eye(4)[None], count, axis=0)
    for i in range(count):
        a, b = rng.uniform(0, 2 * np.pi, 2)
        rz = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])
        rx = np.array([[1, 0, 0], [0, np.cos(b), -np.sin(b)], [0, np.sin(b), np.cos(b)]])
        out[i, :3, :3] = rz @ rx @ np.diag(rng.uniform(0.5, 1.5, 3) * (1 if i % 7 else -1))
        out[i, :3, 3] = (i % 15 - 7.0, i // 15 - 7.0, rng.uniform(-1, 1))
    return out


def open_box():
    """The box without its top: its silhouettes' chains end at the rim (free ends: taper values)."""
    v = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    return small_mesh(v, [[0, 2, 6, 4], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]])


class ManyInstances(unittest.TestCase):
    def setUp(self):
        self.load(small_box())

    def load(self, parts):
        positions, edges, polys, tris = parts
        self.ex, _ = extract_of(positions, edges, polys, tris, np.ones(len(edges), bool), radius=0.1, corners=True)
        self.positions = positions.astype(np.float32)
        self.mesh = native.Mesh(positions, tris)
        self.lib_edges = self.mesh.edges()
        self.normals = self.mesh.edge_normals()
        self.faces = np.arange(2 * len(self.lib_edges), dtype=np.float32).reshape(-1, 2)

    def one_by_one(self, matrix, cam, outline, taper):
        """An instance's silhouettes the way the add-on made them before: its own view, chains,
        taper values, move."""
        view = native.View(self.mesh)
        view.update(native.make_camera(object_to_world=matrix, eye=None if cam.orthographic else cam.eye,
                                       view_dir=cam.view_dir if cam.orthographic else None), native.VIEW_SILHOUETTES)
        sil = view.silhouettes()
        links, chains = self.mesh.chain_edges(sil)
        t = lines.taper_params(links, chains) if taper else np.full((len(sil), 2), native.NO_TAPER, np.float32)
        e = self.lib_edges[sil]
        p = self.positions
        seg = dict(p0=p[e[:, 0]], p1=p[e[:, 1]], n1=self.normals[sil, :3], n2=self.normals[sil, 3:], taper=t,
                   faces=self.faces[sil], links=links)
        if outline is None:
            return seg
        return outline.lines(e, seg["p0"], seg["p1"], seg["n1"], seg["n2"], seg["taper"], seg["faces"], seg["links"],
                             matrix, cam)

    def test_one_call_gives_each_instances_own_segments(self):
        """200 boxes (threads take 64 at a time), closed (orthographic, in perspective) and
        open at the top (free ends), with and without the move and taper values: segment for segment what each instance's own calls
        give (ends within 1e-6, the rest exact but the taper values, within 1e-6)."""
        rng = np.random.default_rng(2)
        mats = matrices(200, rng)
        totals, tapered = 0, 0
        for parts, perspective in ((small_box(), False), (small_box(), True), (open_box(), True)):
            self.load(parts)
            outline = outline_lines.outline_of(self.ex)
            cam = camera(perspective)
            for use_outline, taper in ((True, True), (False, False), (True, False)):
                o = outline if use_outline else None
                offsets, failed, got = native.view_lines(self.mesh, native.outline_views(mats, cam), o, self.faces, taper)
                self.assertEqual(failed, {})
                for i in range(len(mats)):
                    want = self.one_by_one(mats[i], cam, o, taper)
                    at = slice(offsets[i], offsets[i + 1])
                    where = f"instance {i}, perspective {perspective}, outline {use_outline}, taper {taper}"
                    self.assertEqual(offsets[i + 1] - offsets[i], len(want["p0"]), where)
                    for k in ("p0", "p1", "taper"):
                        np.testing.assert_allclose(got[k][at], want[k], atol=1e-6, err_msg=where)
                    for k in ("n1", "n2", "faces"):
                        np.testing.assert_array_equal(got[k][at], want[k], err_msg=where)
                    np.testing.assert_array_equal(got["links"][at], want["links"], err_msg=where)
                totals += int(offsets[-1])
                tapered += int((got["taper"] < 1.0).sum())
        self.assertGreater(totals, 6 * 200 * 6, "every box outlined, arcs appended")
        self.assertGreater(tapered, 200, "ends near the open box's rim taper")

    def test_a_singular_instance_has_none_and_says_why(self):
        mats = matrices(5, np.random.default_rng(4))
        mats[2, :3, :3] = np.diag([1.0, 0.0, 1.0])
        offsets, failed, got = native.view_lines(self.mesh, native.outline_views(mats, camera(False)),
                                                 outline_lines.outline_of(self.ex), None, False)
        self.assertEqual(list(failed), [2])
        self.assertIn("EL_ERR_INVALID_ARGUMENT", failed[2])
        self.assertIn("not an invertible affine transform", failed[2])
        self.assertEqual(offsets[3] - offsets[2], 0)
        self.assertTrue(all(offsets[i + 1] > offsets[i] for i in (0, 1, 3, 4)))
        self.assertIsNone(got["faces"])

    def test_bad_arguments_fail_the_call(self):
        views = native.outline_views(matrices(3, np.random.default_rng(5)), camera(False))
        views["width"][1] = 0.0
        with self.assertRaises(native.NativeError) as e:
            native.view_lines(self.mesh, views, outline_lines.outline_of(self.ex))
        self.assertIn("width", e.exception.message)
        faces = self.faces.copy()
        faces[3, 1] = np.nan
        with self.assertRaises(native.NativeError) as e:
            native.view_lines(self.mesh, native.outline_views(matrices(3, np.random.default_rng(5)), camera(False)),
                              None, faces)
        self.assertEqual(e.exception.status, "EL_ERR_NON_FINITE")


if __name__ == "__main__":
    unittest.main()
