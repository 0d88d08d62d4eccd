"""Bad input gets a report and the render goes on; the user's data is never changed."""
import hashlib
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo


def add_object(name, verts, edges, faces, material=None):
    me = bpy.data.meshes.new(name)
    me.from_pydata(verts, edges, faces)
    ob = bpy.data.objects.new(name, me)
    if material:
        me.materials.append(material)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def messages(rec):
    return " | ".join(m for _, m in rec.get("messages", []))


class BadMeshes(unittest.TestCase):
    def setUp(self):
        helpers.open_sample("cube")

    def render_ok(self):
        rec = helpers.render(resolution=(160, 120))
        self.assertIn("pixels", rec, messages(rec))
        self.assertTrue(np.isfinite(rec["pixels"]).all())
        return rec

    def test_loose_edges_only(self):
        add_object("Wire", [(3, 0, 0), (4, 0, 0), (4, 1, 0)], [(0, 1), (1, 2)], [])
        rec = self.render_ok()
        self.assertIn("Wire: no faces (2 loose edges)", messages(rec))
        self.assertEqual(rec["stats"].objects, 1, "the cube still renders")

    def test_nan_coordinates(self):
        ob = add_object("Broken", [(3, 0, 0), (4, 0, 0), (4, 1, 0)], [], [(0, 1, 2)])
        ob.data.vertices[1].co = (float("nan"), 0.0, 0.0)
        rec = self.render_ok()
        self.assertIn("Broken: every face has a vertex at no usable position (NaN, infinite, or farther than 1e+15 units)",
                      messages(rec))
        self.assertEqual(rec["stats"].objects, 1, "the cube still renders")

    def test_a_render_where_every_object_fails_is_an_error(self):
        """Nothing drawn because every object failed is a failed render, not an empty frame."""
        bpy.data.objects.remove(bpy.data.objects["Cube"])
        for name in ("Broken", "Other"):
            ob = add_object(name, [(0, 0, 0), (1, 0, 0), (1, 1, 0)], [], [(0, 1, 2)])
            ob.data.vertices[2].co = (0.0, float("nan"), 0.0)
        rec = helpers.render(resolution=(160, 120), expect_error=True)
        self.assertIn("nothing could be drawn: 2 objects failed ('Broken', 'Other'; see the warnings)", rec["raised"])
        self.assertNotIn("pixels", rec)


    def test_zero_area_faces(self):
        add_object("Sliver", [(3, 0, 0), (4, 0, 0), (5, 0, 0), (3, 1, 0)], [], [(0, 1, 2), (0, 1, 3)])
        rec = self.render_ok()
        self.assertIn("Sliver: 1 zero-area faces", messages(rec))
        self.assertEqual(rec["stats"].objects, 2)

    def test_singular_transform_with_view_dependent_lines(self):
        bpy.context.scene.edgelight.use_lines = True
        flat = add_object("Flat", [(3, 0, 0), (4, 0, 0), (4, 1, 0), (3, 1, 1)], [], [(0, 1, 2), (0, 2, 3)])
        flat.scale = (1.0, 0.0, 1.0)  # no inverse: the library refuses the object-space view
        rec = self.render_ok()
        self.assertIn("Flat: no silhouettes or contours (EL_ERR_INVALID_ARGUMENT: object_to_world is not an invertible",
                      messages(rec))
        self.assertGreater(rec["stats"].lines_drawn, 0, "the cube's lines are still drawn")
        # With contours too, the refused instance is reported once.
        bpy.context.scene.edgelight.line_contour.enabled = True
        rec = self.render_ok()
        self.assertEqual(messages(rec).count("Flat: no silhouettes or contours"), 1, messages(rec))

    def test_no_material(self):
        bpy.data.objects["Cube"].data.materials.clear()
        rec = self.render_ok()
        self.assertEqual(messages(rec), "")
        self.assertGreater(rec["stats"].edges_drawn, 0, "the default look rounds edges too")


