"""Issue 42's scene zoo: eight scenes built the way artists build them, for the materials and the
light EdgeLight draws (test_material_zoo.py) and for the comparison with EEVEE and Cycles
(bench/zoo_renders.py). Each builder starts from an empty scene (helpers.empty_scene) and
returns a Zoo record: what it shows, whether its edges are rounded (a Cycles + Bevel comparison
applies), and what EdgeLight is expected to say it does not draw (an empty tuple: nothing)."""
import math
import os
from dataclasses import dataclass

import bmesh
import bpy
import numpy as np

import helpers
import scene_zoo as zoo

RESOLUTION = (320, 240)


@dataclass(frozen=True)
class Zoo:
    name: str
    about: str
    rounded: bool          # edges EdgeLight rounds: compared with Cycles' Bevel node too
    unsupported: tuple     # fragments of the report lines that say what is not drawn


def _principled(mat):
    mat.use_nodes = True
    return next(n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED')


def _material(name, base, metallic=0.0, roughness=0.5, radius=0.0):
    mat = zoo.material(name, base)
    node = _principled(mat)
    node.inputs["Base Color"].default_value = (*base, 1.0)
    node.inputs["Metallic"].default_value = metallic
    node.inputs["Roughness"].default_value = roughness
    mat.edgelight.use_rounding = radius > 0.0
    if radius > 0.0:
        mat.edgelight.radius = radius
    return mat


def _scene(samples=8):
    scene = helpers.empty_scene(*RESOLUTION, samples=samples)
    scene.render.film_transparent = False
    return scene


def _world(scene, rgb=(0.05, 0.05, 0.05), hdri=None, strength=1.0):
    world = scene.world
    world.use_nodes = True
    nt = world.node_tree
    bg = next(n for n in nt.nodes if n.type == 'BACKGROUND')
    bg.inputs["Color"].default_value = (*rgb, 1.0)
    bg.inputs["Strength"].default_value = strength
    world.color = rgb
    if hdri:
        env = nt.nodes.new("ShaderNodeTexEnvironment")
        env.image = bpy.data.images.load(os.path.join(bpy.utils.system_resource('DATAFILES'), "studiolights", "world",
                                                      hdri + ".exr"), check_existing=True)
        nt.links.new(env.outputs["Color"], bg.inputs["Color"])


def _floor(size=12.0, z=0.0, rgb=(0.6, 0.6, 0.6)):
    bpy.ops.mesh.primitive_plane_add(size=size, location=(0.0, 0.0, z))
    ob = bpy.context.object
    ob.name = "Floor"
    ob.data.materials.append(_material("Floor", rgb, roughness=0.8))
    return ob


def _gear(name, teeth=12, r=0.8, depth=0.25, width=0.35):
    """A spur gear's blank: a prism whose outline alternates tooth tips and roots."""
    pts = []
    for k in range(teeth * 4):
        a = 2.0 * math.pi * k / (teeth * 4)
        rad = r + (depth if (k // 2) % 2 == 0 else 0.0)
        pts.append((rad * math.cos(a), rad * math.sin(a)))
    n = len(pts)
    verts = [(x, y, z) for z in (-width / 2, width / 2) for x, y in pts]
    faces = [(i, (i + 1) % n, n + (i + 1) % n, n + i) for i in range(n)] + [tuple(range(n))[::-1], tuple(range(n, 2 * n))]
    return zoo.mesh_object(name, verts, faces)


def metals_under_an_hdri():
    scene = _scene()
    _world(scene, hdri="courtyard")
    helpers.add_camera((3.2, -4.0, 2.6), (0.0, 0.0, 0.3))
    gear = _gear("BrassGear")
    gear.location = (-0.6, 0.4, 0.35)
    gear.data.materials.append(_material("Brass", (0.95, 0.7, 0.3), metallic=1.0, roughness=0.3, radius=0.03))
    bolt = zoo.cylinder("Bolt", 6)
    bolt.scale = (0.6, 0.6, 0.6)
    bolt.location = (0.9, -0.3, 0.3)
    bolt.data.materials.append(_material("BlackOxide", (0.08, 0.08, 0.09), metallic=1.0, roughness=0.4, radius=0.02))
    block = zoo.box("Block", 0.7, location=(0.6, 0.9, 0.35))
    block.data.materials.append(_material("Steel", (0.75, 0.75, 0.78), metallic=1.0, roughness=0.15, radius=0.04))
    _floor(rgb=(0.35, 0.35, 0.35))
    return Zoo("metals_hdri", "brass, black oxide and steel under Blender's courtyard HDRI", True, ())


def textured_prop():
    scene = _scene()
    _world(scene, hdri="studio")
    helpers.add_sun((0.5, -0.6, 1.0), 2.0)
    helpers.add_camera((2.6, -3.4, 2.2), (0.0, 0.0, 0.4))
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 0.5))
    crate = bpy.context.object
    mat = _material("Crate", (0.8, 0.8, 0.8), roughness=0.6, radius=0.03)
    tree = mat.node_tree
    tex = tree.nodes.new("ShaderNodeTexImage")
    tex.image = bpy.data.images.new("Grid", 256, 256)
    tex.image.generated_type = 'COLOR_GRID'
    tree.links.new(tex.outputs["Color"], _principled(mat).inputs["Base Color"])
    bump = tree.nodes.new("ShaderNodeNormalMap")
    tree.links.new(bump.outputs["Normal"], _principled(mat).inputs["Normal"])
    # Its normal map: a grid of round bumps, 4 a side, as a baked tangent-space image (Non-Color).
    n = 128
    u, v = np.meshgrid((np.arange(n) + 0.5) / n, (np.arange(n) + 0.5) / n)
    slope = 0.6 * 2.0 * np.pi * 4.0
    dx = slope * np.cos(2.0 * np.pi * 4.0 * u) * np.sin(2.0 * np.pi * 4.0 * v) / (2.0 * np.pi * 4.0)
    dy = slope * np.sin(2.0 * np.pi * 4.0 * u) * np.cos(2.0 * np.pi * 4.0 * v) / (2.0 * np.pi * 4.0)
    normal = np.stack([-dx, -dy, np.ones_like(dx)], axis=-1)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    bumps = bpy.data.images.new("Bumps", n, n, float_buffer=True)
    bumps.colorspace_settings.name = 'Non-Color'
    bumps.pixels.foreach_set(np.concatenate([(normal + 1.0) / 2.0, np.ones((n, n, 1))], axis=-1).astype(np.float32).reshape(-1))
    bump_tex = tree.nodes.new("ShaderNodeTexImage")
    bump_tex.image = bumps
    tree.links.new(bump_tex.outputs["Color"], bump.inputs["Color"])
    crate.data.materials.append(mat)
    _floor()
    return Zoo("textured_prop", "a UV-mapped crate with an image in Base Color and a bumpy Normal Map", True, ())


def vertex_coloured_low_poly():
    scene = _scene()
    _world(scene, rgb=(0.4, 0.45, 0.5))
    helpers.add_sun((-0.4, -0.7, 1.0), 2.5)
    helpers.add_camera((3.0, -3.6, 2.4), (0.0, 0.0, 0.5))
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=1, radius=0.7, location=(0.0, 0.0, 0.7))
    rock = bpy.context.object
    me = rock.data
    attr = me.color_attributes.new("Col", 'FLOAT_COLOR', 'CORNER')
    rng = np.random.default_rng(7)
    face_colours = rng.uniform(0.2, 0.9, (len(me.polygons), 3))
    colours = np.ones((len(me.loops), 4), np.float32)
    for p in me.polygons:
        colours[list(p.loop_indices), :3] = face_colours[p.index]
    attr.data.foreach_set("color", colours.reshape(-1))
    mat = _material("Painted", (0.8, 0.8, 0.8), roughness=0.7, radius=0.02)
    attr_node = mat.node_tree.nodes.new("ShaderNodeVertexColor")
    attr_node.layer_name = "Col"
    mat.node_tree.links.new(attr_node.outputs["Color"], _principled(mat).inputs["Base Color"])
    me.materials.append(mat)
    _floor(rgb=(0.3, 0.5, 0.3))
    return Zoo("vertex_colours", "a low-poly rock painted with a Color Attribute", True, ())


