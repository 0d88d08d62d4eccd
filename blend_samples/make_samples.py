"""Regenerates the sample scenes. Run inside Blender:

    blender -b --factory-startup --python blend_samples/make_samples.py -- OUT_DIR [MESH_DIR]

cube.blend: the paper's figure 3, a unit cube under one sun, EdgeLight on every edge.
fandisk.blend: libcgal-demo's mechanical part (MESH_DIR/fandisk.off), creases above 30 degrees.
prop.blend: a low-poly crate whose chosen edges carry bevel weights.
toon.blend: fandisk again, toon-shaded with a three-band ramp, inked silhouettes and creases
  above 60 degrees, and highlights on the gentler edges between 30 and 60 degrees.

A third argument, a comma-separated list of names (cube,fandisk,prop,toon), makes only those.
"""
import math
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = os.path.abspath(argv[0] if argv else os.path.dirname(__file__))
MESH_DIR = argv[1] if len(argv) > 1 else "/usr/share/doc/libcgal-dev"
ONLY = set(argv[2].split(",")) if len(argv) > 2 else None


def reset(engine="EDGELIGHT"):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # A factory reset disables add-ons; EdgeLight must be on for its engine and settings.
    # The module is "bl_ext.user_default.edgelight" when installed as an extension (4.2+).
    bpy.ops.preferences.addon_enable(module=os.environ.get("EDGELIGHT_MODULE", "edgelight"))
    scene = bpy.context.scene
    scene.render.engine = engine
    scene.render.resolution_x, scene.render.resolution_y = 640, 480
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = 'Standard'
    world = bpy.data.worlds.new("World")
    world.color = (0.05, 0.05, 0.06)
    if world.node_tree:  # 5.0 gives new worlds nodes and renders from them: same colour there
        world.node_tree.nodes["Background"].inputs["Color"].default_value = (*world.color, 1.0)
    scene.world = world
    return scene


def add_camera(scene, location, target, lens=50.0, ortho_scale=None):
    cam = bpy.data.cameras.new("Camera")
    cam.lens = lens
    if ortho_scale:
        cam.type = 'ORTHO'
        cam.ortho_scale = ortho_scale
    ob = bpy.data.objects.new("Camera", cam)
    scene.collection.objects.link(ob)
    ob.location = location
    direction = [t - o for t, o in zip(target, location)]
    from mathutils import Vector
    ob.rotation_euler = Vector(direction).to_track_quat('-Z', 'Y').to_euler()
    scene.camera = ob
    return ob


def add_sun(scene, rotation, strength=3.0):
    """rotation: Euler angles; the sun shines along its local -Z."""
    light = bpy.data.lights.new("Sun", 'SUN')
    light.energy = strength
    ob = bpy.data.objects.new("Sun", light)
    ob.rotation_euler = rotation
    scene.collection.objects.link(ob)
    return ob


def material(name, color, roughness, radius, rules=None, angle_deg=30.0):
    mat = bpy.data.materials.new(name)
    if mat.node_tree is None:  # 5.0 gives new materials nodes (and deprecates use_nodes)
        mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    mat.diffuse_color = (*color, 1.0)
    mat.edgelight.radius = radius
    if rules is not None:
        mat.edgelight.selection = rules
    mat.edgelight.angle = math.radians(angle_deg)
    return mat


def mesh_object(scene, name, verts, faces, mat):
    me = bpy.data.meshes.new(name)
    me.from_pydata(verts, [], faces)
    me.update()
    ob = bpy.data.objects.new(name, me)
    ob.data.materials.append(mat)
    scene.collection.objects.link(ob)
    return ob


def cube_scene():
    scene = reset()
    verts = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    mesh_object(scene, "Cube", verts, faces, material("Cube", (0.55, 0.05, 0.04), 0.3, 0.02))
    cam = add_camera(scene, (5.2, -4.4, 3.6), (0, 0, 0))
    # The sun is mirrored from the view about the bisector of the top and front faces, so that
    # edge's arc holds the half vector and glints as a bevel would (the paper's figure 3).
    from mathutils import Vector
    v = Vector(cam.location).normalized()
    h = Vector((0.0, -1.0, 1.0)).normalized()
    to_light = 2.0 * h.dot(v) * h - v
    add_sun(scene, (-to_light).to_track_quat('-Z', 'Y').to_euler(), strength=4.0)
    return scene


