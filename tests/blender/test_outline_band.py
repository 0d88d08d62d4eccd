"""A silhouette's band hides nothing of what lies past the outline (docs/highlight_math.md, "The
band at the outline"): a box's fillet lies on its front face, so what the pixels at the outline
show of a backdrop behind the box does not depend on the highlights. And the outline is the
fillets' ("The fillet's outline"): the strip between a sharp silhouette edge and its fillet's
outline shows what lies behind, as the box with real fillets does."""
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


def box_before_backdrop(width_px, backdrop_rgb, mode):
    """A unit box, its edges rounded at width_px pixels, before a large backdrop square to the view
    (its own colour `backdrop_rgb`), lit by a sun from the front right: mode 'edgelight'
    (highlights on), 'outline' (on, with bands too faint to draw: the rounded outline alone),
    'sharp' (off) or 'fillets' (exactly circular fillets, highlights off, 64 samples)."""
    # Shadows off: the box's shadow on the backdrop is not what these measure (docs/shadows.md).
    helpers.empty_scene(*RESOLUTION, samples=64 if mode == "fillets" else 8, use_shadows=False)
    helpers.add_camera(tuple(CAMERA))
    helpers.add_sun((0.5, -0.8, 0.6), 4.0)
    cube = zoo.box("Box")
    mat = zoo.material("BoxMaterial", (0.8, 0.8, 0.8))
    mat.edgelight.radius = zoo.radius_at_width(width_px, CAMERA, RESOLUTION[0])
    if mode == "outline":
        mat.edgelight.K = 1e-4  # under an 8-bit step: the edge pass culls every band
    cube.data.materials.append(mat)
    if mode == "fillets":  # before the backdrop, which has no edge to round
        fillets.add_fillets(bpy.context.scene, mat.edgelight.radius, 32, exact=True)
    d = -CAMERA / np.linalg.norm(CAMERA)
    u = np.cross(d, (0.0, 0.0, 1.0))
    u /= np.linalg.norm(u)
    v = np.cross(u, d)
    c = 3.0 * d
    corners = [tuple(c + 20.0 * (a * u + b * v)) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    back = zoo.mesh_object("Backdrop", corners, [(0, 1, 2, 3)])
    back.data.materials.append(zoo.material("BackdropMaterial", backdrop_rgb))
    bpy.context.scene.edgelight.highlights = mode in ("edgelight", "outline")


class BandAtTheOutline(unittest.TestCase):
    def test_band_hides_nothing_past_the_outline(self):
        """At 0.5 and 1 px (wider bands lie inside the outline's pixels): on the pixels the
        outline crosses (those whose colour depends on the backdrop's, partly) that lie mostly on
        the box, the change that the backdrop's colour makes is the same with the bands as with
        the rounded outline alone. A band laid over the samples as a layer hid W of the backdrop
        there too. And how much of the backdrop each outline pixel shows is near the fillets':
        the sharp outline shows too little of it, where the fillets pull the outline in."""
        for width in (0.5, 1.0):
            seen = {}
            for mode in ("sharp", "outline", "edgelight", "fillets"):
                img = {}
                for name, rgb in (("dark", (0.0, 0.0, 0.0)), ("light", (0.9, 0.9, 0.9))):
                    box_before_backdrop(width, rgb, mode)
                    img[name] = np.asarray(helpers.render()["pixels"])[..., :3].astype(np.float64)
                seen[mode] = (img["light"] - img["dark"]).max(axis=2)
            full = np.percentile(seen["sharp"], 99.0)  # where only the backdrop shows
            share = seen["outline"] / full
            # The outline's pixels mostly on the box (their centres on it): past the outline
            # the band stays a layer, since the samples there may all miss the face.
            mostly_box = (share > 0.05) & (share < 0.45)
            hidden = (seen["outline"] - seen["edgelight"])[mostly_box]
            ref_share = seen["fillets"] / full
            outline = (ref_share > 0.02) & (ref_share < 0.98)
            err = {m: float(np.abs(seen[m] - seen["fillets"])[outline].mean()) for m in ("sharp", "edgelight")}
            print(f"{width} px: {int(mostly_box.sum())} outline pixels mostly on the box; the backdrop's change "
                  f"hidden by the bands: mean {hidden.mean():.5f} (of {full:.3f}), {int((np.abs(hidden) > 0.01).sum())} "
                  f"pixels over 0.01, worst {np.abs(hidden).max():.4f}; the backdrop's share off the fillets' by "
                  f"{err['sharp']:.4f} with the sharp outline, {err['edgelight']:.4f} with EdgeLight's")
            self.assertGreater(int(mostly_box.sum()), 50)
            # Measured: mean 0.0028 and 0, 2 and 0 pixels over 0.01 (one at 0.23: a silhouette's corner,
            # whose centre shows the box's third face: there the band stays a layer); the band as a layer everywhere: 0.033 at 0.5 px, 103 pixels
            # over 0.01. The sharp outline is off the fillets' by 0.220 and 0.398, the layer's by
            # 0.086 and 0.111.
            self.assertLess(abs(float(hidden.mean())), 0.005, f"{width} px")
            self.assertLessEqual(int((np.abs(hidden) > 0.01).sum()), 3, f"{width} px")
            self.assertLess(err["edgelight"], 0.5 * err["sharp"], f"{width} px")


class WideBandAtTheOutline(unittest.TestCase):
    def test_outline_pixels_past_the_centre_take_the_band(self):
        """At 4 and 8 px, the outline's pixels whose centres lie past it (the world behind) still
        show the fillet's horizon on the samples that hit the box: the band changes the face
        those samples show (el_silhouette_band), as it does where the centre lies on the face.
        Their colours against the fillets', over the pixels the fillets' outline crosses."""
        for width, bound in ((4.0, 0.052), (8.0, 0.067)):
            ref = box_render(width, "fillets", transparent=False)[..., :3]
            el = box_render(width, "edgelight", transparent=False)[..., :3]
            cov = box_coverage(width, "fillets")
            outline = (cov > 0.02) & (cov < 0.98)
            err = np.abs(el - ref).max(axis=2)[outline]
            print(f"{width} px: {int(outline.sum())} outline pixels, colour off the fillets' by {err.mean():.4f} "
                  f"(95th percentile {np.percentile(err, 95):.4f})")
            # Measured: 0.0466 and 0.0603; 0.0580 and 0.0754 with no band over those pixels.
            self.assertGreater(int(outline.sum()), 200)
            self.assertLess(float(err.mean()), bound, f"{width} px")


def box_render(width_px, mode, ortho=False, camera=CAMERA, cuts=0, transparent=True):
    """The pixels of a unit box, its edges rounded at width_px pixels, on a transparent film or
    before the world's colour: mode 'edgelight' (highlights on), 'sharp' (off) or 'fillets' (the
    Bevel modifier's exactly circular fillets, highlights off, 64 samples). With `cuts`, its
    faces are grids of (cuts + 1)^2 quads."""
    helpers.empty_scene(*RESOLUTION, samples=64 if mode == "fillets" else 8)
    cam = helpers.add_camera(tuple(camera))
    helpers.add_sun((0.5, -0.8, 0.6), 4.0)
    scene = bpy.context.scene
    scene.render.film_transparent = transparent
    cube = zoo.box("Box")
    if cuts:
        import bmesh
        bm = bmesh.new()
        bm.from_mesh(cube.data)
        bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=cuts, use_grid_fill=True)
        bm.to_mesh(cube.data)
        bm.free()
    mat = zoo.material("BoxMaterial", (0.8, 0.8, 0.8))
    radius = zoo.radius_at_width(width_px, np.asarray(camera), RESOLUTION[0])
    if ortho:
        cam.data.type = 'ORTHO'
        cam.data.ortho_scale = 3.0
        radius = width_px * cam.data.ortho_scale / RESOLUTION[0]
    mat.edgelight.radius = radius
    cube.data.materials.append(mat)
    if mode == "fillets":
        fillets.add_fillets(scene, radius, 32, exact=True)
    scene.edgelight.highlights = mode == "edgelight"
    return np.asarray(helpers.render()["pixels"]).astype(np.float64)