def alpha_clipped_cards():
    scene = _scene()
    _world(scene, rgb=(0.5, 0.6, 0.7))
    helpers.add_sun((0.3, -0.5, 1.0), 2.5)
    helpers.add_camera((0.0, -4.5, 1.4), (0.0, 0.0, 0.9))
    leaf = bpy.data.images.new("Leaf", 64, 64, alpha=True)
    y, x = np.mgrid[:64, :64]
    inside = ((x - 31.5) / 24.0) ** 2 + ((y - 31.5) / 31.0) ** 2 < 1.0
    px = np.zeros((64, 64, 4), np.float32)
    px[..., 1] = 0.6
    px[..., 0] = 0.2
    px[..., 3] = inside
    leaf.pixels.foreach_set(px.reshape(-1))
    mat = _material("Leaves", (0.2, 0.6, 0.1), roughness=0.6)
    tree = mat.node_tree
    tex = tree.nodes.new("ShaderNodeTexImage")
    tex.image = leaf
    tree.links.new(tex.outputs["Color"], _principled(mat).inputs["Base Color"])
    tree.links.new(tex.outputs["Alpha"], _principled(mat).inputs["Alpha"])
    if hasattr(mat, "surface_render_method"):
        mat.use_transparent_shadow = True  # the leaves' shadows (4.2+'s default)
    elif hasattr(mat, "blend_method"):
        mat.blend_method = mat.shadow_method = 'CLIP'  # the leaves' shadows, as a foliage artist sets them
    for k in range(3):
        bpy.ops.mesh.primitive_plane_add(size=1.2, location=((k - 1) * 0.9, 0.3 * k, 0.9), rotation=(math.pi / 2, 0.0, 0.3 * k))
        bpy.context.object.data.materials.append(mat)
    _floor(rgb=(0.45, 0.35, 0.25))
    return Zoo("alpha_cards", "foliage cards: an image's alpha clipped (dithered on 4.2+), casting the leaves' shadows",
               False, ())


