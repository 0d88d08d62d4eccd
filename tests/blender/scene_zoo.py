"""Scenes built the way artists build them, by script (never a saved binary), for the
production-scene tests: Geometry Nodes instances, collection and particle instances, linked
duplicates, view layers, objects EdgeLight does not draw. Works on Blender 3.4 through 5.x."""
import math

import bmesh
import bpy
import numpy as np

import helpers


def _group_sockets(group, with_input):
    """Geometry in (optional) and out sockets on any version (4.0 moved them to `interface`)."""
    if hasattr(group, "interface"):
        if with_input:
            group.interface.new_socket("Geometry", in_out='INPUT', socket_type='NodeSocketGeometry')
        group.interface.new_socket("Geometry", in_out='OUTPUT', socket_type='NodeSocketGeometry')
    else:
        if with_input:
            group.inputs.new('NodeSocketGeometry', "Geometry")
        group.outputs.new('NodeSocketGeometry', "Geometry")


def geometry_nodes(ob, build, with_input=False):
    """Adds a Geometry Nodes modifier whose tree `build(nodes, links, group_in)` returns the
    socket that becomes the object's geometry."""
    group = bpy.data.node_groups.new(ob.name + "Nodes", 'GeometryNodeTree')
    _group_sockets(group, with_input)
    nodes, links = group.nodes, group.links
    group_in = nodes.new('NodeGroupInput')
    group_out = nodes.new('NodeGroupOutput')
    links.new(build(nodes, links, group_in), group_out.inputs[0])
    mod = ob.modifiers.new("Nodes", 'NODES')
    mod.node_group = group
    return group


def mesh_object(name, verts, faces, location=(0.0, 0.0, 0.0), collection=None):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    ob = bpy.data.objects.new(name, mesh)
    ob.location = location
    (collection or bpy.context.scene.collection).objects.link(ob)
    return ob


def subdivided_cube(cuts):
    """A bmesh of a 2-unit cube centred at the origin, each face cut into (cuts + 1)^2 quads (an
    imported part's grid of faces)."""
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=2.0)
    bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=cuts, use_grid_fill=True)
    return bm


def rounded_part(name, bm, rgb, radius):
    """An object made from a bmesh (freed here), with one material rounding its edges at radius."""
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    ob = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(ob)
    mat = material(name + "Material", rgb)
    mat.edgelight.radius = radius
    mesh.materials.append(mat)
    return ob


def radius_at_width(width_px, camera, resolution_x):
    """The radius whose image is width_px pixels wide at the origin (r f / d), seen from a camera
    at `camera` looking at it with helpers.add_camera's 50 mm lens on Blender's 36 mm sensor."""
    return width_px * float(np.linalg.norm(camera)) / (50.0 / 36.0 * resolution_x)


def smooth_with_sharp_creases(mesh, crease_deg=30.0):
    """Every face smooth-shaded, sharp where faces fold by more than crease_deg and along open
    edges: auto smooth's rule, on 4.1+ (no auto smooth) marked on the edges."""
    for p in mesh.polygons:
        p.use_smooth = True
    if hasattr(mesh, "use_auto_smooth"):
        mesh.use_auto_smooth = True
        mesh.auto_smooth_angle = math.radians(crease_deg)
    bm = bmesh.new()
    bm.from_mesh(mesh)
    folds = [e.calc_face_angle(0.0) > math.radians(crease_deg) if len(e.link_faces) == 2 else True
             for e in bm.edges]
    bm.free()
    for k, sharp in enumerate(folds):
        if sharp:
            helpers.mark_edge(mesh, "sharp", k)


def box(name, size=1.0, location=(0.0, 0.0, 0.0), collection=None):
    s = size / 2.0
    verts = [(x, y, z) for x in (-s, s) for y in (-s, s) for z in (-s, s)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return mesh_object(name, verts, faces, location, collection)


def cylinder(name, segments=32):
    """A cylinder as Blender's Cylinder is made (radius 0.5, depth 1, n-gon caps, which Blender
    triangulates into long slivers), smooth-shaded with its rims sharp (its side's facets fold
    by 360 / segments degrees)."""
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=True, segments=segments, radius1=0.5, radius2=0.5, depth=1.0)
    me = bpy.data.meshes.new(name)
    bm.to_mesh(me)
    bm.free()
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    smooth_with_sharp_creases(me)
    return ob


def material(name, rgb):
    """A material of colour rgb on every version (5.0 renders materials from their node tree)."""
    mat = bpy.data.materials.new(name)
    mat.diffuse_color = (*rgb, 1.0)
    if mat.node_tree is not None:
        for node in mat.node_tree.nodes:
            if node.type == 'BSDF_PRINCIPLED':
                node.inputs["Base Color"].default_value = (*rgb, 1.0)
    return mat


def top_camera(half_width, height=20.0):
    """An orthographic camera looking straight down at the origin, seeing +-half_width."""
    cam = helpers.add_camera((0.0, 0.0, height), (0.0, 0.0, 0.0))
    cam.rotation_euler = (0.0, 0.0, 0.0)
    cam.data.type = 'ORTHO'
    cam.data.ortho_scale = 2.0 * half_width
    cam.data.clip_end = 2.0 * height
    return cam


def coverage(rec):
    """Surface coverage (h, w) of a render record."""
    return np.asarray(rec["surface"])[..., 3]