def box_coverage(width_px, mode, ortho=False, camera=CAMERA, cuts=0):
    """The box's alpha (coverage) on a transparent film (box_render)."""
    return box_render(width_px, mode, ortho, camera, cuts)[..., 3]


class FilletOutline(unittest.TestCase):
    def test_outline_is_the_fillets(self):
        """Coverage against the real fillets', summed over the image (pixels of coverage), at 4
        and 8 px in perspective and at 8 px seen orthographically. The sharp mesh's outline
        lies r (|P.C| - 1) outside the fillets' along the edges, and past each corner's ball."""
        for width, ortho in ((4.0, False), (8.0, False), (8.0, True)):
            ref = box_coverage(width, "fillets", ortho)
            sharp = np.abs(box_coverage(width, "sharp", ortho) - ref)
            el = np.abs(box_coverage(width, "edgelight", ortho) - ref)
            print(f"{width} px{' ortho' if ortho else ''}: coverage off by {sharp.sum():.1f} pixels with the sharp "
                  f"outline, {el.sum():.1f} with EdgeLight's; worst pixel {sharp.max():.2f} / {el.max():.2f}")
            # Measured: 4 px 597.6 -> 29.6, 8 px 1193.5 -> 36.5, ortho 8 px 1650.3 -> 44.1; the
            # strips alone, with the corners sharp: 52.8, 90.4, 96.6 (0.088 of the sharp outline's
            # at 4 px); no strips: the sharp outline's.
            self.assertGreater(sharp.sum(), 100.0 * width, "the sharp outline differs from the fillets'")
            self.assertLess(el.sum(), 0.07 * sharp.sum(), f"{width} px")

    def test_a_face_seen_at_a_grazing_angle_leaves_the_strip(self):
        """The box with its faces cut into 20 x 20 cells (0.05 wide: between the strip's width
        and the setback at 8 px), the eye a little below the top face's plane: the top face,
        behind the silhouettes along its front edges, folds its image over their strips from
        cells well past the strip's width (up to the fillet's setback, r at these 90-degree
        edges). Those cells must leave the strip too."""
        camera = np.array((3.0, -4.0, 0.42))
        # The fillets on the box uncut: the Bevel modifier cannot set a fillet back past the
        # next cell (it comes out narrower), and the cut box is the same solid.
        ref = box_coverage(8.0, "fillets", camera=camera)
        sharp = np.abs(box_coverage(8.0, "sharp", camera=camera, cuts=19) - ref)
        el = np.abs(box_coverage(8.0, "edgelight", camera=camera, cuts=19) - ref)
        print(f"grazing: coverage off by {sharp.sum():.1f} pixels with the sharp outline, {el.sum():.1f} with "
              f"EdgeLight's; worst pixel {sharp.max():.2f} / {el.max():.2f}")
        # Measured: 879.8 pixels sharp, 40.8 EdgeLight; 204.0 with the cells listed only within
        # the strip's width of the edge (the grazing face's cells past it showed in the strip).
        self.assertGreater(sharp.sum(), 500.0, "the sharp outline differs from the fillets'")
        self.assertLess(el.sum(), 0.07 * sharp.sum())