def emissive_panel():
    scene = _scene()
    _world(scene, rgb=(0.01, 0.01, 0.015))
    helpers.add_camera((2.4, -3.4, 1.8), (0.0, 0.0, 0.7))
    helpers.add_sun((0.2, -0.4, 1.0), 0.5)
    panel = zoo.box("Panel", 1.0, location=(0.0, 0.0, 0.8))
    panel.scale = (1.2, 0.1, 0.8)
    glow = _material("Screen", (0.05, 0.05, 0.05), roughness=0.2, radius=0.01)
    node = _principled(glow)
    (node.inputs.get("Emission Color") or node.inputs["Emission"]).default_value = (0.3, 0.7, 1.0, 1.0)
    node.inputs["Emission Strength"].default_value = 3.0
    panel.data.materials.append(glow)
    _floor(rgb=(0.3, 0.3, 0.3))
    return Zoo("emissive_panel", "a glowing screen in a dark scene (its glow lights nothing)", True, ())


def toon_character():
    scene = _scene()
    _world(scene, rgb=(0.3, 0.3, 0.35))
    helpers.add_sun((0.6, -0.3, 1.0), 3.0)
    helpers.add_camera((0.0, -5.0, 1.8), (0.0, 0.0, 1.0))
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=32, v_segments=16, radius=0.5)
    me = bpy.data.meshes.new("Body")
    bm.to_mesh(me)
    bm.free()
    body = bpy.data.objects.new("Body", me)
    body.scale = (0.8, 0.8, 1.6)
    body.location = (0.0, 0.0, 0.85)
    bpy.context.scene.collection.objects.link(body)
    for p in me.polygons:
        p.use_smooth = True
    mat = _material("Cel", (0.9, 0.4, 0.3), roughness=0.5)
    mat.edgelight.shading = 'RAMP'
    tex = mat.node_tree.nodes.new("ShaderNodeTexImage")
    tex.image = bpy.data.images.new("Shirt", 64, 64)
    tex.image.generated_type = 'UV_GRID'
    mat.node_tree.links.new(tex.outputs["Color"], _principled(mat).inputs["Base Color"])
    me.materials.append(mat)
    floor = _floor(rgb=(0.7, 0.7, 0.6))
    floor.active_material.edgelight.shading = 'RAMP'
    return Zoo("toon_character", "a textured toon figure casting a cel shadow", False, ())


