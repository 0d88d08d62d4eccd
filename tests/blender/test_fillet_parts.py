"""Highlights on built parts against true fillets (bench/fillets.py: the Bevel modifier at the
same radius, 32 segments): each case is a way real parts broke the band before it was fixed."""
import math
import os
import sys
import unittest

import bmesh
import bpy
import numpy as np

import helpers
import scene_zoo as zoo

sys.path.insert(0, os.path.join(helpers.ROOT, "bench"))
import fillets  # noqa: E402
import gt_scenes  # noqa: E402
import parts  # noqa: E402
from gt_scenes import display  # noqa: E402

RESOLUTION = (480, 360)


def step_scene(radius, segments=0, highlights=True):
    """The step seen into its concave corner, lit from above and in front."""
    helpers.empty_scene(*RESOLUTION, samples=16 if segments else 1)
    helpers.add_camera((5.0, -3.0, 4.0))
    helpers.add_sun((0.5, -0.3, 0.8), 4.0)
    ob = zoo.rounded_part("Step", parts.l_step(), (0.6, 0.6, 0.6), radius)
    scene = bpy.context.scene
    scene.view_settings.view_transform = 'Standard'
    scene.edgelight.highlights = highlights
    if segments:
        fillets.add_fillets(scene, radius, segments)
    return ob


def radius_for(width_px, camera_location=(5.0, -3.0, 4.0)):
    """The radius whose image is width_px pixels at the origin (r f / d), 50 mm lens, for a
    camera at camera_location looking at the origin."""
    return zoo.radius_at_width(width_px, camera_location, RESOLUTION[0])


class ConcaveEdges(unittest.TestCase):
    """A concave edge's fillet fills the corner: its axis lies in the air, so the same arc of
    normals lies across the edge the other way round (docs/highlight_math.md, section 15)."""

    TS = np.linspace(0.2, 0.8, 7)
    OFFSETS = np.arange(-10.0, 10.5, 1.0)

    def profile(self, rec, a, b):
        return display(helpers.edge_profile(rec, np.asarray(rec["pixels"])[..., :3], a, b, self.TS, self.OFFSETS))

    def test_concave_band_matches_the_fillet(self):
        concave, convex = ((0, -1, 0), (0, 1, 0)), ((1, -1, 0), (1, 1, 0))
        for width in (1.0, 3.0):
            radius = radius_for(width)
            step_scene(radius, segments=32)
            truth = helpers.render()
            step_scene(radius)
            ours = helpers.render()
            step_scene(radius, highlights=False)
            sharp = helpers.render()
            errors = {}
            for name, (a, b) in (("concave", concave), ("convex", convex)):
                ref = self.profile(truth, a, b)
                errors[name] = (math.sqrt(np.mean((self.profile(ours, a, b) - ref) ** 2)),
                                math.sqrt(np.mean((self.profile(sharp, a, b) - ref) ** 2)))
            print(f"{width} px: RMSE against the fillet (EdgeLight, sharp): "
                  + ", ".join(f"{k} {v[0]:.4f} {v[1]:.4f}" for k, v in errors.items()))
            self.assertGreater(errors["concave"][1], 0.02, "the fillet changes the concave edge's image")
            # Measured on llvmpipe: 0.0026 (1 px) and 0.0013 (3 px); laid the convex way
            # round, 0.0104 at 1 px.
            self.assertLess(errors["concave"][0], 0.006, f"{width} px")
            self.assertLess(errors["concave"][0], 0.3 * errors["concave"][1], f"{width} px")
            self.assertLess(errors["concave"][0], errors["convex"][0] + 0.003, f"{width} px")


