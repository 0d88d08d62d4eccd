"""The world's Environment Texture (world_light.py, environment_filter.py, shaders/environment.glsl):
a mirror reflects the image's known directions, as Cycles does; the background shows the image
along each pixel's ray; a Lambertian sphere under a lit upper hemisphere takes the closed form
(1 + sin elevation) / 2; a uniform image lights exactly as the same world colour; a Mapping
node turns the image; what is not read is said."""
import math
import os
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo
from test_exact_fillets import ExactFillets
from test_exact_fillets import scene as valley_scene
from test_world_light import cycles_pixels

SIZE = 160
# Sectors of the image by the direction's azimuth (centred on +X, +Y, -X, -Y), and caps.
SECTORS = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (1.0, 1.0, 0.0))
TOP, BOTTOM = (1.0, 1.0, 1.0), (0.2, 0.2, 0.2)


def image_directions(w, h):
    """Blender's equirectangular mapping, from its definition (u = 1/2 - atan2(y, x) / 2pi,
    v = 1/2 + asin(z) / pi), at each texel centre, rows bottom-up."""
    u = (np.arange(w) + 0.5) / w
    v = (np.arange(h) + 0.5) / h
    phi = (0.5 - u)[None, :] * 2.0 * math.pi
    el = (v - 0.5)[:, None] * math.pi
    return np.stack(np.broadcast_arrays(np.cos(el) * np.cos(phi), np.cos(el) * np.sin(phi), np.sin(el)), axis=-1)


def sector_colour(d):
    d = np.asarray(d, np.float64) / np.linalg.norm(d)
    if d[2] > 0.7:
        return np.array(TOP)
    if d[2] < -0.7:
        return np.array(BOTTOM)
    k = int(np.floor(math.atan2(d[1], d[0]) / (math.pi / 2.0) + 0.5)) % 4
    return np.array(SECTORS[k])


def float_image(name, rgb):
    h, w = rgb.shape[:2]
    img = bpy.data.images.new(name, w, h, float_buffer=True)
    px = np.ones((h, w, 4), np.float32)
    px[..., :3] = rgb
    img.pixels.foreach_set(px.reshape(-1))
    return img


def directions_image(w=512, h=256):
    """Each texel's colour is its direction, (d + 1) / 2: a smooth image whose value says which
    way a lookup went (bilinear blending of it is exact to 2e-5 at this size)."""
    return float_image("Directions", ((image_directions(w, h) + 1.0) / 2.0).astype(np.float32))


def rays(rec, xy):
    """World directions of the rays through pixel centres xy of a render (its camera's
    matrices, in double precision: no shader code)."""
    cam = rec["camera"]
    inv = np.linalg.inv(np.asarray(cam.projection, np.float64) @ np.asarray(cam.view, np.float64))
    ndc = (np.asarray(xy, np.float64) + 0.5) / np.array([cam.width, cam.height]) * 2.0 - 1.0
    near = np.c_[ndc, -np.ones(len(ndc)), np.ones(len(ndc))] @ inv.T
    far = np.c_[ndc, np.ones(len(ndc)), np.ones(len(ndc))] @ inv.T
    d = far[:, :3] / far[:, 3:] - near[:, :3] / near[:, 3:]
    return d / np.linalg.norm(d, axis=1, keepdims=True)


def sectors_image(w=256, h=128):
    d = image_directions(w, h)
    rgb = np.zeros((h, w, 3), np.float32)
    k = np.floor(np.arctan2(d[..., 1], d[..., 0]) / (math.pi / 2.0) + 0.5).astype(int) % 4
    rgb[:] = np.asarray(SECTORS, np.float32)[k]
    rgb[d[..., 2] > 0.7] = TOP
    rgb[d[..., 2] < -0.7] = BOTTOM
    return float_image("Sectors", rgb)


def environment_world(scene, image, strength=1.0, rotation_z=None, rotation=None, mapping_type='POINT'):
    """The world: Background <- Environment Texture of `image` (<- Mapping turned about Z, or by
    the XYZ Euler `rotation`, of `mapping_type`)."""
    world = scene.world
    world.use_nodes = True
    nt = world.node_tree
    bg = next(n for n in nt.nodes if n.type == 'BACKGROUND')
    bg.inputs["Strength"].default_value = strength
    env = nt.nodes.new("ShaderNodeTexEnvironment")
    env.image = image
    nt.links.new(env.outputs["Color"], bg.inputs["Color"])
    if rotation_z is not None or rotation is not None:
        mapping = nt.nodes.new("ShaderNodeMapping")
        mapping.vector_type = mapping_type
        coords = nt.nodes.new("ShaderNodeTexCoord")
        mapping.inputs["Rotation"].default_value = rotation if rotation is not None else (0.0, 0.0, rotation_z)
        nt.links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
        nt.links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    return env