class NonFiniteVertices(unittest.TestCase):
    def test_only_the_faces_of_a_vertex_at_no_usable_position_are_lost(self):
        """A 4 x 4 grid of unit squares seen from above, one inner vertex at NaN, or at infinity
        (which Blender stores as the largest float): its four faces are not drawn (as a GPU
        leaves them), the other twelve are, with one warning."""
        for bad in (float("nan"), float("inf")):
            helpers.empty_scene(200, 200)
            helpers.add_camera((0.0, 0.0, 8.0))
            helpers.add_sun()
            verts = [(x - 2.0, y - 2.0, 0.0) for y in range(5) for x in range(5)]
            faces = [(y * 5 + x, y * 5 + x + 1, (y + 1) * 5 + x + 1, (y + 1) * 5 + x) for y in range(4) for x in range(4)]
            ob = add_object("Grid", verts, [], faces)
            ob.data.vertices[6].co = (bad, -1.0, 0.0)  # (x, y) = (-1, -1): cells (0..1, 0..1)
            for k in range(len(ob.data.edges)):
                helpers.mark_edge(ob.data, "sharp", k)
            helpers.only_lines(bpy.context.scene, border=2.0, marked=2.0).marks = {'SHARP'}
            rec = helpers.render()
            self.assertIn("Grid: 1 vertices at no usable position (NaN, infinite, or farther than 1e+15 units); "
                          "the 4 faces using them are not drawn", messages(rec))
            centres = [(x - 1.5, y - 1.5, 0.0) for y in range(4) for x in range(4)]
            px = np.floor(helpers.project(rec, centres)).astype(int)
            covered = np.asarray(rec["surface"])[px[:, 1], px[:, 0], 3] > 0.5
            lost = [x < 2 and y < 2 for y in range(4) for x in range(4)]
            self.assertEqual(covered.tolist(), [not k for k in lost], bad)
            self.assertTrue(np.isfinite(rec["pixels"]).all())
            # No ink across the hole: the marked edges that reached the vertex are not drawn
            # (they had run to the origin, where it is put for the library), only the hole's
            # border. Along the lines from its neighbours to the origin, inside the hole:
            stray = [(-2.0 + 2.0 * t, -1.0 + t, 0.0) for t in (0.3, 0.5, 0.7)] + \
                    [(-1.0 + t, -2.0 + 2.0 * t, 0.0) for t in (0.3, 0.5, 0.7)]
            sx, sy = np.floor(helpers.project(rec, stray)).astype(int).T
            self.assertEqual(float(np.asarray(rec["lines"])[sy, sx, 3].max()), 0.0, bad)

    def test_a_vertex_far_away_leaves_the_other_faces_rounded(self):
        """A subdivided cube with one vertex pulled a million units away: the faces elsewhere
        keep their area, so their edges stay rounded (judged against the whole mesh's size,
        every face had looked flat and no band was drawn)."""
        drawn = []
        for far in (False, True):
            helpers.empty_scene(200, 150)
            helpers.add_camera((4.0, -5.0, 3.5))
            helpers.add_sun()
            bm = zoo.subdivided_cube(1)
            me = bpy.data.meshes.new("Part")
            bm.to_mesh(me)
            bm.free()
            ob = bpy.data.objects.new("Part", me)
            bpy.context.scene.collection.objects.link(ob)
            if far:
                low = min(range(len(me.vertices)), key=lambda i: tuple(me.vertices[i].co)[::-1])
                me.vertices[low].co = (1e6, 0.0, -1.0)
            rec = helpers.render()
            self.assertNotIn("zero-area", messages(rec))
            drawn.append(rec["stats"].edges_drawn)
        self.assertGreater(drawn[1], 0.5 * drawn[0], drawn)

class NativeLibraryProblems(unittest.TestCase):
    def render_with_library(self, path):
        helpers.open_sample("cube")
        old = os.environ.get("EDGELIGHT_LIBRARY")
        os.environ["EDGELIGHT_LIBRARY"] = path
        try:
            return helpers.render(resolution=(160, 120), expect_error=True)
        finally:
            if old is None:
                del os.environ["EDGELIGHT_LIBRARY"]
            else:
                os.environ["EDGELIGHT_LIBRARY"] = old

    def test_missing_library(self):
        rec = self.render_with_library("/nonexistent/libedgelight.so")
        self.assertIn("native library unavailable", messages(rec))
        self.assertIn("cannot load /nonexistent/libedgelight.so", rec["raised"])
        self.assertNotIn("pixels", rec)

    def test_abi_mismatch(self):
        fake = os.environ.get("EDGELIGHT_FAKE_ABI_LIBRARY")
        self.assertTrue(fake and os.path.exists(fake), "the test build provides a mismatched library")
        rec = self.render_with_library(fake)
        self.assertIn("has ABI version 999, this add-on needs", messages(rec))

    def test_library_lacking_functions(self):
        fake = os.environ.get("EDGELIGHT_FAKE_SYMBOLS_LIBRARY")
        self.assertTrue(fake and os.path.exists(fake), "the test build provides a library lacking functions")
        rec = self.render_with_library(fake)
        self.assertIn("native library unavailable: EL_ABI_MISMATCH: " + fake, messages(rec))
        # The fake exports el_abi_version and el_last_error only.
        self.assertRegex(messages(rec), r"lacks functions this add-on calls: el_status_name, el_\w+, .* and \d+ more")
        self.assertNotIn("el_last_error", messages(rec))
        self.assertNotIn("pixels", rec)