class FacesUnderTheBand(unittest.TestCase):
    """A band under a pixel or two wide, on an edge between a face lit past white and a dim one: the
    fillet replaces the faces under the band, so the band must take their share out, not the
    pixel's mean (docs/highlight_math.md, "The faces under the band"); and where the line crosses
    a pixel that shows only the two faces, the pixel is drawn whole, with no step left for the
    samples to alias."""

    TS = np.linspace(0.2, 0.8, 13)
    OFFSETS = np.arange(-3.0, 3.5, 1.0)
    EDGE = ((-1.0, -1.0, 1.0), (1.0, -1.0, 1.0))  # the top face's front edge

    def box_scene(self, radius, segments=0, highlights=True):
        helpers.empty_scene(*RESOLUTION, samples=64 if segments else 8)
        helpers.add_camera((5.0, -3.0, 4.0))
        helpers.add_sun((0.0, 0.0, 1.0), 12.0)  # the top face lit past white, the front by the world alone
        bm = bmesh.new()
        bmesh.ops.create_cube(bm, size=2.0)
        zoo.rounded_part("Box", bm, (0.6, 0.6, 0.6), radius)
        scene = bpy.context.scene
        scene.edgelight.highlights = highlights
        if segments:
            fillets.add_fillets(scene, radius, segments)

    def profile(self, rec):
        return display(helpers.edge_profile(rec, np.asarray(rec["pixels"])[..., :3], *self.EDGE, self.TS, self.OFFSETS))

    def test_band_replaces_the_faces_under_it(self):
        for width in (0.5, 1.0, 2.0):
            radius = radius_for(width)
            self.box_scene(radius, segments=32)
            ref = self.profile(helpers.render())
            self.box_scene(radius)
            ours = math.sqrt(np.mean((self.profile(helpers.render()) - ref) ** 2))
            self.box_scene(radius, highlights=False)
            sharp = math.sqrt(np.mean((self.profile(helpers.render()) - ref) ** 2))
            print(f"{width} px: RMSE against the fillet: EdgeLight {ours:.4f}, sharp {sharp:.4f}")
            self.assertLess(ours, 0.01, f"{width} px")
            self.assertLess(ours, 0.25 * sharp, f"{width} px")

    def test_teeth_in_front_keep_their_pixels(self):
        """pinion (libcgal-demo) at 0.3 px: its teeth pass in front of one another, each tooth's
        outline over the next one's rounded edges, in pixels whose 3 x 3 ids are all the part's.
        A pixel is drawn whole only where the depths around it continue the centre's too; without
        that check the outline's pixels lose the part of the tooth in front that their centres
        miss (PSNR there against the fillets: 32.5 dB, the sharp mesh 32.4; with it 33.5; 34.1
        against 32.8 since the outline also takes in the mesh's contour edges)."""
        width = 0.3
        scene = gt_scenes.open_scene("pinion", 0.01, 1, RESOLUTION)
        radius = width / gt_scenes.px_per_unit_at_centre(scene)
        images = {}
        for label, segments, highlights, samples in (("reference", 32, False, 64), ("ours", 0, True, 8), ("sharp", 0, False, 8)):
            scene = gt_scenes.open_scene("pinion", radius, samples, RESOLUTION)
            scene.edgelight.highlights = highlights
            if segments:
                fillets.add_fillets(scene, radius, segments)
            images[label] = helpers.render()
        ref = np.asarray(images["reference"]["pixels"])[..., :3]
        sharp = images["sharp"]
        covered = np.asarray(sharp["surface"])[..., 3] > 0.5
        changed = np.abs(display(ref) - display(np.asarray(sharp["pixels"])[..., :3])).max(axis=2) > 1.0 / 255.0
        changed |= helpers.highlight_change(images["ours"]) > 1.0 / 255.0
        outline = gt_scenes.regions(scene, changed, covered, width, np.asarray(sharp["depth"])[..., 0])["outline"]
        psnr = {k: gt_scenes.errors(np.asarray(images[k]["pixels"])[..., :3], ref, outline)[2] for k in ("ours", "sharp")}
        print(f"pinion at {width} px, outline ({int(outline.sum())} pixels): PSNR EdgeLight {psnr['ours']:.1f} dB, sharp {psnr['sharp']:.1f} dB")
        self.assertGreater(outline.sum(), 500)
        self.assertGreater(psnr["ours"], psnr["sharp"] + 0.6)


def spill(rec, margin=2):
    """What the highlight changes (helpers.highlight_change) summed over pixels more than `margin`
    pixels from the part's coverage, and how many such pixels there are: a fillet lies within its
    part's outline."""
    hl = helpers.highlight_change(rec)
    near = np.asarray(rec["surface"])[..., 3] > 0.5
    for _ in range(margin):
        near = near | np.roll(near, 1, 0) | np.roll(near, -1, 0) | np.roll(near, 1, 1) | np.roll(near, -1, 1)
    return float(hl[~near].sum()), int((hl[~near] > 1.0 / 255.0).sum())