def sphere(base, metallic, roughness, specular=None):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=1.0)
    ob = bpy.context.object
    bpy.ops.object.shade_smooth()
    mat = zoo.material("Sphere", base)
    mat.use_nodes = True
    node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
    node.inputs["Base Color"].default_value = (*base, 1.0)
    node.inputs["Metallic"].default_value = metallic
    node.inputs["Roughness"].default_value = roughness
    if specular is not None:
        node.inputs["Specular IOR Level" if "Specular IOR Level" in node.inputs else "Specular"].default_value = specular
    ob.data.materials.append(mat)
    return ob


def ortho_scene(**settings):
    """A scene seen along +Y by an orthographic camera 2.4 units wide, from y = -6."""
    scene = helpers.empty_scene(SIZE, SIZE, highlights=False, **settings)
    cam = helpers.add_camera((0.0, -6.0, 0.0), (0.0, 0.0, 0.0))
    cam.data.type = 'ORTHO'
    cam.data.ortho_scale = 2.4
    return scene


def pixel_of(rec, point):
    return tuple(int(v) for v in np.floor(helpers.project(rec, np.asarray([point], np.float64))[0][:2]))


def at(image, xy):
    return np.asarray(image)[xy[1], xy[0], :3]


# Mirror directions R, each well inside its sector (the sector centres, and 15 degrees from a
# border), and the sphere's normal that reflects the eye's ray into it.
MIRROR_DIRECTIONS = [(math.cos(math.radians(a)) * math.cos(math.radians(e)),
                      math.sin(math.radians(a)) * math.cos(math.radians(e)), math.sin(math.radians(e)))
                     for a, e in ((0, 0), (180, 0), (270, 0), (240, 0), (-30, 0), (200, 10), (270, 60), (250, -60))]


# The prism's view: from the front, 30 degrees above, so both faces at its edge show.
PRISM_VIEW = np.array([0.0, -math.cos(math.radians(30.0)), math.sin(math.radians(30.0))])
PRISM_PX_PER_UNIT = 240 / 3.0


def rounded_prism(radius, arc_segments=48):
    """A square prism along x, 2 units across, its top front edge (y = -1, z = 1) rounded by an
    exactly circular arc of `radius` (0: sharp); the arc smooth, the flat faces flat."""
    import bmesh
    profile = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0)]  # (y, z), counter-clockwise seen from +x
    if radius > 0.0:
        c = (-1.0 + radius, 1.0 - radius)
        for k in range(arc_segments + 1):
            t = math.pi / 2.0 * (1.0 - k / arc_segments)  # normal (-cos t, sin t): the top's, then the front's
            profile.append((c[0] - radius * math.cos(t), c[1] + radius * math.sin(t)))
    else:
        profile.append((-1.0, 1.0))
    n = len(profile)
    verts = [(x, y, z) for x in (-1.5, 1.5) for y, z in profile]
    faces = [(i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n)] + [tuple(range(n)), tuple(range(n, 2 * n))]
    ob = zoo.mesh_object("Prism", verts, faces)
    bm = bmesh.new()
    bm.from_mesh(ob.data)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    bm.to_mesh(ob.data)
    bm.free()
    zoo.smooth_with_sharp_creases(ob.data)
    for poly in ob.data.polygons:
        poly.use_smooth = poly.use_smooth and poly.area < 0.5
    return ob


def mirror_normal(r):
    n = np.asarray(r) + np.array([0.0, -1.0, 0.0])  # R + V, V towards the eye
    return n / np.linalg.norm(n)


def messages(rec):
    return [m for _level, m in rec.get("messages", [])]