def flange_coverage(width_px, fillet):
    """The flange (bench/parts.py: a plate with a boss and six bolt holes) in the ground truth's
    framing, rounded at width_px pixels, on a transparent film: its alpha, with the exactly
    circular fillets (highlights off) or with EdgeLight's."""
    scene = gt_scenes.open_scene("flange", 0.01, 1, gt_scenes.RESOLUTION)
    radius = width_px / gt_scenes.px_per_unit_at_centre(scene)
    scene = gt_scenes.open_scene("flange", radius, 8, gt_scenes.RESOLUTION)
    scene.render.film_transparent = True
    if fillet:
        fillets.add_fillets(scene, radius, 32, exact=True)
    scene.edgelight.highlights = not fillet
    return np.asarray(helpers.render()["pixels"])[..., 3].astype(np.float64)


class StripEnds(unittest.TestCase):
    def test_a_bolt_holes_strips_reach_no_farther_than_their_edges(self):
        """A bolt hole seen obliquely at 8 px: near the ends of its rim's silhouette the rim's
        edges are shorter on screen than their strips are wide. A strip's end is a half disc of
        its width, and there it reached past the next edges, whose strips narrow, taking away
        face that the fillets keep (docs/highlight_math.md, "The fillet's outline"). Coverage
        the part lacks against its fillets, summed and in its worst 3 x 3 pixels."""
        ref = flange_coverage(8.0, True)
        lost = np.clip(ref - flange_coverage(8.0, False), 0.0, None)
        window = sum(np.roll(np.roll(lost, dy, 0), dx, 1) for dy in (-1, 0, 1) for dx in (-1, 0, 1))
        print(f"coverage lost against the fillets: {lost.sum():.1f} pixels, {window.max():.2f} in the worst 3 x 3")
        # Measured: 32.5 pixels, 4.88 in the worst 3 x 3; 34.8 and 5.75 where a disc counted
        # with any other strip's end near, not only one at its vertex (the rim's edges before
        # the last are shorter than the strip is wide); 39.2 and 5.75 with every disc; 58.7 and
        # 8.0 with discs of the strip's full width.
        self.assertGreater(ref.sum(), 10000.0, "the flange is in view")
        self.assertLess(lost.sum(), 40.0)
        self.assertLess(window.max(), 5.5)


