"""Silhouette lines on the rounded outline (addon/geometry/outline_lines.py, docs/lines.md): with the
highlights on, the surface pass pulls a rounded silhouette's outline in to the fillet's, and the
silhouette's ink follows it there; a crease along that edge does not trace the sharp edge past
the part, nor widen the outline's stroke where it overlaps it. Against the exact fillets' outline, row by row across a box's left and right sides."""
import importlib
import os
import sys
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo

sys.path.insert(0, os.path.join(helpers.ROOT, "bench"))
import fillets  # noqa: E402
import gt_scenes  # noqa: E402

RESOLUTION = (320, 240)
CAMERA = np.array((3.0, -4.0, 2.5))
INK = (1.0, 0.0, 0.0)


def box(width_px, mode, made="object"):
    """A unit box rounded at width_px pixels on a transparent film: 'fillets' (exact fillets,
    highlights and lines off: its alpha is the fillets' outline), 'lines' (highlights and red
    silhouettes and creases, 1.5 px) or 'sharp lines' (the same, highlights off). `made`: an
    'object', a 'mirrored collection instance' (an empty scaled -1 in x instancing it: the same
    image, since the box is symmetric, through a matrix that flips handedness) or a 'geometry
    nodes instance' (a Mesh Cube node's box instanced on one point, turned 90 degrees about z:
    the same image again)."""
    helpers.empty_scene(*RESOLUTION, samples=64 if mode == "fillets" else 8)
    helpers.add_camera(tuple(CAMERA))
    helpers.add_sun((0.5, -0.8, 0.6), 4.0)
    scene = bpy.context.scene
    scene.render.film_transparent = True
    mat = zoo.material("BoxMaterial", (0.8, 0.8, 0.8))
    mat.edgelight.radius = zoo.radius_at_width(width_px, CAMERA, RESOLUTION[0])
    if made == "geometry nodes instance":
        zoo.geometry_nodes(zoo.mesh_object("Host", [(5.0, 5.0, 5.0)], []), lambda n, ln, g: cube_instance(n, ln, mat))
    elif made == "mirrored collection instance":
        part = bpy.data.collections.new("Part")
        zoo.box("Box", collection=part).data.materials.append(mat)
        empty = bpy.data.objects.new("Mirror", None)
        empty.instance_type, empty.instance_collection = 'COLLECTION', part
        empty.scale = (-1.0, 1.0, 1.0)
        scene.collection.objects.link(empty)
    else:
        zoo.box("Box").data.materials.append(mat)
    s = scene.edgelight
    if mode == "fillets":
        fillets.add_fillets(scene, mat.edgelight.radius, 32, exact=True)
    else:
        s.use_lines = True
        for style in (s.line_silhouette, s.line_crease):
            style.color, style.width = INK, 1.5
    s.highlights = mode != "sharp lines"
    return np.asarray(helpers.render()["pixels"]).astype(np.float64)


def cube_instance(nodes, links, mat):
    point = nodes.new('GeometryNodePoints')
    point.inputs["Count"].default_value = 1
    cube = nodes.new('GeometryNodeMeshCube')
    for k in ("Vertices X", "Vertices Y", "Vertices Z"):
        cube.inputs[k].default_value = 2
    paint = nodes.new('GeometryNodeSetMaterial')
    paint.inputs["Material"].default_value = mat
    links.new(cube.outputs["Mesh"], paint.inputs["Geometry"])
    inst = nodes.new('GeometryNodeInstanceOnPoints')
    inst.inputs["Rotation"].default_value = (0.0, 0.0, np.pi / 2.0)
    links.new(point.outputs[0], inst.inputs["Points"])
    links.new(paint.outputs["Geometry"], inst.inputs["Instance"])
    return inst.outputs["Instances"]


def sides(alpha, rows):
    """Per row, where the coverage ends on the left and on the right (pixels, 0 at the left edge
    of the image): the part covers each side's last 8 pixels to its own area, so each side lies
    that area past the first wholly covered pixel (exact for an outline straight across them)."""
    out = []
    for y in rows:
        a = alpha[y]
        inside = np.flatnonzero(a >= 0.5)
        i, j = inside[0] + 4, inside[-1] - 4
        out.append((i - a[i - 8:i].sum(), j + 1 + a[j + 1:j + 9].sum()))
    return np.array(out)


