"""Every kind of depsgraph instance: one native mesh per distinct geometry, each instance drawn
with its own matrix (Geometry Nodes, collections, particles, linked duplicates)."""
import unittest

import bpy
import numpy as np

import helpers
import scene_zoo as zoo

GRID = 30  # Instance on Points on a 30 x 30 grid: 900 instances


def cones_on_grid(nodes, links, group_in, realize=False):
    grid = nodes.new('GeometryNodeMeshGrid')
    grid.inputs["Size X"].default_value = grid.inputs["Size Y"].default_value = 10.0
    grid.inputs["Vertices X"].default_value = grid.inputs["Vertices Y"].default_value = GRID
    cone = nodes.new('GeometryNodeMeshCone')
    cone.inputs["Radius Bottom"].default_value = 0.12
    inst = nodes.new('GeometryNodeInstanceOnPoints')
    links.new(grid.outputs["Mesh"], inst.inputs["Points"])
    links.new(cone.outputs["Mesh"], inst.inputs["Instance"])
    if not realize:
        return inst.outputs["Instances"]
    real = nodes.new('GeometryNodeRealizeInstances')
    links.new(inst.outputs["Instances"], real.inputs[0])
    return real.outputs[0]


def grid_points():
    c = np.linspace(-5.0, 5.0, GRID)
    x, y = np.meshgrid(c, c)
    return np.c_[x.ravel(), y.ravel(), np.zeros(GRID * GRID)]