def cylinder_coverage(width_px, fillet):
    """A 32-sided cylinder as Blender's Cylinder is made (n-gon caps, which Blender triangulates
    into long slivers), its rims rounded at width_px pixels, seen from above on a transparent
    film: its alpha, with the exactly circular fillets (highlights off) or with EdgeLight's."""
    camera = np.array((2.2, -3.0, 2.6))
    helpers.empty_scene(*RESOLUTION, samples=64 if fillet else 8)
    helpers.add_camera(tuple(camera))
    helpers.add_sun((0.5, -0.8, 0.6), 4.0)
    scene = bpy.context.scene
    scene.render.film_transparent = True
    me = zoo.cylinder("Cylinder").data
    mat = zoo.material("CylinderMaterial", (0.8, 0.8, 0.8))
    mat.edgelight.radius = zoo.radius_at_width(width_px, camera, RESOLUTION[0])
    me.materials.append(mat)
    if fillet:
        fillets.add_fillets(scene, mat.edgelight.radius, 32, exact=True)
    scene.edgelight.highlights = not fillet
    return np.asarray(helpers.render()["pixels"])[..., 3].astype(np.float64)


class NgonCap(unittest.TestCase):
    def test_a_caps_slivers_leave_their_far_rims_strips(self):
        """The cap's triangles are slivers whose chords cut across the reach of rims none of
        their corners touches, and each lies in the reach of up to eight rims: listed four at a
        time, walked by corners alone, the far rim's silhouette kept blocks of the cap above the
        fillets' outline. Coverage past the fillets', summed."""
        for width, bound in ((4.0, 40.0), (8.0, 120.0)):
            ref = cylinder_coverage(width, True)
            past = np.clip(cylinder_coverage(width, False) - ref, 0.0, None)
            print(f"{width} px: coverage past the fillets' {past.sum():.1f} pixels")
            # Measured: 26.8 and 83.3 pixels; 69.4 and 191.5 with four rims a triangle, walked
            # by corners alone.
            self.assertGreater(ref.sum(), 5000.0, "the cylinder is in view")
            self.assertLess(past.sum(), bound, f"{width} px")


STEP_CAMERA = np.array((-3.0, -4.0, 2.5))


def step_render(width_px, fillet):
    """bench/parts.py's step (floor z = 0 for x in 0..1, riser x = 0 up to the top z = 1 at x < 0,
    its L-shaped ends at y = +-1), rounded at width_px pixels, seen from behind its riser on a
    transparent film: the end face y = -1 and the floor face the eye, the riser does not. The
    silhouette between the end face and the riser ends at the L's inside corner, where it runs on
    into the concave edge's, behind the end face. Its record, with the exactly circular fillets
    (highlights off) or with EdgeLight's."""
    helpers.empty_scene(*RESOLUTION, samples=64 if fillet else 8)
    helpers.add_camera(tuple(STEP_CAMERA))
    helpers.add_sun((0.5, -0.8, 0.6), 4.0)
    scene = bpy.context.scene
    scene.render.film_transparent = True
    verts, faces = gt_scenes.built_mesh("l_step")
    ob = zoo.mesh_object("Step", verts.tolist(), faces)
    zoo.smooth_with_sharp_creases(ob.data)
    mat = zoo.material("StepMaterial", (0.8, 0.8, 0.8))
    mat.edgelight.radius = zoo.radius_at_width(width_px, STEP_CAMERA, RESOLUTION[0])
    ob.data.materials.append(mat)
    if fillet:
        fillets.add_fillets(scene, mat.edgelight.radius, 32, exact=True)
    scene.edgelight.highlights = not fillet
    return helpers.render()