def ink_centres(rgba, rows, near):
    """Per row, the centre of the red ink within 6 px of each of `near`'s (left, right) points,
    weighted by its redness over the other channels: its coverage, over the grey part or the
    transparent film alike (the pixels are premultiplied)."""
    red = np.clip(rgba[..., 0] - np.maximum(rgba[..., 1], rgba[..., 2]), 0.0, None)
    x = np.arange(rgba.shape[1]) + 0.5
    out = []
    for y, (left, right) in zip(rows, near):
        row = []
        for at in (left, right):
            w = np.where(np.abs(x - at) <= 6.0, red[y], 0.0)
            row.append(float((w * x).sum() / w.sum()) if w.sum() > 0.0 else np.nan)
        out.append(row)
    return np.array(out)


class SilhouetteLines(unittest.TestCase):
    def test_silhouette_ink_lies_on_the_fillets_outline(self):
        """At 8 px the strip moves the outline in by up to 0.41 r. The ink's centre, per row
        across the box's left and right silhouettes, against the fillets' outline: the sharp
        edge's lines lie that far outside it; EdgeLight's now lie on it. And no ink lies past
        it by more than the stroke's half width and a pixel (a crease left on the sharp edge
        would)."""
        ref = box(8.0, "fillets")[..., 3]
        rows = np.arange(94, 150, 4)  # clear of the corners, where the outline is the ball's circle
        outline = sides(ref, rows)
        for mode in ("lines", "sharp lines"):
            ink = ink_centres(box(8.0, mode), rows, outline)
            off = np.abs(ink - outline)
            print(f"{mode}: ink centre off the fillets' outline by {np.nanmean(off):.2f} px on average, "
                  f"{np.nanmax(off):.2f} at most ({np.isnan(off).sum()} of {off.size} without ink)")
            if mode == "sharp lines":
                self.assertGreater(np.nanmean(off), 1.5, "the sharp edge lies outside the fillets' outline")
        rgba = box(8.0, "lines")
        ink = ink_centres(rgba, rows, outline)
        off = np.abs(ink - outline)
        self.assertFalse(np.isnan(off).any(), "ink on every row")
        self.assertLess(float(off.max()), 0.3)
        red = rgba[..., 0] - np.maximum(rgba[..., 1], rgba[..., 2]) > 0.1
        past = 0
        for y, (left, right) in zip(rows, outline):
            x = np.flatnonzero(red[y]) + 0.5
            past += int(((x < left - 1.75) | (x > right + 1.75)).sum())
        print(f"ink past the fillets' outline by more than 1.75 px: {past} pixels")
        self.assertEqual(past, 0)

    def test_one_stroke_where_a_crease_runs_along_the_silhouette(self):
        """At 2 and 4 px the strip is a pixel or two wide, and the crease along a silhouette,
        still on the sharp edge, overlaps the moved silhouette's stroke; its ink over the strip
        is left out pixel by pixel, so the outline is one stroke: ink per row across each side
        (its coverage summed) is the 1.5 px stroke's, centred on the fillets' outline."""
        for width in (2.0, 4.0):
            ref = box(width, "fillets")[..., 3]
            rows = np.arange(94, 150, 4)
            outline = sides(ref, rows)
            rgba = box(width, "lines")
            red = np.clip(rgba[..., 0] - np.maximum(rgba[..., 1], rgba[..., 2]), 0.0, None)
            x = np.arange(rgba.shape[1]) + 0.5
            ink = np.array([[red[y][np.abs(x - at) <= 6.0].sum() for at in pair] for y, pair in zip(rows, outline)])
            off = np.abs(ink_centres(rgba, rows, outline) - outline)
            print(f"{width} px: ink per row {ink.mean():.2f} px ({ink.min():.2f} to {ink.max():.2f}), centre off the "
                  f"fillets' outline by {off.max():.2f} px at most")
            # Measured: 1.50 px everywhere, 0.04 off; 2.15 (up to 2.38) at 2 px and 1.68 (up to
            # 2.78) at 4 px with the crease drawn beside the moved silhouette.
            self.assertLess(float(np.abs(ink - 1.5).max()), 0.1, f"{width} px")
            self.assertLess(float(off.max()), 0.3, f"{width} px")

    def test_corners_follow_the_balls_circle(self):
        """At 8 px each of the box's outline corners is a corner patch's ball, and the fillets'
        outline there its circle: the ink goes round it. Measured as the distance of the red
        pixels outside the fillets' coverage from its edge, over the whole image: joined where
        their lines cross, the strokes overshot each corner."""
        inside = box(8.0, "fillets")[..., 3] >= 0.5
        rgba = box(8.0, "lines")
        edge = inside & ~(np.roll(inside, 1, 0) & np.roll(inside, -1, 0) & np.roll(inside, 1, 1) & np.roll(inside, -1, 1))
        red = rgba[..., 0] - np.maximum(rgba[..., 1], rgba[..., 2]) > 0.1
        ys, xs = np.nonzero(red & ~inside)
        by, bx = np.nonzero(edge)
        far = np.sqrt(((ys[:, None] - by[None]) ** 2 + (xs[:, None] - bx[None]) ** 2).min(axis=1))
        print(f"ink outside the fillets' outline: {len(far)} pixels, {int((far > 2.0).sum())} more than 2 px "
              f"from it, {far.max():.2f} px at most")
        # Measured: 2.00 at most, none past 2 px; 3.61 and 13 pixels past 2 px joined where the
        # lines cross.
        self.assertLess(float(far.max()), 2.5)

    def test_instances_and_mirrored_objects(self):
        """The move is computed per instance through its own matrix: a box instanced by
        Geometry Nodes (turned 90 degrees) and one through a collection instance mirrored in x
        (a matrix of negative determinant, whose normals the inverse transpose keeps outward)
        draw their silhouettes on the same fillets' outline as the plain object at 8 px."""
        ref = box(8.0, "fillets")[..., 3]
        rows = np.arange(94, 150, 4)
        outline = sides(ref, rows)
        for made in ("geometry nodes instance", "mirrored collection instance"):
            rgba = box(8.0, "lines", made)
            off = np.abs(ink_centres(rgba, rows, outline) - outline)
            print(f"{made}: ink centre off the fillets' outline by {np.nanmean(off):.2f} px on average, "
                  f"{np.nanmax(off):.2f} at most")
            self.assertFalse(np.isnan(off).any(), made)
            self.assertLess(float(off.max()), 0.3, made)

    def test_a_failed_move_leaves_the_objects_silhouettes_sharp_and_says_so(self):
        """Should moving an object's silhouettes fail (the library refusing el_outline_lines),
        the render goes on: that object's silhouettes stay on its sharp edges, and a report names
        it."""
        outline_lines = importlib.import_module(helpers.MODULE + ".geometry.outline_lines")
        native = importlib.import_module(helpers.MODULE + ".bridge.native")
        ref = box(8.0, "fillets")[..., 3]
        rows = np.arange(94, 150, 4)
        outline = sides(ref, rows)
        box(8.0, "lines")

        def fails(*args, **kwargs):
            raise native.NativeError("EL_ERR_INTERNAL", "a broken move")
        move, outline_lines.outline_of = outline_lines.outline_of, fails
        try:
            rec = helpers.render()
        finally:
            outline_lines.outline_of = move
        notes = [n for n in rec["reports"] if "silhouettes left on the sharp edges" in n]
        print(notes)
        self.assertEqual(len(notes), 1)
        self.assertIn("Box", notes[0])
        self.assertIn("a broken move", notes[0])
        off = np.abs(ink_centres(np.asarray(rec["pixels"]).astype(np.float64), rows, outline) - outline)
        self.assertGreater(float(np.nanmean(off)), 2.5, "the ink on the sharp edges, outside the fillets' outline")

    def test_a_side_runs_on_to_the_rims_moved_silhouette(self):
        """A 32-sided cylinder seen from above, its rims rounded at 8 px and its side not (its
        facets fold by 11.25 degrees): the silhouette is one closed loop, the far top rim, a
        side, the near bottom rim, the other side. The rims' segments move onto their fillets'
        outline; each side ends at the fillet's foot and a segment from there meets the rim's
        moved end (left on the sharp vertex, the side's stroke ran on past the moved rim).
        Every silhouette end's image meets another's."""
        lines = importlib.import_module(helpers.MODULE + ".linework.lines")
        helpers.empty_scene(*RESOLUTION, samples=1)
        helpers.add_camera((2.2, -3.0, 2.6))
        helpers.add_sun((0.5, -0.8, 0.6), 4.0)
        me = zoo.cylinder("Cylinder").data
        mat = zoo.material("CylinderMaterial", (0.8, 0.8, 0.8))
        mat.edgelight.radius = zoo.radius_at_width(8.0, np.array((2.2, -3.0, 2.6)), RESOLUTION[0])
        me.materials.append(mat)
        bpy.context.scene.edgelight.use_lines = True
        seen, silhouettes = [], lines.silhouettes
        lines.silhouettes = lambda *a, **k: seen.append(silhouettes(*a, **k)) or seen[-1]
        try:
            rec = helpers.render()
        finally:
            lines.silhouettes = silhouettes
        sil = seen[-1][0]
        ends = helpers.project(rec, np.concatenate([sil.p0, sil.p1]).astype(np.float64))
        gap = np.linalg.norm(ends[:, None] - ends[None], axis=2) + np.eye(len(ends)) * 1e9
        apart = gap.min(axis=1)
        print(f"{len(sil)} silhouette segments; an end's image from the nearest other end's {apart.max():.2e} px "
              f"at most")
        self.assertGreater(len(sil), 30)
        # Measured: 1e-4 px; 6.27 px with the sides' ends left on the sharp vertices.
        self.assertLess(float(apart.max()), 0.01)

    def test_a_long_side_silhouette_keeps_its_ink(self):
        """joint (libcgal-demo) seen along its cylinder, rounded at 4 px: the cylinder's side
        silhouette is one long segment between facets that fold by less than the crease angle,
        not moved, whose ends meet the rounded rims' moved silhouettes. Its ink over the block
        behind is as much with the highlights on as off: dragging its ends onto the rims' moved
        ones tilted it off its thin facets, and the line pass hid all but stubs of it."""
        verts, faces = gt_scenes.off_mesh("joint")
        lo, hi = verts.min(0), verts.max(0)
        verts = (verts - 0.5 * (lo + hi)) / (hi - lo).max()
        camera = np.array((2.8221626051507918, 0.5644325210301584, -0.8466487815452375))
        red = {}
        for highlights in (False, True):
            helpers.empty_scene(400, 300, samples=8)
            helpers.add_camera(tuple(camera))
            helpers.add_sun((0.5, -0.8, 0.6), 4.0)
            part = zoo.mesh_object("Joint", verts.tolist(), faces)
            mat = zoo.material("JointMaterial", (0.7, 0.7, 0.7))
            mat.edgelight.radius = zoo.radius_at_width(4.0, camera, 400)
            part.data.materials.append(mat)
            s = bpy.context.scene.edgelight
            s.use_lines, s.highlights = True, highlights
            s.line_silhouette.color, s.line_silhouette.width = INK, 1.5
            s.line_crease.color = (0.0, 1.0, 0.0)
            rgba = np.asarray(helpers.render()["pixels"]).astype(np.float64)[::-1]
            ink = rgba[..., 0] - np.maximum(rgba[..., 1], rgba[..., 2]) > 0.5
            red[highlights] = int(ink[105:130, 170:290].sum())
        print(f"the cylinder's side silhouette: {red[False]} red pixels with the highlights off, {red[True]} on")
        # Measured: 171 and 170 (the side ending at the fillets' feet); 11 on with the side's
        # ends dragged onto the rims' moved ones.
        self.assertGreater(red[False], 120, "the side's silhouette is in the window")
        self.assertGreater(red[True], 0.9 * red[False])


if __name__ == "__main__":
    unittest.main()