def sunlit_room():
    scene = _scene()
    _world(scene, rgb=(0.3, 0.4, 0.6), strength=0.5)
    helpers.add_sun((-0.6, 1.0, 0.8), 4.0)
    helpers.add_camera((0.0, -1.8, 1.3), (0.0, 0.5, 0.9), lens=20.0)
    wall = _material("Plaster", (0.8, 0.78, 0.72), roughness=0.9, radius=0.02)
    # Floor, side walls and ceiling; the back wall in four pieces round a window.
    pieces = [((0.0, 0.0, -0.05), (4.0, 4.0, 0.1)), ((-2.0, 0.0, 1.5), (0.1, 4.0, 3.0)), ((2.0, 0.0, 1.5), (0.1, 4.0, 3.0)),
              ((0.0, 0.0, 3.0), (4.0, 4.0, 0.1)),
              ((-1.25, 2.0, 1.5), (1.5, 0.1, 3.0)), ((1.25, 2.0, 1.5), (1.5, 0.1, 3.0)),
              ((0.0, 2.0, 0.4), (1.0, 0.1, 0.8)), ((0.0, 2.0, 2.55), (1.0, 0.1, 0.9))]
    for k, (loc, size) in enumerate(pieces):
        ob = zoo.box(f"Wall{k}", 1.0, location=loc)
        ob.scale = size
        ob.data.materials.append(wall)
    table = zoo.box("Table", 1.0, location=(0.3, 0.6, 0.4))
    table.scale = (0.9, 0.6, 0.8)
    table.data.materials.append(_material("Wood", (0.45, 0.28, 0.15), roughness=0.5, radius=0.03))
    return Zoo("sunlit_room", "a room lit by the sun through a window", True, ())


def glass():
    scene = _scene()
    _world(scene, hdri="city")
    helpers.add_camera((2.5, -3.2, 1.8), (0.0, 0.0, 0.5))
    bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=0.6, location=(0.0, 0.0, 0.6))
    bpy.ops.object.shade_smooth()
    mat = bpy.data.materials.new("Glass")
    mat.use_nodes = True
    tree = mat.node_tree
    for n in [n for n in tree.nodes if n.type == 'BSDF_PRINCIPLED']:
        tree.nodes.remove(n)
    glass_node = tree.nodes.new("ShaderNodeBsdfGlass")
    out = next(n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL')
    tree.links.new(glass_node.outputs[0], out.inputs["Surface"])
    bpy.context.object.data.materials.append(mat)
    _floor(rgb=(0.5, 0.5, 0.5))
    return Zoo("glass", "a glass ball: declared unsupported", False, ("Glass BSDF",))


SCENES = (metals_under_an_hdri, textured_prop, vertex_coloured_low_poly, alpha_clipped_cards, emissive_panel,
          toon_character, sunlit_room, glass)