class DamagedLibraryFiles(unittest.TestCase):
    """Damaged copies of the installed library are refused before ctypes maps them."""

    def load_elsewhere(self, paths):
        """native.load of each path in another Blender: a copy mapped by mistake may kill it."""
        cmd = helpers.blender_command(os.path.join(helpers.HERE, "load_library.py"), *paths)
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
        results = dict(re.findall(r"^EDGELIGHT_LOAD (\d+) (.*)$", run.stdout, re.M))
        self.assertEqual(len(results), len(paths), f"exit code {run.returncode}: {(run.stdout + run.stderr)[-3000:]}")
        return [results[str(i)] for i in range(len(paths))]

    def test_truncated_and_flipped_copies(self):
        here = os.path.dirname(helpers.addon().__file__)
        with open(os.path.join(here, "libedgelight.so"), "rb") as f:
            data = f.read()
        flipped = bytearray(data)
        flipped[len(data) // 2] ^= 0x10
        tmp = tempfile.mkdtemp(prefix="edgelight_damaged_")
        self.addCleanup(shutil.rmtree, tmp)
        cases = {}  # name: path of a copy, beside the package's record unless *_bare
        for name, content, record in (("intact", data, True), ("half", data[:len(data) // 2], True),
                                      ("hundred", data[:100], True), ("flipped", bytes(flipped), True),
                                      ("half_bare", data[:len(data) // 2], False), ("hundred_bare", data[:100], False),
                                      ("flipped_bare", bytes(flipped), False)):
            os.mkdir(os.path.join(tmp, name))
            path = os.path.join(tmp, name, "libedgelight.so")
            with open(path, "wb") as f:
                f.write(content)
            if record:
                shutil.copy(os.path.join(here, "libedgelight.json"), os.path.join(tmp, name))
            cases[name] = path
        results = dict(zip(cases, self.load_elsewhere(list(cases.values()))))
        self.assertEqual(results["intact"], "ok")
        for name in ("half", "hundred"):
            self.assertRegex(results[name],
                             rf"^refused EL_LIBRARY_CORRUPT: {re.escape(cases[name])} is \d+ bytes but .*truncated")
        for name in ("half_bare", "hundred_bare", "flipped_bare"):
            self.assertIn(f"refused EL_LIBRARY_CORRUPT: {cases[name]} has no checksum record", results[name])
        self.assertIn(f"refused EL_LIBRARY_CORRUPT: {cases['flipped']} does not match the SHA-256 checksum",
                      results["flipped"])


def fingerprint():
    """Hash of every mesh's geometry and attributes and every material's settings and nodes."""
    h = hashlib.sha256()
    for me in bpy.data.meshes:
        for coll, prop, width in ((me.vertices, "co", 3), (me.edges, "vertices", 2), (me.loops, "vertex_index", 1)):
            a = np.empty(len(coll) * width, np.float64 if prop == "co" else np.int64)
            coll.foreach_get(prop, a)
            h.update(a.tobytes())
        for attr in me.attributes:
            h.update(attr.name.encode())
        h.update(str(sorted(me.keys())).encode())
    for mat in bpy.data.materials:
        h.update(repr([getattr(mat.edgelight, k) for k in ("use_rounding", "K", "radius", "angle")]).encode())
        h.update(repr(tuple(mat.diffuse_color)).encode())
        if mat.node_tree:
            for node in mat.node_tree.nodes:
                for socket in node.inputs:
                    if hasattr(socket, "default_value"):
                        v = socket.default_value
                        h.update(repr(tuple(v) if hasattr(v, "__len__") else v).encode())
    return h.hexdigest(), len(bpy.data.meshes), len(bpy.data.materials)


class UserDataUnchanged(unittest.TestCase):
    def test_render_changes_no_mesh_or_material(self):
        for name in ("cube", "fandisk", "prop", "toon"):
            helpers.open_sample(name, use_lines=True)
            before = fingerprint()
            helpers.render(resolution=(160, 120))
            self.assertEqual(before, fingerprint(), name)


class SettingsSurviveSaveAndReload(unittest.TestCase):
    def test_round_trip(self):
        import tempfile
        helpers.open_sample("cube", samples=5)
        s = bpy.data.materials["Cube"].edgelight
        s.K, s.radius, s.tint, s.selection, s.angle = 0.75, 0.033, (0.2, 0.4, 0.6), {'SHARP'}, 0.7
        s.use_custom_shininess, s.shininess = True, 123.0
        path = os.path.join(tempfile.mkdtemp(), "roundtrip.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        s = bpy.data.materials["Cube"].edgelight
        self.assertAlmostEqual(s.K, 0.75, places=6)
        self.assertAlmostEqual(s.radius, 0.033, places=6)
        self.assertEqual(tuple(round(c, 6) for c in s.tint), (0.2, 0.4, 0.6))
        self.assertEqual(set(s.selection), {'SHARP'})
        self.assertAlmostEqual(s.angle, 0.7, places=6)
        self.assertTrue(s.use_custom_shininess)
        self.assertEqual(s.shininess, 123.0)
        self.assertEqual(bpy.context.scene.edgelight.samples, 5)
        self.assertEqual(bpy.context.scene.render.engine, "EDGELIGHT")

    def test_lines_and_toon_round_trip(self):
        import tempfile
        helpers.open_sample("cube")
        sc = bpy.context.scene.edgelight
        sc.use_lines, sc.crease_angle, sc.marks, sc.hidden_lines, sc.debug = True, 0.9, {'SEAM'}, 'DIMMED', {'WIRE'}
        # The unit first: switching it converts the width.
        sc.line_contour.enabled, sc.line_contour.unit, sc.line_contour.width, sc.line_contour.taper = True, 'SCENE', 0.02, 0.25
        sc.line_silhouette.color = (0.1, 0.2, 0.3)
        m = bpy.data.materials["Cube"].edgelight
        m.shading, m.xtoon_axis, m.xtoon_far = 'RAMP', 'ORIENTATION', 33.0
        color_ramp = helpers.addon().extract.color_ramp
        m.shade_ramp = color_ramp.new_ramp([(pos, (pos, 0.5, 1.0 - pos)) for pos in (0.0, 0.4, 0.8)], 'LINEAR')
        path = os.path.join(tempfile.mkdtemp(), "lines.blend")
        bpy.ops.wm.save_as_mainfile(filepath=path)
        bpy.ops.wm.open_mainfile(filepath=path)
        sc = bpy.context.scene.edgelight
        self.assertTrue(sc.use_lines)
        self.assertAlmostEqual(sc.crease_angle, 0.9, places=6)
        self.assertEqual((set(sc.marks), sc.hidden_lines, set(sc.debug)), ({'SEAM'}, 'DIMMED', {'WIRE'}))
        c = sc.line_contour
        self.assertEqual((c.enabled, c.unit), (True, 'SCENE'))
        self.assertAlmostEqual(c.width, 0.02, places=6)
        self.assertAlmostEqual(c.taper, 0.25, places=6)
        self.assertEqual(tuple(round(v, 6) for v in sc.line_silhouette.color), (0.1, 0.2, 0.3))
        m = bpy.data.materials["Cube"].edgelight
        self.assertEqual((m.shading, m.xtoon_axis), ('RAMP', 'ORIENTATION'))
        stops, smooth = color_ramp.stops_of(m)
        self.assertEqual([round(p, 6) for p, _ in stops], [0.0, 0.4, 0.8])
        self.assertTrue(smooth)
        self.assertAlmostEqual(m.xtoon_far, 33.0, places=5)
        self.assertEqual(bpy.context.scene.render.engine, "EDGELIGHT")


if __name__ == "__main__":
    unittest.main()
