"""Ink lines in final renders: silhouettes, creases, borders, joins, taper, hidden lines,
widths in scene units, and the debug views."""
import math
import unittest

import bpy
import numpy as np

import helpers


def coverage(d, r):
    """line.frag.glsl's box-filtered coverage of a pixel at distance d from a stroke of half-width r."""
    return np.clip(np.minimum(d + r, 0.5) - np.maximum(d - r, -0.5), 0.0, 1.0)


def alpha_at(rec, xy):
    return helpers.sample(rec["lines"][..., 3], np.asarray(xy, float))


def cube_edges(size=2.0):
    h = size / 2
    corners = np.array([[x, y, z] for x in (-h, h) for y in (-h, h) for z in (-h, h)])
    edges = [(i, j) for i in range(8) for j in range(i + 1, 8) if np.sum(corners[i] != corners[j]) == 1]
    return corners, edges


def visible_cube_edges(corners, edges, eye):
    """An edge of a convex box is visible when one of its two faces faces the eye."""
    out = []
    for i, j in edges:
        a, b = corners[i], corners[j]
        mid = (a + b) / 2
        axis = np.flatnonzero(a == b)  # the two axes along which the edge sits on a face
        faces = [np.eye(3)[k] * np.sign(mid[k]) for k in axis]
        out.append(any(np.dot(n, np.asarray(eye) - mid) > 0 for n in faces))
    return out


def render_sphere(segments, rings, eye, **lines):
    """A unit UV sphere at the origin, smooth-shaded, with only the given line types."""
    scene = helpers.empty_scene(400, 400)
    helpers.only_lines(scene, **lines)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=segments, ring_count=rings, radius=1.0)
    bpy.ops.object.shade_smooth()
    helpers.add_camera(eye)
    helpers.add_sun()
    return helpers.render()


def ink_around(rec, centre):
    """Line alpha, and the radius (px) and angle (degrees) about `centre` of the inked pixels."""
    a = rec["lines"][..., 3]
    ys, xs = np.nonzero(a > 0.5)
    dx, dy = xs + 0.5 - centre[0], ys + 0.5 - centre[1]
    return a, a[ys, xs], np.hypot(dx, dy), np.degrees(np.arctan2(dy, dx)) % 360.0


def image_radius(rec, eye):
    """Radius in pixels of the image of a unit sphere's tangent cone seen from `eye`."""
    return rec["camera"].px_per_unit * math.tan(math.asin(1.0 / np.linalg.norm(eye)))