class EnvironmentTexture(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()

    def mirror(self, rotation_z=None, transparent=False):
        scene = ortho_scene(samples=4)
        scene.render.film_transparent = transparent
        environment_world(scene, sectors_image(), rotation_z=rotation_z)
        sphere((1.0, 1.0, 1.0), 1.0, 0.0)
        return scene, helpers.render()

    def test_a_mirror_reflects_the_images_directions(self):
        for turn in (None, math.radians(90.0)):
            scene, rec = self.mirror(turn)
            turned = np.eye(3) if turn is None else np.array(
                [[math.cos(turn), -math.sin(turn), 0.0], [math.sin(turn), math.cos(turn), 0.0], [0.0, 0.0, 1.0]])
            for r in MIRROR_DIRECTIONS:
                with self.subTest(turn=turn, r=np.round(r, 3)):
                    xy = pixel_of(rec, mirror_normal(r))
                    # A white metal's lobe albedo is 1 (el_env_specular at F0 = 1).
                    np.testing.assert_allclose(at(rec["pixels"], xy), sector_colour(turned @ np.asarray(r)), atol=0.03)
            # Behind the sphere, the orthographic rays run along +Y.
            np.testing.assert_allclose(at(rec["pixels"], (3, 3)), sector_colour(turned @ np.array([0.0, 1.0, 0.0])), atol=1e-3)

    def test_the_mapping_is_blenders(self):
        """Cycles renders the same mirror: the image's directions are Blender's own."""
        scene, rec = self.mirror()
        theirs = cycles_pixels(scene, samples=4)
        for r in MIRROR_DIRECTIONS:
            xy = pixel_of(rec, mirror_normal(r))
            np.testing.assert_allclose(at(rec["pixels"], xy), at(theirs, xy), atol=0.03, err_msg=str(np.round(r, 3)))
        np.testing.assert_allclose(at(rec["pixels"], (3, 3)), at(theirs, (3, 3)), atol=1e-3)

    def test_a_turned_image_is_turned_as_cycles_turns_it(self):
        """A smooth image (each texel its direction) turned about X and Z by a Mapping node of
        each vector type: the mirror sphere's pixels as Cycles' over the whole sphere."""
        images = {}
        for kind in ('POINT', 'TEXTURE'):
            scene = ortho_scene(samples=1)
            environment_world(scene, directions_image(), rotation=(0.5, 0.0, 1.2), mapping_type=kind)
            sphere((1.0, 1.0, 1.0), 1.0, 0.0)
            ours = np.asarray(helpers.render()["pixels"])[..., :3]
            theirs = cycles_pixels(scene, samples=1)[..., :3]
            y, x = np.mgrid[:SIZE, :SIZE]
            r = np.hypot((x + 0.5) / SIZE - 0.5, (y + 0.5) / SIZE - 0.5) * 2.4  # from the centre, in units
            inner = r < 0.85  # the mirror, short of its grazing rim
            diff = np.abs(ours - theirs)[inner].max()
            print(f"{kind}: the turned mirror against Cycles, {int(inner.sum())} pixels, largest difference {diff:.4f}")
            self.assertLess(diff, 0.02, kind)
            images[kind] = ours[inner]
        # Texture turns the other way from Point: the two differ, so the turn is seen.
        self.assertGreater(float(np.abs(images['POINT'] - images['TEXTURE']).mean()), 0.05)

    def test_the_background_is_the_image_along_each_ray(self):
        """Every pixel's background is the image along its own ray (corners included), in a
        perspective and an orthographic view; a render region shows the same pixels."""
        scene = helpers.empty_scene(SIZE, 120, highlights=False)
        environment_world(scene, directions_image())
        cam = helpers.add_camera((0.0, 0.0, 0.0), (-1.0, 0.4, 0.3), lens=24.0)
        xy = np.array([(x, y) for x in (0, 7, 80, 150, SIZE - 1) for y in (0, 33, 60, 119)])
        for ortho in (False, True):
            cam.data.type = 'ORTHO' if ortho else 'PERSP'
            rec = helpers.render()
            px = np.asarray(rec["pixels"])[..., :3]
            expected = (rays(rec, xy) + 1.0) / 2.0
            np.testing.assert_allclose(px[xy[:, 1], xy[:, 0]], expected, atol=2e-3, err_msg=f"orthographic {ortho}")
        cam.data.type = 'PERSP'
        full = np.asarray(helpers.render()["pixels"])[..., :3]
        r = scene.render
        r.use_border, r.use_crop_to_border = True, True
        r.border_min_x, r.border_max_x, r.border_min_y, r.border_max_y = 0.25, 0.75, 0.5, 1.0
        part = np.asarray(helpers.render()["pixels"])[..., :3]
        np.testing.assert_allclose(part, full[60:120, 40:120], atol=1e-4, err_msg="the region's own rays")
        r.use_border = False
        scene.world.node_tree.nodes.remove(next(n for n in scene.world.node_tree.nodes if n.type == 'TEX_ENVIRONMENT'))
        bpy.data.objects.remove(cam)
        environment_world(scene, sectors_image(), strength=0.5)
        for direction in ((-1.0, 0.2, 0.3), (0.2, -1.0, -0.1), (0.1, 0.2, 1.0), (0.3, 1.0, -0.2)):
            cam = helpers.add_camera((0.0, 0.0, 0.0), direction)
            rec = helpers.render()
            np.testing.assert_allclose(at(rec["pixels"], (SIZE // 2, 60)), 0.5 * sector_colour(direction),
                                       atol=1e-3, err_msg=str(direction))
            bpy.data.objects.remove(cam)
        scene.render.film_transparent = True
        helpers.add_camera((0.0, 0.0, 0.0), (-1.0, 0.2, 0.3))
        px = np.asarray(helpers.render()["pixels"])
        self.assertEqual(float(np.abs(px).max()), 0.0, "a transparent film shows no world")

    def test_a_lambertian_sphere_takes_the_hemispheres_closed_form(self):
        """Radiance 1 above the horizon, 0 below: E(n) / pi = (1 + sin elevation) / 2."""
        scene = ortho_scene(samples=4)
        d = image_directions(512, 256)
        environment_world(scene, float_image("Sky", np.repeat((d[..., 2:3] > 0.0).astype(np.float32), 3, axis=2)))
        sphere((0.8, 0.8, 0.8), 0.0, 1.0, specular=0.0)
        rec = helpers.render()
        for deg in (-60.0, -30.0, 0.0, 30.0, 60.0):
            b = math.radians(deg)
            n = (0.0, -math.cos(b), math.sin(b))
            value = at(rec["pixels"], pixel_of(rec, n))
            np.testing.assert_allclose(value, 0.8 * (1.0 + math.sin(b)) / 2.0, atol=0.01, err_msg=f"{deg} degrees")

    def test_a_floor_facing_the_pole(self):
        """A normal exactly along +Z or -Z (a floor, a ceiling) looks up the image's pole, where
        atan2(0, 0) has no value. Radiance (1 + x) / 2, which differs by azimuth near the pole:
        E / pi there is 1/2 exactly (the x part cancels), where a row 5.6 degrees short of the
        pole, read at one azimuth, is 0.53."""
        scene = helpers.empty_scene(64, 64, highlights=False)
        d = image_directions(512, 256)
        environment_world(scene, float_image("Sky", np.repeat(0.5 * (1.0 + d[..., :1]), 3, axis=2).astype(np.float32)))
        for height, expected in ((5.0, 0.4), (-5.0, 0.4)):
            cam = helpers.add_camera((0.0, 0.0, height), (0.0, 0.0, 0.0))
            cam.data.type = 'ORTHO'
            bpy.ops.mesh.primitive_plane_add(size=40.0, rotation=(0.0, 0.0, 0.0) if height > 0 else (math.pi, 0.0, 0.0))
            plane = bpy.context.object
            mat = zoo.material("Floor", (0.8, 0.8, 0.8))
            mat.use_nodes = True
            node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
            node.inputs["Base Color"].default_value = (0.8, 0.8, 0.8, 1.0)
            node.inputs["Roughness"].default_value = 1.0
            node.inputs["Specular IOR Level" if "Specular IOR Level" in node.inputs else "Specular"].default_value = 0.0
            plane.data.materials.append(mat)
            px = np.asarray(helpers.render()["pixels"])[..., :3]
            np.testing.assert_allclose(px[32, 32], expected, atol=0.01, err_msg=f"seen from z = {height}")
            bpy.data.objects.remove(plane)
            bpy.data.objects.remove(cam)

    def test_a_floor_under_an_hdri_is_lit_as_cycles_lights_it(self):
        """Blender's courtyard HDRI on a white Lambertian floor seen from above: EdgeLight's
        irradiance against Cycles' Diffuse BSDF at 256 samples, the mean over the floor."""
        scene = helpers.empty_scene(64, 64, highlights=False)
        path = os.path.join(bpy.utils.system_resource('DATAFILES'), "studiolights", "world", "courtyard.exr")
        environment_world(scene, bpy.data.images.load(path))
        cam = helpers.add_camera((0.0, 0.0, 5.0), (0.0, 0.0, 0.0))
        cam.data.type = 'ORTHO'
        cam.data.ortho_scale = 1.0
        bpy.ops.mesh.primitive_plane_add(size=4.0)
        mat = bpy.data.materials.new("White")
        mat.use_nodes = True
        node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
        node.inputs["Base Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        node.inputs["Roughness"].default_value = 1.0
        node.inputs["Specular IOR Level" if "Specular IOR Level" in node.inputs else "Specular"].default_value = 0.0
        bpy.context.object.data.materials.append(mat)
        ours = np.asarray(helpers.render()["pixels"])[..., :3].reshape(-1, 3).mean(axis=0)
        tree = mat.node_tree
        lambert = tree.nodes.new("ShaderNodeBsdfDiffuse")
        lambert.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        tree.links.new(lambert.outputs[0], next(n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL').inputs["Surface"])
        theirs = cycles_pixels(scene, samples=256)[..., :3].reshape(-1, 3).mean(axis=0)
        print(f"courtyard on a white floor: EdgeLight {np.round(ours, 4)}, Cycles {np.round(theirs, 4)}")
        # Measured: within 0.8 %; read at one azimuth of a row short of the pole, 19 % over.
        np.testing.assert_allclose(ours, theirs, rtol=0.02)

    def test_a_uniform_image_lights_as_the_world_colour(self):
        """Surface, bands and corners: an image of one colour is that colour's world."""
        images = []
        for use_image in (False, True):
            scene = helpers.empty_scene(240, 200, samples=2, use_shadows=False)
            helpers.add_camera((3.0, -4.0, 2.5), (0.0, 0.0, 0.0))
            helpers.add_sun((0.4, -0.6, 1.0), 2.0)
            ob = zoo.box("Box", 1.5)
            mat = zoo.material("Brass", (0.9, 0.7, 0.3))
            mat.use_nodes = True
            node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
            node.inputs["Metallic"].default_value = 0.7
            node.inputs["Roughness"].default_value = 0.35
            mat.edgelight.radius = 0.08
            ob.data.materials.append(mat)
            grey = (0.45, 0.5, 0.55)
            if use_image:
                environment_world(scene, float_image("Grey", np.broadcast_to(np.float32(grey), (32, 64, 3)).copy()))
            else:
                helpers.set_world_color(scene, grey)
            rec = helpers.render()
            images.append(np.asarray(rec["pixels"]))
            self.assertGreater(rec["stats"].edges_drawn, 0)
        self.assertGreater(np.abs(images[0] - np.asarray(grey + (1.0,))).max(), 0.05, "the box is in the image")
        # Measured: 1.2e-7, one float rounding.
        self.assertLess(float(np.abs(images[0] - images[1]).max()), 1e-5)

    def test_a_band_under_an_hdri_against_the_exact_fillet(self):
        """Blender's studio HDRI on a metal valley's fillet: the band's arc of normals samples
        the prefiltered image as the exact fillet's own normals do (docs/highlight_math.md)."""
        path = os.path.join(bpy.utils.system_resource('DATAFILES'), "studiolights", "world", "studio.exr")
        profile = ExactFillets().profile
        out = {}
        for name, kw in (("exact", {"exact_radius": 1.0, "samples": 64}), ("ours", {}), ("sharp", {"highlights": False})):
            for width in (3.0, 6.0):
                valley_scene(60.0, width, (0.4, -5.0, 3.0), **kw)
                scene = bpy.context.scene
                environment_world(scene, bpy.data.images.load(path), strength=0.5)
                # The valley's flat faces flat: smooth, the exact fillet's faces lean their
                # normals over the whole face, which a mirror-like metal shows.
                for poly in bpy.data.objects["Valley"].data.polygons:
                    poly.use_smooth = poly.use_smooth and poly.area < 0.5
                mat = bpy.data.materials["ValleyMaterial"]
                mat.use_nodes = True
                node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
                node.inputs["Metallic"].default_value = 1.0
                node.inputs["Roughness"].default_value = 0.25
                out[name, width] = profile(helpers.render())
        for width in (3.0, 6.0):
            rmse = {k: math.sqrt(np.mean((out[k, width] - out["exact", width]) ** 2)) for k in ("ours", "sharp")}
            print(f"studio HDRI, metal valley, {width:g} px: RMSE against the exact fillet: EdgeLight {rmse['ours']:.4f}, "
                  f"sharp {rmse['sharp']:.4f}")
            self.assertLess(rmse["ours"], 0.3 * rmse["sharp"], f"{width} px")

    def test_a_bands_arc_reflects_what_its_normals_see(self):
        """A mirror's rounded edge under the sectors: its arc of normals reflects the image
        from the front face's direction (yellow) over the sky (white) to the top face's (green),
        each weighted by its projected width. Held to the exact fillet as the colour the edge
        adds across its line (integrated over the profile, so no sub-pixel position counts)."""
        offsets = np.arange(-8.0, 8.25, 0.25)
        gained = {}
        for name, width in (("sharp", 0.0), ("exact", 1.0), ("ours", 1.0), ("exact", 4.0), ("ours", 4.0)):
            scene = helpers.empty_scene(240, 240, samples=16 if name == "exact" else 4, use_shadows=False,
                                        highlights=name == "ours")
            cam = helpers.add_camera(tuple(np.array([0.0, -1.0, 1.0]) + 10.0 * PRISM_VIEW), (0.0, -1.0, 1.0))
            cam.data.type = 'ORTHO'
            cam.data.ortho_scale = 3.0
            environment_world(scene, sectors_image(512, 256))
            radius = width / (PRISM_PX_PER_UNIT * (math.sin(math.radians(60.0)) + 0.5))
            ob = rounded_prism(radius if name == "exact" else 0.0)
            mat = zoo.material("Mirror", (1.0, 1.0, 1.0))
            mat.use_nodes = True
            node = next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')
            node.inputs["Base Color"].default_value = (1.0, 1.0, 1.0, 1.0)
            node.inputs["Metallic"].default_value = 1.0
            node.inputs["Roughness"].default_value = 0.0
            mat.edgelight.radius = radius
            ob.data.materials.append(mat)
            rec = helpers.render()
            prof = helpers.edge_profile(rec, np.asarray(rec["pixels"])[..., :3], (-0.8, -1.0, 1.0), (0.8, -1.0, 1.0),
                                        np.linspace(0.3, 0.7, 5), offsets)
            gained[name, width] = prof.mean(axis=0)
        # The closed form: the arc's normal at angle t from the front face's reflects the view
        # at 2t - 30 degrees from -Y towards +Z: yellow below 44.4 degrees of elevation (t < 37.2),
        # the white cap to t = 82.8, green past it, each over its projected width
        # sin(t - 30) - sin(t0 - 30) of the arc's sin 60 + 1/2; the sharp faces it replaces are
        # yellow over cos 30 of it and green over sin 30.
        s = np.sin(np.radians([-30.0, 7.2, 52.8, 60.0]))
        yellow, white, green = np.diff(s) / (s[3] - s[0])
        closed = np.array([yellow + white - math.cos(math.radians(30.0)) / (s[3] - s[0]), 0.0, white])
        for width in (1.0, 4.0):
            ours, exact = ((gained[k, width] - gained["sharp", 0.0]).sum(axis=0) * 0.25 for k in ("ours", "exact"))
            print(f"sectors, mirror prism, {width:g} px: colour the edge adds, closed form {np.round(closed * width, 3)}, "
                  f"exact fillet {np.round(exact, 3)}, EdgeLight {np.round(ours, 3)}")
            np.testing.assert_allclose(exact, closed * width, atol=0.1 * width, err_msg=f"the reference, {width} px")
            # Measured: within 0.008 of the closed form at 1 px (the exact mesh, 16 samples, 0.07
            # off), 0.073 at 4 px; the arc's mean normal alone is 0.134 off at 1 px.
            np.testing.assert_allclose(ours, closed * width, atol=0.025 * width, err_msg=f"{width} px")

    def test_what_is_not_read_is_said(self):
        scene = ortho_scene()
        env = environment_world(scene, sectors_image())
        env.projection = 'MIRROR_BALL'
        rec = helpers.render()
        self.assertTrue(any("Mirror Ball projection is read as Equirectangular" in r for r in messages(rec)), messages(rec))
        env.projection = 'EQUIRECTANGULAR'
        rec = helpers.render()
        self.assertFalse(any("world" in r for r in messages(rec)), messages(rec))
        nt = scene.world.node_tree
        sky = nt.nodes.new("ShaderNodeTexNoise")
        nt.links.new(sky.outputs["Color"], next(n for n in nt.nodes if n.type == 'BACKGROUND').inputs["Color"])
        rec = helpers.render()
        self.assertTrue(any("its Color comes from Noise Texture" in r for r in messages(rec)), messages(rec))


if __name__ == "__main__":
    unittest.main()