class BandEnds(unittest.TestCase):
    """Bands end on their faces (addon/geometry/band_ends.py: cuts through the end vertices, mitres where
    rounded edges meet) and never show past the part's outline (the id image's fringe)."""

    def part_at(self, build, camera, width_px):
        helpers.empty_scene(*RESOLUTION)
        helpers.add_camera(camera)
        helpers.add_sun((0.5, -0.3, 0.8), 4.0)
        zoo.rounded_part("Part", build(), (0.6, 0.6, 0.6), radius_for(width_px, camera))
        return helpers.render()

    def test_bands_stay_within_the_outline(self):
        # Measured on llvmpipe before the cuts and the fringe: the step's corners 40.9 (52 px),
        # the gear's teeth seen end-on at the outline 22.7 (35 px); now 0 and 0 (5.3 without the
        # fringe).
        cases = (("step's outline corners", parts.l_step, (5.0, -3.0, 4.0)),
                 ("gear's teeth end-on at the outline", parts.gear, (0.9, -4.5, 1.2)))
        for name, build, camera in cases:
            weight, count = spill(self.part_at(build, camera, 8.0))
            print(f"{name} at 8 px: band weight {weight:.3f} in {count} pixels past the outline")
            self.assertLess(weight, 0.5, name)

    def test_box_corner_bands_mitre(self):
        """Two rounded edges at a corner of a box's top face (the material rounds only the edges
        marked sharp, the horizontal ones, so no ball rounds the corner: docs/highlight_math.md,
        "Corner patches"): the two bands
        end on the corner's diagonal, where two fillets meet. Points of the top face 0.3 r from
        one edge and 0.8 r from the other lie on the nearer edge's fillet, so they show that
        band as it is halfway along its edge; square ends left both bands there, the one drawn
        last on top."""
        bm = bmesh.new()
        bmesh.ops.create_cube(bm, size=2.0)
        for e in bm.edges:
            e.smooth = abs(e.verts[0].co.z - e.verts[1].co.z) > 1e-6  # the horizontal edges marked sharp
        helpers.empty_scene(*RESOLUTION)
        helpers.add_camera((4.0, -5.0, 6.0))
        helpers.add_sun((0.0, 0.0, 1.0), 4.0)
        ob = zoo.rounded_part("Box", bm, (0.6, 0.6, 0.6), radius_for(8.0, (4.0, -5.0, 6.0)))
        ob.data.materials[0].edgelight.selection = {'SHARP'}
        rec = helpers.render()
        hl = np.asarray(rec["highlight"])
        r = ob.data.materials[0].edgelight.radius
        for near_corner, mid_edge in (((1.0 - 0.8 * r, -1.0 + 0.3 * r, 1.0), (0.0, -1.0 + 0.3 * r, 1.0)),
                                      ((1.0 - 0.3 * r, -1.0 + 0.8 * r, 1.0), (1.0 - 0.3 * r, 0.0, 1.0))):
            c_corner, c_mid = (helpers.sample(hl, xy) for xy in helpers.project(rec, [near_corner, mid_edge]))
            self.assertGreater(c_mid[3], 0.5)
            self.assertGreater(c_corner[3], 0.5)
            lum = [float(helpers.luminance(c[:3] / c[3])) for c in (c_corner, c_mid)]
            print(f"band at {np.round(near_corner, 3)}: {lum[0]:.4f}, halfway along its edge {lum[1]:.4f}")
            # The view turns between the two points: measured 4.6 % (Blender 3.4) and 7.6 % (5.0)
            # apart on the same band; 24 % and 30 % with square ends.
            self.assertLess(abs(lum[0] - lum[1]), 0.1 * lum[1])


