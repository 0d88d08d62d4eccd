"""A closed surface's back faces are culled where they cannot show (addon/geometry/closed_surfaces.py):
through the rounded outline's strips they showed the part's inside, a cylinder's cap along its
silhouette. Where the eye is inside the surface, its walls still show; a mirrored instance and a
file whose faces are wound either way render as before."""
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

CAMERA = (0.0, -4.0, 3.0)


def cylinder(radius, triangulated=False, flip_every=0, samples=8, fillet=False, scale=(1.0, 1.0, 1.0), smooth=True):
    """A 96-sided cylinder (n-gon caps, or triangulated), rounded at radius, seen from above its
    front rim; film transparent, so the pixels' alpha is the coverage. flip_every: every so many
    faces wound the other way in the file."""
    helpers.empty_scene(480, 360, samples=samples)
    helpers.add_camera(CAMERA)
    helpers.add_sun((0.2, -0.9, 0.5), 4.0)
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=True, cap_tris=False, segments=96, radius1=1.0, radius2=1.0, depth=1.0)
    if triangulated:
        bmesh.ops.triangulate(bm, faces=bm.faces[:])
    if flip_every:
        bmesh.ops.reverse_faces(bm, faces=list(bm.faces)[::flip_every])
    me = bpy.data.meshes.new("Cylinder")
    bm.to_mesh(me)
    bm.free()
    ob = bpy.data.objects.new("Cylinder", me)
    ob.scale = scale
    bpy.context.scene.collection.objects.link(ob)
    if smooth:
        zoo.smooth_with_sharp_creases(me)
    mat = zoo.material("Steel", (0.6, 0.6, 0.6))
    mat.edgelight.radius = radius
    me.materials.append(mat)
    s = bpy.context.scene
    s.render.film_transparent = True
    if fillet:
        fillets.add_fillets(s, radius, 32)
    return helpers.render()


def bottom_coverage(rec):
    """Per column across the cylinder's front, its coverage (pixels) below the middle: where its
    bottom rim's silhouette lies."""
    alpha = np.asarray(rec["pixels"])[..., 3]
    return alpha[:90, 190:290].sum(axis=0)


class StripsShowNoInside(unittest.TestCase):
    def test_a_cylinders_bottom_outline_against_its_fillet(self):
        """The bottom rim at 4 px is a silhouette whose strip leaves out the side's faces; behind
        them lies the bottom cap, whose triangles each list at most four rims' strips. Coverage
        per column against the Bevel modifier's fillets, measured on llvmpipe: with the cap's
        back faces drawn, up to 1.77 px more (n-gon caps) in runs of two segments where a cap
        triangle did not list the rim; culled, 0.05-0.12; the sharp rim 1.9."""
        helpers.needs_gpu()
        radius = zoo.radius_at_width(4.0, CAMERA, 480)
        for triangulated in (False, True):
            exact = bottom_coverage(cylinder(radius, triangulated, samples=64, fillet=True))
            ours = bottom_coverage(cylinder(radius, triangulated, samples=64))
            sharp = bottom_coverage(cylinder(0.0, triangulated, samples=64))
            print(f"triangulated {triangulated}: coverage per column off the fillet's: EdgeLight "
                  f"{np.abs(ours - exact).max():.2f} at most, sharp {np.abs(sharp - exact).mean():.2f} on average")
            self.assertGreater(np.abs(sharp - exact).mean(), 1.0, "the fillet moves the outline in")
            self.assertLess(np.abs(ours - exact).max(), 0.35, f"triangulated {triangulated}")


class BackFacesWhereTheyShow(unittest.TestCase):
    def test_from_inside_a_closed_box_its_walls_show(self):
        helpers.needs_gpu()
        helpers.empty_scene(160, 120, samples=1)
        helpers.add_camera((0.0, 0.0, 0.0), target=(1.0, 0.3, 0.2))
        helpers.add_sun((0.2, -0.9, 0.5), 4.0)
        room = zoo.box("Room", 6.0)
        mat = zoo.material("Wall", (0.6, 0.6, 0.6))
        mat.edgelight.radius = 0.1
        room.data.materials.append(mat)
        bpy.context.scene.render.film_transparent = True
        alpha = np.asarray(helpers.render()["pixels"])[..., 3]
        self.assertEqual(float(alpha.min()), 1.0, "every pixel shows a wall")

    def test_a_mirrored_instance_renders_as_its_mirror_image(self):
        """The cylinder is its own mirror image across x: scaled by -1 along x (its faces' winding
        turned on screen) it must render as it does unscaled."""
        helpers.needs_gpu()
        radius = zoo.radius_at_width(4.0, CAMERA, 480)
        plain = np.asarray(cylinder(radius, samples=1)["pixels"])
        mirrored = np.asarray(cylinder(radius, samples=1, scale=(-1.0, 1.0, 1.0))["pixels"])
        self.assertGreater((plain[..., 3] > 0.5).sum(), 20000)
        self.assertLess(np.abs(plain - mirrored).max(axis=-1).mean(), 2e-3)
        self.assertLess(np.percentile(np.abs(plain - mirrored).max(axis=-1), 99.5), 0.05)

    def test_faces_wound_either_way_render_alike(self):
        """Every third face wound the other way in the file: the library orients them, the
        surface batch winds them as it oriented them, their normals turned with them, and each
        is still shaded as it is seen. Flat-shaded, as Blender's smooth normals across faces
        wound both ways are not the same as across faces wound alike."""
        helpers.needs_gpu()
        radius = zoo.radius_at_width(4.0, CAMERA, 480)
        plain = np.asarray(cylinder(radius, samples=1, smooth=False)["pixels"])
        flipped = np.asarray(cylinder(radius, samples=1, flip_every=3, smooth=False)["pixels"])
        self.assertLess(np.abs(plain - flipped).max(axis=-1).mean(), 2e-3)
        self.assertLess(np.percentile(np.abs(plain - flipped).max(axis=-1), 99.5), 0.05)


if __name__ == "__main__":
    unittest.main()