def read_off(path):
    with open(path) as f:
        words = [w for line in f for w in line.split("#")[0].split()]
    assert words[0] == "OFF", path
    nv, nf = int(words[1]), int(words[2])
    vals = words[4:]
    verts = [tuple(float(v) for v in vals[3 * i:3 * i + 3]) for i in range(nv)]
    faces, k = [], 3 * nv
    for _ in range(nf):
        n = int(vals[k])
        faces.append(tuple(int(v) for v in vals[k + 1:k + 1 + n]))
        k += 1 + n
    return verts, faces


def fandisk_scene(mesh_dir):
    import tarfile
    scene = reset()
    path = os.path.join(mesh_dir, "fandisk.off")
    if not os.path.exists(path):
        with tarfile.open(os.path.join(mesh_dir, "data.tar.gz")) as tar:
            tar.extract("data/meshes/fandisk.off", OUT)
        path = os.path.join(OUT, "data/meshes/fandisk.off")
    verts, faces = read_off(path)
    ob = mesh_object(scene, "Fandisk", verts, faces, material("Steel", (0.6, 0.62, 0.65), 0.25, 0.004))
    for p in ob.data.polygons:
        p.use_smooth = True
    if hasattr(ob.data, "use_auto_smooth"):  # up to 4.0
        ob.data.use_auto_smooth = True  # at its default 30 degrees
    else:  # 4.1+ replaced Auto Smooth by sharp edges
        ob.data.set_sharp_from_angle(angle=math.radians(30.0))
    add_camera(scene, (2.2, -2.0, 1.6), (0.0, 0.0, 0.0), lens=45)
    add_sun(scene, (math.radians(40), math.radians(-20), math.radians(60)))
    return scene


def toon_scene(mesh_dir):
    scene = fandisk_scene(mesh_dir)
    mat = bpy.data.materials["Steel"]
    s = mat.edgelight
    s.shading = 'RAMP'
    import importlib
    color_ramp = importlib.import_module(os.environ.get("EDGELIGHT_MODULE", "edgelight") + ".extract.color_ramp")
    s.shade_ramp = color_ramp.new_ramp(
        ((0.0, (0.05, 0.07, 0.12)), (0.3, (0.22, 0.3, 0.45)), (0.75, (0.55, 0.68, 0.85))), 'CONSTANT')
    s.radius, s.K, s.use_custom_shininess, s.shininess = 0.006, 1.5, True, 40.0
    lines = scene.edgelight
    lines.use_lines = True
    lines.crease_angle = math.radians(60)
    lines.line_silhouette.width = 2.5
    lines.line_crease.width = 1.5
    lines.line_crease.color = (0.02, 0.03, 0.08)
    lines.line_border.width = 2.0
    lines.samples = 8
    return scene


def prop_scene():
    import bmesh
    scene = reset()
    me = bpy.data.meshes.new("Crate")
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.6)
    # An inset lid: more edges, some marked for rounding by bevel weight.
    top = [f for f in bm.faces if f.normal.z > 0.9][0]
    bmesh.ops.inset_region(bm, faces=[top], thickness=0.15, depth=-0.08)
    bm.to_mesh(me)
    bm.free()
    ob = bpy.data.objects.new("Crate", me)
    scene.collection.objects.link(ob)
    ob.data.materials.append(material("Wood", (0.45, 0.28, 0.12), 0.45, 0.05, rules={'BEVEL'}))
    weights = [1.0 if abs(me.vertices[e.vertices[0]].co.z - me.vertices[e.vertices[1]].co.z) < 1e-6 else 0.4 for e in me.edges]
    if hasattr(me.edges[0], "bevel_weight"):
        for e, w in zip(me.edges, weights):
            e.bevel_weight = w
    else:
        attr = me.attributes.new("bevel_weight_edge", 'FLOAT', 'EDGE')
        attr.data.foreach_set("value", weights)
    add_camera(scene, (3.6, -3.4, 2.8), (0, 0, -0.1))
    add_sun(scene, (math.radians(45), math.radians(15), math.radians(-25)))
    return scene


def save(name):
    path = os.path.join(OUT, name)
    bpy.ops.wm.save_as_mainfile(filepath=path, compress=True)
    print("wrote", path)


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    makers = {"cube": cube_scene, "fandisk": lambda: fandisk_scene(MESH_DIR), "prop": prop_scene,
              "toon": lambda: toon_scene(MESH_DIR)}
    for name, make in makers.items():
        if ONLY is None or name in ONLY:
            make()
            save(name + ".blend")