class FilletReference(unittest.TestCase):
    """The reference itself (bench/fillets.py): every fillet meets its faces r tan(a / 2) from
    the edge, also where triangulated faces put diagonals at the fillet's ends (CAD meshes:
    joint, anchor). With the Bevel modifier's loop slide on, those diagonals pulled a 90-degree
    fillet's setbacks to about 0.58 r and 0.39 r, and EdgeLight's concave bands were scored
    against half-size fillets."""

    def test_setback_on_triangulated_faces(self):
        """The step (bench/parts.py) with every face triangulated: the concave edge's fillet meets
        both faces r from the edge at 10, 50 and 90 % along it (cross-sections of the modifier's
        mesh)."""
        helpers.empty_scene(*RESOLUTION)
        bm = parts.l_step()
        bmesh.ops.triangulate(bm, faces=bm.faces[:])
        bm.normal_update()
        concave = [e for e in bm.edges if len(e.link_faces) == 2 and not e.is_convex and e.calc_face_angle(0.0) > 0.5]
        self.assertEqual(len(concave), 1)
        e = concave[0]
        p0, p1 = (np.array(v.co[:]) for v in e.verts)
        planes = [(np.array(f.normal[:]), np.array(f.verts[0].co[:])) for f in e.link_faces]
        radius = 0.1
        ob = zoo.rounded_part("Step", bm, (0.6, 0.6, 0.6), radius)
        fillets.add_fillets(bpy.context.scene, radius, 8)
        evaluated = ob.evaluated_get(bpy.context.evaluated_depsgraph_get())
        me = evaluated.to_mesh()
        co = np.array([v.co[:] for v in me.vertices])
        ends = np.array([ed.vertices[:] for ed in me.edges])
        evaluated.to_mesh_clear()
        axis = (p1 - p0) / np.linalg.norm(p1 - p0)
        for frac in (0.1, 0.5, 0.9):
            # The modifier's mesh cut square to the edge: where its edges cross that plane.
            s0, s1 = ((co[ends[:, k]] - p0) @ axis - frac * np.linalg.norm(p1 - p0) for k in (0, 1))
            cross = s0 * s1 < 0.0
            w = (s0[cross] / (s0[cross] - s1[cross]))[:, None]
            pts = co[ends[cross, 0]] * (1.0 - w) + co[ends[cross, 1]] * w
            off_line = (pts - p0) - np.outer((pts - p0) @ axis, axis)
            for n, q in planes:
                on = np.abs((pts - q) @ n) < 1e-5
                setback = float(np.linalg.norm(off_line[on], axis=1).min())
                print(f"{frac:.0%} along: the fillet meets the face with normal {np.round(n, 3)} {setback / radius:.4f} r from the edge")
                self.assertAlmostEqual(setback / radius, 1.0, delta=1e-3)


def ground_truth_regions(name, width_px, ref_samples=64, harden=True):
    """bench/ground_truth.py's comparison of one part at one width, in its framing: EdgeLight's
    and the reference's display values (the Bevel modifier's fillets, 32 segments, highlights
    off; `harden`: fillets.add_fillets'), gt_scenes.regions' masks and EdgeLight's record."""
    scene = gt_scenes.open_scene(name, 0.01, 1, gt_scenes.RESOLUTION)
    radius = width_px / gt_scenes.px_per_unit_at_centre(scene)
    scene = gt_scenes.open_scene(name, radius, ref_samples, gt_scenes.RESOLUTION)
    fillets.add_fillets(scene, radius, 32, harden=harden)
    ref = display(np.asarray(helpers.render()["pixels"])[..., :3])
    scene = gt_scenes.open_scene(name, radius, 8, gt_scenes.RESOLUTION)
    rec = helpers.render()
    ours = display(np.asarray(rec["pixels"])[..., :3])
    band = np.abs(np.asarray(rec["highlight"])).max(axis=-1)
    scene.edgelight.highlights = False
    off = helpers.render()
    changed = (np.abs(ref - display(np.asarray(off["pixels"])[..., :3])).max(axis=2) > 1.0 / 255.0) | (band > 1.0 / 255.0)
    covered = np.asarray(off["surface"])[..., 3] > 0.5
    region = gt_scenes.regions(scene, changed, covered, width_px, np.asarray(off["depth"])[..., 0])
    return ours, ref, region, rec