class Silhouettes(unittest.TestCase):
    def test_uv_sphere_silhouette_is_a_closed_ring_at_the_expected_radius(self):
        eye = (0.0, -6.0, 0.0)
        rec = render_sphere(96, 48, eye, silhouette=3.0)
        expected = image_radius(rec, eye)
        a, weight, r, angle = ink_around(rec, (200.0, 200.0))
        ring_r = np.average(r, weights=weight)
        print(f"silhouette ring: mean radius {ring_r:.2f} px, expected {expected:.2f} px, spread {r.min():.2f}..{r.max():.2f}")
        self.assertLess(abs(ring_r - expected), 0.5)
        self.assertLess(np.abs(r - expected).max(), 1.5 + 1.0)  # half the 3 px width plus a pixel
        bins = np.bincount((angle // 1.0).astype(int), minlength=360)
        self.assertTrue((bins > 0).all(), f"gaps at degrees {np.flatnonzero(bins == 0)}")
        # Nothing inside the ring: a sphere has no other silhouette from outside.
        inner = np.hypot(*np.meshgrid(np.arange(400) + 0.5 - 200.0, np.arange(400) + 0.5 - 200.0)) < expected - 3.0
        self.assertEqual(int((a[inner] > 0).sum()), 0)

    def test_smooth_contour_of_a_sphere_is_a_closed_ring_inside_the_faces(self):
        eye = (0.3, -6.0, 0.2)
        rec = render_sphere(24, 12, eye, contour=2.0)
        self.assertGreater(rec["stats"].lines_drawn, 20)
        _, _, r, angle = ink_around(rec, helpers.project(rec, [(0.0, 0.0, 0.0)])[0])
        bins = np.bincount((angle // 2.0).astype(int), minlength=180)
        self.assertTrue((bins > 0).all(), "closed: ink in every 2-degree sector")
        # A coarse sphere's interpolated contour runs inside the polygon outline, near the true circle.
        expected = image_radius(rec, eye)
        self.assertLess(abs(np.median(r) - expected), 0.05 * expected)


class Creases(unittest.TestCase):
    def render_cube(self, cuts=0, **scene_settings):
        scene = helpers.empty_scene(480, 480, **scene_settings)
        helpers.only_lines(scene, crease=3.0)
        bpy.ops.mesh.primitive_cube_add(size=2.0)
        if cuts:
            bpy.ops.object.mode_set(mode='EDIT')
            bpy.ops.mesh.subdivide(number_cuts=cuts)
            bpy.ops.object.mode_set(mode='OBJECT')
        self.eye = (4.0, -5.5, 3.5)
        helpers.add_camera(self.eye)
        helpers.add_sun()
        return helpers.render()

    def edge_alphas(self, rec):
        """Visibility per cube edge and the line alpha along its middle; points of hidden edges
        whose image passes within 3 px of a visible edge's image are NaN (not judged)."""
        corners, edges = cube_edges()
        vis = np.array(visible_cube_edges(corners, edges, self.eye))
        ts = np.linspace(0.25, 0.75, 11)
        shown = [helpers.project(rec, corners[[i, j]]) for (i, j), v in zip(edges, vis) if v]
        out = []
        for (i, j), v in zip(edges, vis):
            xy = helpers.project(rec, corners[i] + ts[:, None] * (corners[j] - corners[i]))
            a = alpha_at(rec, xy).astype(float)
            if not v:
                for p, q in shown:
                    u = np.clip((xy - p) @ (q - p) / np.dot(q - p, q - p), 0, 1)
                    a[np.linalg.norm(xy - (p + u[:, None] * (q - p)), axis=1) < 3.0] = np.nan
            out.append(a)
        return vis, np.array(out)

    def test_cube_shows_its_visible_creases_and_no_hidden_ones(self):
        vis, alpha = self.edge_alphas(self.render_cube())
        self.assertEqual(int(vis.sum()), 9)
        self.assertTrue((alpha[vis] > 0.99).all(), alpha[vis].min(axis=1))
        hidden = alpha[~vis]
        self.assertGreater(np.isfinite(hidden).sum(), 20, "enough points of hidden edges judged")
        self.assertTrue((hidden[np.isfinite(hidden)] == 0.0).all(), np.nanmax(hidden, axis=1))

    def test_hidden_creases_of_a_cube_drawn_in_two_batches(self):
        # Subdivided, the faces' middle triangles list no rounded silhouette's strip, and the
        # surface pass draws them apart from those along the edges (passes/batches.py): the
        # face ids the visibility reads must still be each triangle's own.
        rec = self.render_cube(cuts=4)
        el = helpers.addon()
        lib, error = el.host.engine.load_library()
        self.assertIsNotNone(lib, error)
        extract = el.extract.scene_sync.collect(bpy.context.evaluated_depsgraph_get(), lib=lib).instances[0].mesh
        listed = np.concatenate([np.any(rows > 0.0, axis=1) for rows in el.geometry.rounded_outline.records(extract)[2].values()])
        self.assertTrue(listed.any() and not listed.all(), "the faces drawn in two batches")
        vis, alpha = self.edge_alphas(rec)
        self.assertTrue((alpha[vis] > 0.99).all(), alpha[vis].min(axis=1))
        hidden = alpha[~vis]
        self.assertGreater(np.isfinite(hidden).sum(), 20, "enough points of hidden edges judged")
        self.assertTrue((hidden[np.isfinite(hidden)] == 0.0).all(), np.nanmax(hidden, axis=1))

    def test_hidden_creases_dimmed(self):
        vis, alpha = self.edge_alphas(self.render_cube(hidden_lines='DIMMED', hidden_opacity=0.3))
        self.assertTrue((alpha[vis] > 0.99).all())
        hidden = alpha[~vis]
        np.testing.assert_allclose(hidden[np.isfinite(hidden)], 0.3, atol=1e-4)

    def test_crease_angle_threshold_follows_auto_smooth_convention(self):
        scene = helpers.empty_scene(200, 200)
        helpers.only_lines(scene, crease=2.0)
        scene.edgelight.crease_angle = math.radians(90.5)  # a cube's edges are at 90 degrees
        bpy.ops.mesh.primitive_cube_add(size=2.0)
        helpers.add_camera((4.0, -5.5, 3.5))
        helpers.add_sun()
        rec = helpers.render()
        self.assertEqual(rec["stats"].lines_drawn, 0)
        scene.edgelight.crease_angle = math.radians(89.5)
        rec = helpers.render()
        self.assertEqual(rec["stats"].lines_drawn, 12)


class Borders(unittest.TestCase):
    def test_open_cylinder_shows_its_border_circles(self):
        scene = helpers.empty_scene(400, 400)
        helpers.only_lines(scene, border=3.0)
        bpy.ops.mesh.primitive_cylinder_add(vertices=64, radius=1.0, depth=2.0, end_fill_type='NOTHING')
        eye = np.array((0.0, -6.0, 4.0))
        helpers.add_camera(tuple(eye))
        helpers.add_sun()
        rec = helpers.render()
        self.assertEqual(rec["stats"].lines_drawn, 128)
        phi = np.linspace(0.0, 2.0 * math.pi, 360, endpoint=False)
        ring = np.c_[np.cos(phi), np.sin(phi), np.zeros_like(phi)]
        top = alpha_at(rec, helpers.project(rec, ring + (0, 0, 1.0)))
        self.assertTrue((top > 0.99).all(), f"top circle: {np.sum(top <= 0.99)} of 360 points without ink")
        # The bottom circle's front half (outward normal towards the eye) is in view.
        bottom = ring + (0, 0, -1.0)
        front = np.einsum("ij,ij->i", ring, eye - bottom) > 0.3
        low = alpha_at(rec, helpers.project(rec, bottom[front]))
        self.assertTrue((low > 0.99).all(), f"bottom front: {np.sum(low <= 0.99)} of {front.sum()} without ink")


class MarksAndMaterials(unittest.TestCase):
    def cube(self, **lines):
        scene = helpers.empty_scene(300, 300)
        helpers.only_lines(scene, **lines)
        bpy.ops.mesh.primitive_cube_add(size=2.0)
        helpers.add_camera((4.0, -5.5, 3.5))
        helpers.add_sun()
        return scene, bpy.context.object

    def test_marked_edges_follow_the_chosen_marks(self):
        scene, ob = self.cube(marked=2.0)
        me = ob.data
        helpers.mark_edge(me, "freestyle", 0)
        helpers.mark_edge(me, "seam", 1)
        helpers.mark_edge(me, "sharp", 2)
        counts = {}
        for marks in ({'FREESTYLE'}, {'SEAM'}, {'FREESTYLE', 'SHARP'}, {'FREESTYLE', 'SHARP', 'SEAM'}):
            scene.edgelight.marks = marks
            counts[tuple(sorted(marks))] = helpers.render()["stats"].lines_drawn
        self.assertEqual(list(counts.values()), [1, 1, 2, 3], counts)

    def test_material_boundaries(self):
        scene, ob = self.cube(material=2.0)
        for name in ("A", "B"):
            ob.data.materials.append(bpy.data.materials.new(name))
        self.assertEqual(helpers.render()["stats"].lines_drawn, 0)
        top = max(ob.data.polygons, key=lambda p: p.center.z)
        top.material_index = 1  # the top face's four edges now separate A from B
        self.assertEqual(helpers.render()["stats"].lines_drawn, 4)


class Joins(unittest.TestCase):
    def test_joins_leave_no_gap_at_a_cube_corner(self):
        """Round caps: around the corner where three creases meet, every pixel is covered at
        least as much as a disc of the stroke's radius covers it (the gap between unjoined stroke
        quads is a notch on the outside of the join)."""
        eye = (4.0, -5.5, 3.5)
        for width in (1.0, 4.0, 12.0):
            # A sharp corner: with the highlights on, the outline's is the fillets' (test_outline_lines).
            scene = helpers.empty_scene(480, 480, highlights=False)
            helpers.only_lines(scene, crease=width, silhouette=width)
            bpy.ops.mesh.primitive_cube_add(size=2.0)
            helpers.add_camera(eye)
            helpers.add_sun()
            rec = helpers.render()
            a = rec["lines"][..., 3]
            for corner in ((1.0, -1.0, 1.0), (1.0, -1.0, -1.0), (-1.0, -1.0, 1.0)):  # inner, outline
                c = helpers.project(rec, [corner])[0]
                r = width / 2.0
                xs, ys = np.meshgrid(np.arange(a.shape[1]) + 0.5, np.arange(a.shape[0]) + 0.5)
                d = np.hypot(xs - c[0], ys - c[1])
                near = d <= r + 0.5
                need = coverage(d[near], r) - 1e-4
                short = a[near] < need
                self.assertFalse(short.any(), f"width {width}, corner {corner}: {short.sum()} gap pixels, "
                                              f"worst {np.min(a[near] - need):.3f}")


class Taper(unittest.TestCase):
    def test_open_chain_tapers_to_its_free_ends(self):
        scene = helpers.empty_scene(600, 200)
        s = helpers.only_lines(scene, marked=10.0)
        s.line_marked.taper = 0.5
        bpy.ops.mesh.primitive_grid_add(x_subdivisions=20, y_subdivisions=2, size=4.0)
        mesh = bpy.context.object.data
        # Mark the middle row of edges (y = 0) for Freestyle: one open chain across the grid.
        co = np.array([v.co[:] for v in mesh.vertices])
        for e in mesh.edges:
            a, b = co[e.vertices[0]], co[e.vertices[1]]
            helpers.mark_edge(mesh, "freestyle", e.index, abs(a[1]) < 1e-6 and abs(b[1]) < 1e-6)
        helpers.add_camera((0.0, 0.0, 9.0), lens=50.0)
        helpers.add_sun((0.0, 0.0, 1.0))
        rec = helpers.render()
        a = rec["lines"][..., 3]
        xs = np.linspace(-1.9, 1.9, 39)
        widths = []
        for x in xs:
            px = helpers.project(rec, [(x, 0.0, 0.0)])[0]
            col = a[:, int(px[0])]
            widths.append(col.sum())  # ink across the line = its width in pixels
        widths = np.array(widths)
        # Taper 0.5: the width grows linearly from the ends to full at the middle.
        length = 4.0
        full = widths[len(xs) // 2]
        expected = 10.0 * np.clip((length / 2 - np.abs(xs)) / (0.5 * length), 0, 1)
        print("tapered widths:", np.round(widths[::4], 2))
        self.assertGreater(full, 9.0)
        np.testing.assert_allclose(widths, expected, atol=1.2)


class ScaleAndDebug(unittest.TestCase):
    def test_scene_unit_width_thins_with_distance_down_to_the_floor(self):
        scene = helpers.empty_scene(400, 400)
        s = helpers.only_lines(scene, border=2.0)
        s.line_border.unit = 'SCENE'  # converts the width (no camera yet: kept); set it after
        s.line_border.width = 0.05
        s.line_border.min_pixels = 2.0
        bpy.ops.mesh.primitive_plane_add(size=2.0)
        cam = helpers.add_camera((0.0, 0.0, 5.0))
        helpers.add_sun((0.0, 0.0, 1.0))
        widths = {}
        for dist in (5.0, 10.0, 80.0):
            cam.location = (0.0, 0.0, dist)
            rec = helpers.render()
            px = helpers.project(rec, [(0.0, -1.0, 0.0)])[0]
            widths[dist] = rec["lines"][:200, int(px[0]), 3].sum()  # the lower half: the y = -1 border only
            expected = max(0.05 * rec["camera"].px_per_unit / dist, 2.0)
            self.assertAlmostEqual(widths[dist], expected, delta=0.15 * expected + 0.2, msg=f"distance {dist}")
        print("scene-unit widths by distance:", {k: round(v, 2) for k, v in widths.items()})

    def test_whiteout_has_only_white_surface_pixels(self):
        scene = helpers.empty_scene(300, 300, debug={'WHITEOUT'})
        helpers.only_lines(scene, silhouette=2.0, crease=2.0)
        bpy.ops.mesh.primitive_monkey_add()
        helpers.add_camera((0.0, -5.0, 1.0))
        helpers.add_sun()
        rec = helpers.render()
        surf = rec["surface"][..., 3] == 1.0
        clear = surf & (rec["lines"][..., 3] == 0.0)
        self.assertGreater(clear.sum(), 5000)
        self.assertTrue(np.array_equal(rec["pixels"][clear][:, :3], np.ones((clear.sum(), 3), np.float32)))
        self.assertEqual(int((helpers.highlight_change(rec) > 0).sum()), 0, "no highlights in whiteout")
        self.assertGreater(int((rec["lines"][..., 3] > 0.99).sum()), 500, "the lines are drawn")

    def test_edge_types_view_colours_silhouettes_red_and_creases_yellow(self):
        scene = helpers.empty_scene(480, 480, debug={'EDGE_TYPES'})
        scene.edgelight.use_lines = False  # the debug view draws every type anyway
        # The sharp edges: with the highlights on, the silhouette moves in onto its fillet's
        # outline beside the crease (test_outline_lines).
        scene.edgelight.highlights = False
        bpy.ops.mesh.primitive_cube_add(size=2.0)
        eye = (4.0, -5.5, 3.5)
        helpers.add_camera(eye)
        helpers.add_sun()
        rec = helpers.render()
        ln = rec["lines"]
        # The top face's front edge is a crease inside the outline; the far top edge is on it.
        inner = helpers.project(rec, [(0.0, -1.0, 1.0)])[0]
        outline = helpers.project(rec, [(0.0, 1.0, 1.0)])[0]
        np.testing.assert_array_equal(helpers.sample(ln, inner)[:3], (1.0, 1.0, 0.0))
        np.testing.assert_array_equal(helpers.sample(ln, outline)[:3], (1.0, 0.0, 0.0))

    def test_wire_view_draws_every_edge(self):
        helpers.empty_scene(300, 300, debug={'WIRE'})
        bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=2)
        helpers.add_camera((0.0, -5.0, 1.0))
        helpers.add_sun()
        rec = helpers.render()
        self.assertEqual(rec["stats"].lines_drawn, len(bpy.data.objects["Icosphere"].data.edges))


if __name__ == "__main__":
    unittest.main()


class ContoursOnFlatFaces(unittest.TestCase):
    def render(self, make):
        scene = helpers.empty_scene(320, 240)
        helpers.add_camera((4.0, -6.0, 3.0))
        helpers.add_sun()
        make(scene)
        helpers.only_lines(scene, contour=2.0)
        return np.asarray(helpers.render()["lines"])[..., 3] > 0.25

    def test_a_flat_shaded_box_has_no_smooth_contours(self):
        """Smooth contours are where smooth shading turns from the eye: a flat-shaded box has
        none (the library's vertex normals would put some across its faces), while a smooth
        sphere keeps its contour."""
        helpers.needs_gpu()
        import bmesh

        import scene_zoo as zoo

        def boxes(scene):
            for i, angle in enumerate((0.0, 0.6, 1.1)):
                box = zoo.box(f"Box{i}", 1.2, ((i - 1) * 1.8, 0.0, 0.0))
                box.rotation_euler = (angle, 0.3 * i, angle)
                box.data.polygons.foreach_set("use_smooth", [False] * len(box.data.polygons))

        def ball(scene):
            mesh = bpy.data.meshes.new("Ball")
            bm = bmesh.new()
            bmesh.ops.create_uvsphere(bm, u_segments=32, v_segments=16, radius=1.0)
            bm.to_mesh(mesh)
            bm.free()
            mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
            scene.collection.objects.link(bpy.data.objects.new("Ball", mesh))

        self.assertEqual(int(self.render(boxes).sum()), 0, "contour strokes on flat-shaded boxes")
        self.assertGreater(int(self.render(ball).sum()), 100, "the smooth sphere keeps its contour")
