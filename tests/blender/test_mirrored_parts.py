"""Mirrored parts render as the mirror image: the step seen from behind its riser (a silhouette
running on into a concave edge: the strips' end cuts and concave marks, docs/highlight_math.md,
"The fillet's outline") and the hollow shaft's concave ring seen along its edges ("Along the
line"), mirrored across x = 0 with their camera and sun, by the object's scale and by a Geometry
Nodes instance of negative scale. Both reverse the triangles' winding on screen; the mirrored
scene's image must be the plain one's flipped left to right."""
import os
import sys
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo

sys.path.insert(0, os.path.join(helpers.ROOT, "bench"))
import gt_scenes  # noqa: E402

RESOLUTION = (320, 240)
VIEWS = {  # camera, its target, and the part's rounded width in pixels at the origin
    "l_step": ((-3.0, -4.0, 2.5), (0.0, 0.0, 0.0), 6.0),
    # Off the axis: seen towards its axis, a body of revolution is its own mirror image.
    "hollow_shaft": ((2.2, -3.4, 2.6), (0.4, 0.2, 0.0), 4.0),
}


def mirror_x(p):
    return (-p[0], p[1], p[2])


def instance_by_nodes(part, scale):
    """A one-point host whose Geometry Nodes instance `part` at the origin with `scale`; the part
    itself is not rendered."""
    host = zoo.mesh_object("Host", [(0.0, 0.0, 0.0)], [])

    def build(nodes, links, group_in):
        info = nodes.new('GeometryNodeObjectInfo')
        info.inputs["Object"].default_value = part
        inst = nodes.new('GeometryNodeInstanceOnPoints')
        inst.inputs["Scale"].default_value = scale
        links.new(group_in.outputs[0], inst.inputs["Points"])
        links.new(info.outputs["Geometry"], inst.inputs["Instance"])
        return inst.outputs["Instances"]

    zoo.geometry_nodes(host, build, with_input=True)
    part.hide_render = True
    return host


def window_sums(x):
    """Each pixel's 3 x 3 window's sum (zero past the image's border)."""
    p = np.pad(x.astype(np.float64), 1)
    h, w = x.shape
    return sum(p[i:i + h, j:j + w] for i in range(3) for j in range(3))


def render(name, how):
    """The part `name`, centred at the origin and about 2 units across, rounded, on a
    transparent film; how: 'plain', 'scaled' (object scale -1 in x) or 'instanced' (a Geometry
    Nodes instance of scale -1 in x). The mirrored ways mirror the camera and the sun too."""
    camera, target, width_px = VIEWS[name]
    mirrored = how != "plain"
    helpers.empty_scene(*RESOLUTION)
    bpy.context.scene.render.film_transparent = True
    helpers.add_camera(mirror_x(camera) if mirrored else camera, mirror_x(target) if mirrored else target)
    sun = (0.5, -0.8, 0.6)
    helpers.add_sun(mirror_x(sun) if mirrored else sun, 4.0)
    verts, faces = gt_scenes.built_mesh(name)
    verts = (verts - 0.5 * (verts.min(0) + verts.max(0))) * (2.0 / np.ptp(verts, 0).max())
    ob = zoo.mesh_object("Part", verts.tolist(), faces)
    zoo.smooth_with_sharp_creases(ob.data)
    mat = zoo.material("PartMaterial", (0.8, 0.8, 0.8))
    mat.edgelight.radius = zoo.radius_at_width(width_px, np.array(camera), RESOLUTION[0])
    ob.data.materials.append(mat)
    if how == "scaled":
        ob.scale = (-1.0, 1.0, 1.0)
    elif how == "instanced":
        instance_by_nodes(ob, (-1.0, 1.0, 1.0))
    bpy.context.scene.edgelight.highlights = True
    return helpers.render()


class MirroredParts(unittest.TestCase):
    def test_mirrored_parts_render_as_the_mirror_image(self):
        helpers.needs_gpu()
        for name in VIEWS:
            plain = render(name, "plain")
            cover = np.asarray(plain["pixels"])[..., 3]
            band = np.asarray(plain["highlight"])[..., 3]
            self.assertGreater((cover > 0.5).sum(), 2000, name)
            self.assertGreater((band > 0.05).sum(), 200, f"{name}: its bands are drawn")
            for how in ("scaled", "instanced"):
                rec = render(name, how)
                drawn = int((np.asarray(rec["pixels"])[..., 3] > 0.5).sum())
                self.assertGreater(drawn, 2000, f"{name} {how}: {rec.get('messages')}")
                for buf in ("pixels", "highlight"):
                    a = np.asarray(plain[buf])
                    b = np.asarray(rec[buf])[:, ::-1]
                    diff = np.abs(a - b).max(axis=-1)
                    window = window_sums(diff)
                    print(f"{name} {how} {buf}: {int((diff > 2.0 / 255.0).sum())} pixels differ by more than "
                          f"2/255, {int((diff > 0.3).sum())} by more than 0.3; in all {diff.sum():.2f}, "
                          f"in the worst 3 x 3 {window.max():.2f}")
                    # One sample: rasterisation's ties are not their own mirror image, so outline
                    # pixels at the step's corners may differ. Measured (3.4): the step 21 / 28
                    # pixels over 2/255, one over 0.3, in all 2.66 / 4.13, worst 3 x 3 0.75; the
                    # shaft none. With the fold judged in world space (mirrored by the model):
                    # 2206 over 0.3, worst 3 x 3 5.55.
                    self.assertLess(int((diff > 0.3).sum()), 4, f"{name} {how} {buf}")
                    self.assertLess(window.max(), 1.5, f"{name} {how} {buf}")
                    self.assertLess(diff.sum(), 10.0, f"{name} {how} {buf}")


if __name__ == "__main__":
    unittest.main()