def oblique_ring_pixels(rec, ring_radius, ring_z, width_px, min_cos=0.7):
    """Pixels within the bands' reach of the hollow shaft's ring (radius, height in bench/parts.py's
    units) where its edges are seen within acos(min_cos) of the view: where its image turns."""
    verts, _ = gt_scenes.built_mesh("hollow_shaft")
    ob = next(o for o in bpy.context.scene.objects if o.type == 'MESH')
    on = np.flatnonzero((np.abs(np.hypot(verts[:, 0], verts[:, 1]) - ring_radius) < 1e-4) & (np.abs(verts[:, 2] - ring_z) < 1e-4))
    on = on[np.argsort(np.arctan2(verts[on, 1], verts[on, 0]))]
    world = np.array([tuple(ob.matrix_world @ ob.data.vertices[int(i)].co) for i in on])
    eye = np.array(bpy.context.scene.camera.matrix_world.translation)
    pts = []
    for a, b in zip(world, np.roll(world, -1, axis=0)):
        e, v = (b - a) / np.linalg.norm(b - a), eye - 0.5 * (a + b)
        if abs(np.dot(e, v / np.linalg.norm(v))) > min_cos:
            pts += [a + t * (b - a) for t in np.linspace(0.0, 1.0, 9)]
    shape = np.asarray(rec["pixels"]).shape[:2]
    yy, xx = np.mgrid[0:shape[0], 0:shape[1]] + 0.5
    near = np.zeros(shape, bool)
    for x, y in helpers.project(rec, np.array(pts)) if pts else []:
        near |= (xx - x) ** 2 + (yy - y) ** 2 < (3.0 + 1.5 * width_px) ** 2
    return near


class ConcaveRing(unittest.TestCase):
    def test_a_ring_seen_along_its_edges(self):
        """The hollow shaft (bench/parts.py) at 2 and 4 px: its shoulder's concave ring is a
        chain of edges whose normals turn along it, and where its image turns it is seen nearly
        along them, where each pixel sees the fillet's cross-section of a point on along the
        edge, with that point's normals (docs/highlight_math.md, "Along the line"). With the
        foot's normals the band there was darker than the fillet. RMSE against the fillets on
        the ring's concave pixels where its edges lie within 45 degrees of the view. The
        fillets' normals are the mesh's own smoothing: hardened, Blender 3.4 and 4.1+ shade
        this ring's fillet differently there (fillets.add_fillets)."""
        for width in (2.0, 4.0):
            ours, ref, region, rec = ground_truth_regions("hollow_shaft", width, harden=False)
            m = region["concave"] & oblique_ring_pixels(rec, 0.55, 0.1, width)
            rmse = math.sqrt(float(np.mean((ours[m] - ref[m]) ** 2)))
            print(f"hollow shaft at {width} px: {int(m.sum())} concave pixels where the ring is seen along its edges, "
                  f"RMSE {rmse:.4f}; all concave {psnr(ours, ref, region['concave']):.2f} dB, "
                  f"convex {psnr(ours, ref, region['convex']):.2f} dB")
            self.assertGreater(m.sum(), 50)
            # Measured: 0.0040 and 0.0037 (3.4), 0.0019 and 0.0019 (4.2-5.0); with the foot's
            # normals 0.0049 and 0.0059 (3.4), 0.0038 and 0.0061 (4.2).
            self.assertLess(rmse, 0.0045, f"{width} px")


def psnr(a, b, m):
    return 10.0 * math.log10(1.0 / max(float(np.mean((a[m] - b[m]) ** 2)), 1e-12))


class CoincidentVertices(unittest.TestCase):
    def test_cow_keeps_its_bands_on_itself(self):
        """cow.off has two vertices at one position (not welded: a pinch where two fans touch).
        Its folds there threw bands far into the background (in the fandisk sample's framing at
        1280 x 720: 111 pixels at 4 px, 377 at 8 px, and 2.8 of band weight at 1 px with square
        ends). The radius clamp, the bands' cuts at their ends and the outline's fringe keep every
        band on the cow, at every width."""
        for width in (1.0, 4.0, 8.0):
            scene = gt_scenes.open_scene("cow", 0.01, 1, (1280, 720))
            radius = width / gt_scenes.px_per_unit_at_centre(scene)
            for mat in bpy.data.materials:
                mat.edgelight.radius = radius
            weight, count = spill(helpers.render())
            print(f"cow at {width} px: band weight {weight:.3f} in {count} pixels past the outline")
            self.assertLess(weight, 0.5, f"{width} px")


if __name__ == "__main__":
    unittest.main()