class Instances(unittest.TestCase):
    def setUp(self):
        helpers.needs_gpu()
        helpers.empty_scene(360, 360)
        zoo.top_camera(6.0)
        helpers.add_sun()

    def distinct(self, rec):
        return len({id(i.mesh) for i in rec["scene"].instances})

    def covered_at(self, rec, points):
        return zoo.coverage(rec)[tuple(np.floor(helpers.project(rec, points)[:, ::-1]).astype(int).T)] > 0.5

    def test_instance_on_points_draws_every_instance_from_one_mesh(self):
        zoo.geometry_nodes(zoo.box("Host"), cones_on_grid)
        rec = helpers.render()
        self.assertEqual(len(rec["scene"].instances), GRID * GRID)
        self.assertEqual(self.distinct(rec), 1, "instances of one geometry share one native mesh")
        hit = self.covered_at(rec, grid_points())
        self.assertTrue(hit.all(), f"{(~hit).sum()} of {GRID * GRID} cone tips uncovered")
        self.assertLess(zoo.coverage(rec)[180, 180 + 6], 0.5, "nothing between the cones")

    def test_realized_instances_cover_the_same_pixels(self):
        host = zoo.box("Host")
        zoo.geometry_nodes(host, cones_on_grid)
        instanced = zoo.coverage(helpers.render())
        host.modifiers[0].node_group = zoo.geometry_nodes(zoo.box("Other"), lambda n, ln, g: cones_on_grid(n, ln, g, True))
        bpy.data.objects.remove(bpy.data.objects["Other"])
        rec = helpers.render()
        self.assertEqual(len(rec["scene"].instances), 1)
        a, b = instanced > 0.5, zoo.coverage(rec) > 0.5
        self.assertGreater((a & b).sum() / (a | b).sum(), 0.995)

    def test_instances_mixed_with_the_hosts_own_mesh(self):
        def spheres_on_corners(nodes, links, group_in):
            ico = nodes.new('GeometryNodeMeshIcoSphere')
            ico.inputs["Radius"].default_value = 0.3
            inst = nodes.new('GeometryNodeInstanceOnPoints')
            links.new(group_in.outputs[0], inst.inputs["Points"])
            links.new(ico.outputs["Mesh"], inst.inputs["Instance"])
            join = nodes.new('GeometryNodeJoinGeometry')
            links.new(inst.outputs["Instances"], join.inputs[0])
            links.new(group_in.outputs[0], join.inputs[0])
            return join.outputs[0]

        host = zoo.box("Host", 4.0)
        host.data.materials.append(zoo.material("Red", (0.8, 0.05, 0.05)))
        zoo.geometry_nodes(host, spheres_on_corners, with_input=True)
        rec = helpers.render()
        sc = rec["scene"]
        self.assertEqual(len(sc.instances), 9, "the host's cube and 8 spheres")
        self.assertEqual(self.distinct(rec), 2)
        # The spheres stick out past the cube's corners; the cube covers its middle.
        corners = np.array([(x, y, 2.0) for x in (-2.12, 2.12) for y in (-2.12, 2.12)])
        self.assertTrue(self.covered_at(rec, corners).all())
        self.assertTrue(self.covered_at(rec, [(0.0, 0.0, 2.0)]).all())

    def test_collection_instances_share_their_meshes(self):
        coll = bpy.data.collections.new("Part")
        zoo.box("Block", 1.0, collection=coll)
        places = [(-3.0, -3.0, 0.0), (3.0, -2.0, 0.0), (0.0, 3.0, 0.0)]
        for i, p in enumerate(places):
            empty = bpy.data.objects.new(f"Inst{i}", None)
            empty.instance_type = 'COLLECTION'
            empty.instance_collection = coll
            empty.location = p
            bpy.context.scene.collection.objects.link(empty)
        rec = helpers.render()
        self.assertEqual(len(rec["scene"].instances), 3, "the collection is not in the scene itself")
        self.assertEqual(self.distinct(rec), 1)
        self.assertTrue(self.covered_at(rec, [(x, y, 0.5) for x, y, _ in places]).all())
        self.assertFalse(self.covered_at(rec, [(0.0, 0.0, 0.5)]).any())

    def test_particle_object_instances(self):
        emitter = zoo.mesh_object("Emitter", [(-4, -4, 0), (4, -4, 0), (4, 4, 0), (-4, 4, 0)], [(0, 1, 2, 3)])
        ball = zoo.box("Ball", 0.3, location=(0.0, 0.0, -50.0))
        ball.hide_render = True  # only its particle copies render
        emitter.modifiers.new("Particles", 'PARTICLE_SYSTEM')
        ps = emitter.particle_systems[0].settings
        ps.type = 'HAIR'
        ps.count = 25
        ps.hair_length = 0.5
        ps.render_type = 'OBJECT'
        ps.instance_object = ball
        ps.particle_size = 1.0
        rec = helpers.render()
        balls = [i for i in rec["scene"].instances if i.mesh.name.startswith("Ball")]
        self.assertEqual(len(balls), 25)
        self.assertEqual(len({id(i.mesh) for i in balls}), 1)
        centres = np.array([np.asarray(i.matrix, np.float64)[:3, 3] for i in balls])
        self.assertEqual(len(np.unique(centres.round(4), axis=0)), 25, "each particle has its own place")
        self.assertTrue(self.covered_at(rec, centres + [0.0, 0.0, 0.15]).all())
        self.assertIn("Emitter", [i.mesh.name for i in rec["scene"].instances])
        # Show Emitter off (the object's Instancing panel, Render): the particles without it.
        emitter.show_instancer_for_render = False
        rec = helpers.render()
        self.assertEqual([i.mesh.name for i in rec["scene"].instances if not i.mesh.name.startswith("Ball")], [])
        self.assertEqual(len(rec["scene"].instances), 25)
        gaps = np.array([(x + 0.5, y + 0.5, 0.0) for x in range(-3, 3) for y in range(-3, 3)])
        self.assertLess(self.covered_at(rec, gaps).mean(), 0.5, "the emitter's face is not drawn")

    def test_linked_duplicates_share_one_mesh(self):
        a = zoo.box("A", 1.0, location=(-2.0, 0.0, 0.0))
        b = bpy.data.objects.new("B", a.data)
        b.location = (2.0, 1.0, 0.0)
        b.scale = (1.5, 1.5, 1.5)
        bpy.context.scene.collection.objects.link(b)
        rec = helpers.render()
        self.assertEqual(len(rec["scene"].instances), 2)
        self.assertEqual(self.distinct(rec), 1)
        self.assertTrue(self.covered_at(rec, [(-2.0, 0.0, 0.5), (2.0, 1.0, 0.75), (2.7, 1.7, 0.75)]).all())
        self.assertFalse(self.covered_at(rec, [(-2.7, 0.0, 0.5)]).any(), "the scale is B's only")

    def test_separate_copies_of_one_part_share_one_mesh(self):
        # Shift+D copies the mesh: equal content under other names, as artists' scenes of many
        # parts are. One extraction serves them (scene_sync.extract_mesh's same_content); a copy
        # edited, or given another material, is its own.
        a = zoo.box("A", 1.0, location=(-2.0, 0.0, 0.0))
        for name, x in (("B", 0.0), ("C", 2.0), ("Edited", 0.0), ("Painted", 2.0)):
            ob = bpy.data.objects.new(name, a.data.copy())
            ob.location = (x, 2.0 if name in ("Edited", "Painted") else 0.0, 0.0)
            bpy.context.scene.collection.objects.link(ob)
        edited = bpy.data.objects["Edited"].data
        edited.vertices[0].co.x -= 0.25
        bpy.data.objects["Painted"].data.materials.append(zoo.material("Red", (0.8, 0.1, 0.1)))
        rec = helpers.render()
        meshes = {inst.mesh.name: id(inst.mesh) for inst in rec["scene"].instances}
        by_object = [id(inst.mesh) for inst in rec["scene"].instances]
        self.assertEqual(len(by_object), 5)
        self.assertEqual(self.distinct(rec), 3, meshes)
        self.assertTrue(self.covered_at(rec, [(-2.0, 0.0, 0.5), (0.0, 0.0, 0.5), (2.0, 0.0, 0.5),
                                              (0.0, 2.0, 0.5), (2.0, 2.0, 0.5)]).all())
        # The edited copy's bottom corner moved out to (-0.75, 1.5): drawn from its own mesh.
        self.assertTrue(self.covered_at(rec, [(-0.6, 1.55, -0.5)]).all(), "the edited copy is its own")
        self.assertFalse(self.covered_at(rec, [(1.4, 1.55, -0.5)]).any(), "the painted copy is not edited")

    def test_many_objects_share_their_view_lines_textures(self):
        """Six separate boxes, their silhouettes on the rounded outline: each type's view lines
        of all six are one record texture and one face texture (line_pass.view_line_batches),
        each box drawing its own range, and the ink is what six textures of their own draw."""
        import importlib
        line_pass = importlib.import_module(helpers.MODULE + ".passes.line_pass")
        helpers.add_camera((3.0, -6.0, 5.0), lens=35.0)
        for i in range(6):
            zoo.box(f"Box{i}", 1.0, location=((i % 3) * 1.8 - 1.8, (i // 3) * 1.8 - 0.9, 0.0))
        helpers.only_lines(bpy.context.scene, silhouette=3.0, crease=1.5)
        shared = line_pass.view_line_batches
        made = []

        def recording(per_instance, chunk=None):
            made.append(shared(per_instance, chunk))
            return made[-1]

        def separate(per_instance, chunk=None):
            return [line_pass.line_batches(segs, chunk) for segs in per_instance]
        try:
            line_pass.view_line_batches = recording
            ours = helpers.render()
            line_pass.view_line_batches = separate
            theirs = helpers.render()
        finally:
            line_pass.view_line_batches = shared
        sets = [s["silhouette"] for s in made[0] if "silhouette" in s]
        self.assertEqual(len(sets), 6)
        self.assertEqual(len({id(s.nodes) for s in sets}), 1, "one record texture")
        self.assertEqual(len({id(s.faces) for s in sets}), 1, "one face texture")
        self.assertGreater(sum(s.count for s in sets), 6 * 4, "arcs on the rounded outline, in each box's range")
        ink = ours["lines"][..., 3]
        self.assertGreater(int((ink > 0.5).sum()), 2000)
        np.testing.assert_array_equal(ink, theirs["lines"][..., 3])

    def test_objects_not_drawn_are_reported_in_one_line(self):
        zoo.box("Block")
        smoke = bpy.data.objects.new("Smoke", bpy.data.volumes.new("Smoke"))
        bpy.context.scene.collection.objects.link(smoke)

        def points(nodes, links, group_in):
            to_points = nodes.new('GeometryNodeMeshToPoints')
            links.new(group_in.outputs[0], to_points.inputs[0])
            return to_points.outputs[0]

        dots = zoo.box("Dots", 2.0, location=(3.0, 3.0, 0.0))
        zoo.geometry_nodes(dots, points, with_input=True)
        rec = helpers.render()
        lines = [m for lvl, m in rec.get("messages", []) if "does not draw" in m]
        self.assertEqual(len(lines), 1, rec.get("messages"))
        self.assertIn("'Smoke' (volume)", lines[0])
        self.assertIn("point cloud", lines[0])
        self.assertEqual(len(rec["scene"].instances), 1)


class InconsistentWinding(unittest.TestCase):
    """Half the faces of an imported part flipped: the image, the rounded edges and the lines
    must be those of the consistently wound part, with one report line."""

    def part(self, flip):
        import bmesh
        helpers.empty_scene(320, 240)
        helpers.add_camera((4.0, -5.0, 3.5))
        helpers.add_sun()
        bm = zoo.subdivided_cube(2)
        bm.faces.ensure_lookup_table()
        if flip:
            rng = np.random.default_rng(7)
            faces = [f for f in bm.faces if rng.random() < 0.5]
            bmesh.ops.reverse_faces(bm, faces=faces)
        zoo.rounded_part("Part", bm, (0.7, 0.1, 0.08), 0.05)
        helpers.only_lines(bpy.context.scene, silhouette=2.0, crease=2.0)
        return helpers.render()

    def test_half_flipped_part_renders_like_the_consistent_one(self):
        helpers.needs_gpu()
        good, bad = self.part(False), self.part(True)
        self.assertEqual(bad["stats"].edges_drawn, good["stats"].edges_drawn)
        self.assertEqual(bad["stats"].lines_drawn, good["stats"].lines_drawn)
        for buf in ("highlight", "lines", "pixels"):
            diff = np.abs(np.asarray(bad[buf]) - np.asarray(good[buf]))
            self.assertLess(np.percentile(diff, 99.9), 1e-3, buf)
        winding = [m for _, m in bad.get("messages", []) if "wound against" in m]
        self.assertEqual(len(winding), 1, bad.get("messages"))
        self.assertFalse([m for _, m in good.get("messages", []) if "wound against" in m])


class MirroredObjects(unittest.TestCase):
    def test_negative_scale_renders_like_the_mirror_image(self):
        """A mirrored object (scale -1 on one axis, or a mirrored instance) reverses its
        triangles' winding on screen: it must still be lit from its outside. A cube is its own
        mirror image, so the mirrored cube's render equals the plain one's."""
        helpers.needs_gpu()
        renders = []
        for scale in ((1.0, 1.0, 1.0), (-1.0, 1.0, 1.0), (-1.0, -1.0, -1.0)):
            helpers.empty_scene(200, 150)
            helpers.add_camera((4.0, -5.0, 3.5))
            helpers.add_sun((0.4, -0.7, 0.9), 4.0)
            cube = zoo.box("Cube", 2.0)
            cube.scale = scale
            cube.data.materials.append(zoo.material("Red", (0.7, 0.1, 0.05)))
            helpers.only_lines(bpy.context.scene, silhouette=1.5, crease=1.5)
            renders.append(helpers.render())
        for rec in renders[1:]:
            for buf in ("surface", "highlight", "pixels"):
                diff = np.abs(np.asarray(rec[buf]) - np.asarray(renders[0][buf]))
                self.assertLess(np.percentile(diff, 99.5), 2e-3, buf)