def framed_step(width_px, fillet):
    """The step in the ground truth's framing (bench/gt_scenes.py), rounded at width_px pixels, on
    a transparent film: its record and the world positions of its two inside corners. There the
    end faces turn away, and each corner is where two silhouettes (the end face's with the floor
    and with the riser) meet the concave edge, which the eye sees."""
    scene = gt_scenes.open_scene("l_step", 0.01, 1, gt_scenes.RESOLUTION)
    radius = width_px / gt_scenes.px_per_unit_at_centre(scene)
    scene = gt_scenes.open_scene("l_step", radius, 64 if fillet else 8, gt_scenes.RESOLUTION)
    scene.render.film_transparent = True
    verts, _ = gt_scenes.built_mesh("l_step")
    ob = next(o for o in scene.objects if o.type == 'MESH')
    inside = [ob.matrix_world @ ob.data.vertices[i].co for i in np.flatnonzero((np.abs(verts[:, 0]) < 1e-6) & (np.abs(verts[:, 2]) < 1e-6))]
    if fillet:
        fillets.add_fillets(scene, radius, 32, exact=True)
    scene.edgelight.highlights = not fillet
    return helpers.render(), [tuple(v) for v in inside]


def near_corners(rec, corners, radius_px):
    shape = np.asarray(rec["pixels"]).shape[:2]
    yy, xx = np.mgrid[0:shape[0], 0:shape[1]] + 0.5
    return np.any([(xx - c[0]) ** 2 + (yy - c[1]) ** 2 < radius_px ** 2 for c in helpers.project(rec, corners)], axis=0)


class ConcaveEnds(unittest.TestCase):
    def test_a_silhouette_running_on_into_a_concave_edge_keeps_the_face_past_its_end(self):
        """Past the end of the riser's silhouette lies the end face's lower part, which the
        fillets keep (the concave fillet fills the L's inside corner; docs/highlight_math.md,
        "The fillet's outline"). The strip's end took a half disc of it, and behind the end face
        is the part's inside, which is not drawn: a hole to the background. Coverage lost
        against the fillets within 3 r of the corner's image, and past them in the same window."""
        for width in (4.0, 8.0):
            rec = step_render(width, True)
            ref = np.asarray(rec["pixels"])[..., 3].astype(np.float64)
            el = np.asarray(step_render(width, False)["pixels"])[..., 3].astype(np.float64)
            corner = helpers.project(rec, [(0.0, -1.0, 0.0)])[0]
            yy, xx = np.mgrid[0:ref.shape[0], 0:ref.shape[1]]
            near = (xx - corner[0]) ** 2 + (yy - corner[1]) ** 2 < (3.0 * width) ** 2
            lost = float(np.clip(ref - el, 0.0, None)[near].sum())
            past = float(np.clip(el - ref, 0.0, None)[near].sum())
            print(f"{width} px: at the inside corner, coverage lost against the fillets {lost:.1f} pixels, "
                  f"past them {past:.1f}")
            self.assertGreater(ref[near].sum(), 0.5 * near.sum(), "the corner is in view, inside the part")
            # Measured: 0.0 and 0.0 pixels lost (none past); 3.5 and 14.7 lost with the disc.
            self.assertLess(lost, 0.5 * width)

    def test_where_two_silhouettes_meet_a_concave_edge_the_fillet_rounds_the_inside_corner(self):
        """Seen with its end faces turned away, the step's outline has a notch at each inside
        corner, where the floor's and the riser's silhouettes meet the concave edge. The concave
        fillet's end rounds the notch out: the strips of both narrow towards the corner by how far
        its end arc lies out over their lines (docs/highlight_math.md, "The fillet's outline").
        Coverage lost against the fillets and past them within 3 r of the corners' images."""
        for width in (4.0, 8.0):
            rec, corners = framed_step(width, True)
            ref = np.asarray(rec["pixels"])[..., 3].astype(np.float64)
            el = np.asarray(framed_step(width, False)[0]["pixels"])[..., 3].astype(np.float64)
            near = near_corners(rec, corners, 3.0 * width)
            lost = float(np.clip(ref - el, 0.0, None)[near].sum())
            past = float(np.clip(el - ref, 0.0, None)[near].sum())
            print(f"{width} px: at the notches, coverage lost against the fillets {lost:.1f} pixels, past them {past:.1f}")
            self.assertGreater(near.sum(), 50, "the corners are in view")
            # Measured: 0.8 and 0.7 pixels lost, 1.8 and 8.9 past; 4.0 and 12.2 lost (0.4 and
            # 2.0 past) with the strips at full width to the corner.
            self.assertLess(lost, 0.25 * width)
            self.assertLess(past, 1.5 * width)


if __name__ == "__main__":
    unittest.main()
