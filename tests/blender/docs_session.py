"""Screenshots of what an artist sees, for docs/addon.md (scripts/docs_screenshots.sh runs this):
Blender 3.4's UI under xvfb-run, as in tests/blender/viewport_session.py, on scenes built here.

    xvfb-run -a -s "-screen 0 1400x1000x24" blender --factory-startup --addons edgelight \
        blend_samples/cube.blend --python tests/blender/docs_session.py -- OUT_DIR

(a file on the command line: without one Blender shows its splash screen over the view).

The 3D view fills the window in Rendered shading, in the camera's view at 1:1 with the render
resolution, so a shot's camera frame is what EdgeLight draws for that scene. Writes, per shot,
OUT_DIR/<shot>.png (the whole window) and its crop box and caption in OUT_DIR/shots.json;
a final render's passes as OUT_DIR/passes/<pass>.npy. scripts/docs_images.py lays them out
into docs/img/. Every shot is checked to show its feature (it differs from the shot without
it where the feature is); prints PASS/FAIL per check and exits 1 on any failure.
"""
import json
import math
import os
import sys

import bmesh
import bpy
import numpy as np
from bpy_extras.view3d_utils import location_3d_to_region_2d
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ui_session  # noqa: E402
from ui_session import check  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else "/tmp/edgelight_docs"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SAMPLES = os.path.join(ROOT, "blend_samples")
os.makedirs(os.path.join(OUT, "passes"), exist_ok=True)
shots = {}
if os.path.exists(os.path.join(OUT, "shots.json")):  # a run of some groups only keeps the others'
    with open(os.path.join(OUT, "shots.json")) as f:
        shots.update(json.load(f))


def addon():
    import edgelight
    return edgelight


# ---- the window ----------------------------------------------------------------------------------
def window():
    return bpy.context.window_manager.windows[0]


def area_of(kind):
    areas = [a for a in window().screen.areas if a.type == kind]
    return max(areas, key=lambda a: a.width * a.height) if areas else None


def region_of(area):
    return next(r for r in area.regions if r.type == 'WINDOW')


def redraw_all():
    for area in window().screen.areas:
        area.tag_redraw()


def viewport_passes():
    state = addon().host.viewport.last_state
    return state.counters.passes if state else 0


def wait_for_viewport():
    """Until the Rendered view has drawn a new image (EdgeLight's pass counter moved), then a
    little longer for the window to show it."""
    before = viewport_passes()
    for _ in range(60):
        redraw_all()
        yield 0.25
        if viewport_passes() > before:
            break
    yield 0.5


def screenshot(name):
    """The whole window as OUT/name.png; returns its pixels (top row first, RGB floats)."""
    path = os.path.join(OUT, name + ".png")
    area = area_of('VIEW_3D') or window().screen.areas[0]
    with bpy.context.temp_override(window=window(), area=area, region=region_of(area)):
        bpy.ops.screen.screenshot(filepath=path)
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float32).reshape(h, w, img.channels)[::-1, :, :3]
    bpy.data.images.remove(img)
    return px


def camera_box(scene):
    """The camera frame in window pixels (left, top, right, bottom; top-left origin), as large
    as the render resolution (the view is at 1:1)."""
    area = area_of('VIEW_3D')
    region, rv3d = region_of(area), area.spaces.active.region_3d
    cam = scene.camera
    corners = [cam.matrix_world @ v for v in cam.data.view_frame(scene=scene)]
    xy = np.array([location_3d_to_region_2d(region, rv3d, c) for c in corners])
    cx, cy = xy.mean(axis=0) + (region.x, region.y)
    w, h = scene.render.resolution_x, scene.render.resolution_y
    left, bottom = int(round(cx - w / 2)), int(round(cy - h / 2))
    win_h = window().height
    return [left, win_h - (bottom + h), left + w, win_h - bottom]


def crop(px, box):
    left, top, right, bottom = box
    return px[top:bottom, left:right]


def shot(name, caption, scene=None, box=None):
    """Screenshot `name`, recorded with its crop (the camera frame unless `box`); returns the
    crop's pixels."""
    px = screenshot(name)
    box = box or camera_box(scene)
    shots[name] = {"box": box, "caption": caption}
    with open(os.path.join(OUT, "shots.json"), "w") as f:
        json.dump(shots, f, indent=1)
    return crop(px, box)


def show_scene(scene):
    """The window shows `scene` in the 3D view's camera view, Rendered, at 1:1."""
    window().scene = scene
    area = area_of('VIEW_3D')
    space = area.spaces.active
    space.shading.type = 'RENDERED'
    space.overlay.show_overlays = False
    space.show_gizmo = False
    space.region_3d.view_perspective = 'CAMERA'
    with bpy.context.temp_override(window=window(), area=area, region=region_of(area)):
        bpy.ops.view3d.zoom_camera_1_to_1()
    space.region_3d.view_camera_offset = (0.0, 0.0)


# ---- scenes --------------------------------------------------------------------------------------
def new_scene(name, width, height, world=(0.05, 0.055, 0.065)):
    scene = bpy.data.scenes.new(name)
    scene.render.engine = 'EDGELIGHT'
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100
    scene.view_settings.view_transform = 'Standard'
    scene.world = bpy.data.worlds.new(name)
    scene.world.use_nodes = False
    scene.world.color = world
    scene.edgelight.samples = 8
    scene.edgelight.viewport_samples = 8
    return scene


def look_at(ob, location, target):
    ob.location = location
    ob.rotation_euler = (Vector(target) - Vector(location)).to_track_quat('-Z', 'Y').to_euler()


def add_camera(scene, location, target, lens=50.0):
    cam = bpy.data.objects.new(scene.name + "Camera", bpy.data.cameras.new(scene.name + "Camera"))
    cam.data.lens = lens
    scene.collection.objects.link(cam)
    look_at(cam, location, target)
    scene.camera = cam
    return cam


def add_sun(scene, towards_light, strength=3.0):
    sun = bpy.data.objects.new(scene.name + "Sun", bpy.data.lights.new(scene.name + "Sun", 'SUN'))
    sun.data.energy = strength
    scene.collection.objects.link(sun)
    look_at(sun, towards_light, (0.0, 0.0, 0.0))
    return sun


def material(name, rgb, roughness=0.4):
    mat = bpy.data.materials.new(name)
    mat.diffuse_color = (*rgb, 1.0)
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*rgb, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    return mat


def from_bmesh(scene, name, bm, mat, location=(0.0, 0.0, 0.0), smooth=False):
    mesh = bpy.data.meshes.new(name)
    bm.to_mesh(mesh)
    bm.free()
    mesh.polygons.foreach_set("use_smooth", [smooth] * len(mesh.polygons))
    mesh.materials.append(mat)
    ob = bpy.data.objects.new(name, mesh)
    ob.location = location
    scene.collection.objects.link(ob)
    return ob


def append_sample(scene, sample, names):
    """Objects of a sample .blend (with their meshes and materials) linked into `scene`."""
    with bpy.data.libraries.load(os.path.join(SAMPLES, sample + ".blend")) as (src, dst):
        dst.objects = list(names)
    for ob in dst.objects:
        scene.collection.objects.link(ob)
    return dst.objects


def highlights_scene():
    """The fandisk part (blend_samples/fandisk.blend, its material's radius), seen close."""
    scene = new_scene("Highlights", 480, 360, world=(0.05, 0.05, 0.06))
    append_sample(scene, "fandisk", ("Fandisk", "Sun"))
    add_camera(scene, (2.2, -2.0, 1.6), (0.3, 0.0, 0.3), lens=120.0)
    return scene


def torus(major=0.6, minor=0.22, rings=48, sides=24):
    bm = bmesh.new()
    verts = []
    for i in range(rings):
        u = 2 * math.pi * i / rings
        for j in range(sides):
            v = 2 * math.pi * j / sides
            r = major + minor * math.cos(v)
            verts.append(bm.verts.new((r * math.cos(u), r * math.sin(u), minor * math.sin(v))))
    for i in range(rings):
        for j in range(sides):
            a, b = i * sides + j, ((i + 1) % rings) * sides + j
            c, d = ((i + 1) % rings) * sides + (j + 1) % sides, i * sides + (j + 1) % sides
            bm.faces.new((verts[a], verts[b], verts[c], verts[d]))
    return bm


def lines_scene():
    """One object per line type: a smooth torus (smooth contours), a box (creases), an open tube
    (borders), a sphere with a meridian marked Freestyle (marked edges) and its cap of another
    material (material boundaries); every outline is a silhouette."""
    scene = new_scene("Lines", 400, 300, world=(0.06, 0.065, 0.075))
    pale = material("Pale", (0.75, 0.72, 0.66))
    bm = torus()
    from_bmesh(scene, "Torus", bm, pale, (-1.25, 0.3, 0.22), smooth=True)
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=0.9)
    box = from_bmesh(scene, "Box", bm, pale, (0.1, 1.0, 0.45))
    box.rotation_euler = (0.0, 0.0, math.radians(25.0))
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=False, segments=32, radius1=0.35, radius2=0.35, depth=1.1)
    tube = from_bmesh(scene, "Tube", bm, pale, (1.35, 0.5, 0.55), smooth=True)
    tube.rotation_euler = (math.radians(-35.0), 0.0, 0.0)
    bm = bmesh.new()
    bmesh.ops.create_uvsphere(bm, u_segments=32, v_segments=16, radius=0.5)
    sphere = from_bmesh(scene, "Sphere", bm, pale, (0.05, -0.55, 0.5), smooth=True)
    mesh = sphere.data
    cap = material("Cap", (0.35, 0.55, 0.8))
    mesh.materials.append(cap)
    for poly in mesh.polygons:
        poly.material_index = 1 if poly.center.z > 0.25 else 0
    for edge in mesh.edges:  # a meridian: edges whose two ends have x = 0 on the front (y < 0)
        a, b = (mesh.vertices[i].co for i in edge.vertices)
        if abs(a.x) < 1e-4 and abs(b.x) < 1e-4 and a.y < 0.0 and b.y < 0.0:
            edge.use_freestyle_mark = True
    add_camera(scene, (0.9, -5.2, 3.0), (0.0, 0.25, 0.35), lens=60.0)
    add_sun(scene, (0.4, -0.6, 0.9), 3.0)
    s = scene.edgelight
    s.use_lines = True
    s.crease_angle = math.radians(60.0)
    return scene


def monkey(scene, name, mat, location, levels=2):
    bm = bmesh.new()
    bmesh.ops.create_monkey(bm)
    ob = from_bmesh(scene, name, bm, mat, location, smooth=True)
    ob.rotation_euler = (0.0, 0.0, math.radians(-25.0))
    mod = ob.modifiers.new("Subdivision", 'SUBSURF')
    mod.levels = mod.render_levels = levels
    return ob


def toon_scene():
    """Three monkeys receding from the camera (X-Toon's depth axis has something to show),
    silhouettes inked."""
    scene = new_scene("Toon", 480, 300, world=(0.06, 0.065, 0.075))
    mat = material("Toon", (0.85, 0.45, 0.2), roughness=0.35)
    mat.edgelight.use_rounding = False
    for i, (x, y) in enumerate(((-1.5, 0.0), (0.4, 2.2), (2.3, 4.8))):
        monkey(scene, f"Monkey{i}", mat, (x, y, 0.0))
    add_camera(scene, (0.2, -6.5, 1.6), (0.4, 1.8, 0.0), lens=38.0)
    add_sun(scene, (0.6, -0.8, 0.7), 3.5)
    s = scene.edgelight
    s.use_lines = True
    for name in ("crease", "border"):
        getattr(s, "line_" + name).enabled = False
    s.line_silhouette.width = 2.0
    return scene, mat


# ---- the shots -----------------------------------------------------------------------------------
def highlight_shots():
    """Highlights off and on, the same view of a part."""
    scene = highlights_scene()
    show_scene(scene)
    shots_px = {}
    for on in (False, True):
        scene.edgelight.highlights = on
        yield from wait_for_viewport()
        shots_px[on] = shot(f"highlights_{'on' if on else 'off'}",
                            "Edge highlights on" if on else "Edge highlights off", scene)
    diff = np.abs(shots_px[True] - shots_px[False]).max(axis=2)
    brighter = (shots_px[True].mean(axis=2) - shots_px[False].mean(axis=2)) > 0.1
    check("highlights: the bands show, brighter than the sharp edges, nothing else changes",
          brighter.sum() > 300 and (diff > 0.02).mean() < 0.2 and shots_px[False].std() > 0.05,
          f"{int(brighter.sum())} brighter pixels, {100 * (diff > 0.02).mean():.1f} % changed")


LINE_CAPTIONS = {
    "silhouette": "Silhouettes", "crease": "Creases", "border": "Borders",
    "contour": "Smooth Contours", "marked": "Marked Edges (Freestyle)", "material": "Material Boundaries",
}


def line_shots():
    """Each line type alone, 3 px black ink, on the same scene; the scene without lines first."""
    scene = lines_scene()
    show_scene(scene)
    s = scene.edgelight
    s.use_lines = False
    yield from wait_for_viewport()
    bare = shot("lines_none", "No lines", scene)
    for name in LINE_CAPTIONS:
        s.use_lines = True
        for other in LINE_CAPTIONS:
            style = getattr(s, "line_" + other)
            style.enabled = other == name
            style.width, style.color = 3.0, (0.0, 0.0, 0.0)
        yield from wait_for_viewport()
        px = shot("lines_" + name, LINE_CAPTIONS[name], scene)
        ink = (bare.max(axis=2) - px.max(axis=2)) > 0.25
        check(f"lines: {name} drawn", ink.sum() > 150, f"{int(ink.sum())} inked pixels")
    s.use_lines = True
    for name in LINE_CAPTIONS:
        getattr(s, "line_" + name).enabled = True
    s.debug = {'EDGE_TYPES'}
    yield from wait_for_viewport()
    px = shot("lines_debug", "All, Debug: Edge Types", scene)
    colour = (px.max(axis=2) - px.min(axis=2)) > 0.5
    check("lines: the Edge Types debug view colours them", colour.sum() > 500, f"{int(colour.sum())} coloured pixels")
    s.debug = set()


def top_colours_share(px):
    """The share of the objects' pixels (not the background's colour) taken by their three
    commonest colours, in steps of 1/32."""
    q = np.round(px.reshape(-1, 3) * 32).astype(int)
    colours, counts = np.unique(q, axis=0, return_counts=True)
    counts = np.sort(counts[np.any(colours != q[0], axis=1)])  # q[0]: a corner, background
    return round(float(counts[-3:].sum() / max(counts.sum(), 1)), 3)


def toon_shots():
    scene, mat = toon_scene()
    show_scene(scene)
    s = mat.edgelight
    ramp = addon().extract.color_ramp
    modes = (
        ("toon_phong", "Blinn-Phong", dict(shading='PHONG')),
        ("toon_ramp", "Toon Ramp (Constant)", dict(shading='RAMP')),
        ("toon_xtoon_depth", "X-Toon, Depth", dict(shading='XTOON', xtoon_axis='DEPTH', xtoon_near=4.5, xtoon_far=11.0)),
        ("toon_xtoon_orientation", "X-Toon, Orientation", dict(shading='XTOON', xtoon_axis='ORIENTATION')),
    )
    s.shade_ramp = ramp.new_ramp(((0.0, (0.18, 0.07, 0.06)), (0.35, (0.55, 0.25, 0.12)), (0.8, (0.95, 0.7, 0.45))),
                                 'CONSTANT')
    px = {}
    for name, caption, settings in modes:
        for key, value in settings.items():
            setattr(s, key, value)
        yield from wait_for_viewport()
        px[name] = shot(name, caption, scene)
    names = [m[0] for m in modes]
    differ = [np.abs(px[a] - px[b]).max(axis=2).mean() for i, a in enumerate(names) for b in names[i + 1:]]
    check("toon: the four modes look different", min(differ) > 0.01, f"mean differences {np.round(differ, 3).tolist()}")
    shares = {name: top_colours_share(px[name]) for name in ("toon_phong", "toon_ramp")}
    check("toon: the constant ramp paints in bands, Blinn-Phong in gradients",
          shares["toon_ramp"] > 0.45 and shares["toon_ramp"] > 2.5 * shares["toon_phong"], f"share of the 3 commonest colours {shares}")


def compositor_scene():
    """The fandisk part with lines, every pass on, and a compositor tree that recomposes
    Combined from them (docs/addon.md, "Render passes")."""
    scene = new_scene("Passes", 400, 300, world=(0.2, 0.3, 0.4))
    append_sample(scene, "fandisk", ("Fandisk", "Sun"))
    add_camera(scene, (2.2, -2.0, 1.6), (0.0, 0.0, 0.0), lens=80.0)
    s = scene.edgelight
    s.use_lines = True
    s.line_silhouette.width, s.line_crease.width = 2.5, 1.5
    s.line_silhouette.color = (0.05, 0.05, 0.12)
    layer = scene.view_layers[0]
    layer.use_pass_z = layer.use_pass_normal = True
    for prop in ("use_pass_highlights", "use_pass_lines", "use_pass_surface"):
        setattr(layer.edgelight, prop, True)
    layer.update_render_passes()  # the settings' update asks the window's view layer, not this one
    scene.use_nodes = True
    tree = scene.node_tree
    tree.nodes.clear()
    layers = tree.nodes.new("CompositorNodeRLayers")
    layers.scene, layers.layer = scene, layer.name  # a new node shows the window's scene
    layers.location = (-600, 60)
    layers.show_preview = False
    world = tree.nodes.new("CompositorNodeRGB")
    world.label = "World colour"
    world.outputs[0].default_value = (*scene.world.color, 1.0)
    world.location = (-100, 400)
    o = layers.outputs

    def alpha_over(background, foreground, x, y, label):
        node = tree.nodes.new("CompositorNodeAlphaOver")
        node.label, node.location = label, (x, y)
        inputs = [i for i in node.inputs if i.type == 'RGBA']
        tree.links.new(background, inputs[0])
        tree.links.new(foreground, inputs[1])
        return node.outputs[0]

    image = alpha_over(o["Surface"], o["Highlights"], -300, 40, "Highlights over Surface")
    image = alpha_over(image, o["Lines"], -100, 140, "Lines over that")
    image = alpha_over(world.outputs[0], image, 100, 240, "over the world")
    composite = tree.nodes.new("CompositorNodeComposite")
    composite.location = (300, 280)
    tree.links.new(image, composite.inputs[0])
    viewer = tree.nodes.new("CompositorNodeViewer")
    viewer.location = (300, 110)
    tree.links.new(image, viewer.inputs[0])
    return scene


def compositor_shots():
    """A final render's passes (saved for docs_images.py to lay out side by side) and the
    compositor's node tree that recomposes Combined from them."""
    scene = compositor_scene()
    window().scene = scene
    el = addon()
    el.host.engine.capture = True
    el.host.engine.last_render.clear()
    bpy.ops.render.render()
    rec = el.host.engine.last_render
    passes = dict(rec.get("passes", {}), Combined=rec.get("pixels"))
    for name, data in passes.items():
        if data is not None:
            np.save(os.path.join(OUT, "passes", name + ".npy"), np.asarray(data, np.float32))
    np.save(os.path.join(OUT, "passes", "world.npy"), np.array(scene.world.color, np.float32))
    check("passes: a render wrote all six", set(passes) == {"Combined", "Depth", "Normal", "Highlights", "Lines", "Surface"}
          and all(v is not None for v in passes.values()), sorted(passes))
    if passes.get("Highlights") is not None:
        check("passes: highlights and ink in their passes",
              (passes["Highlights"][..., 3] > 0.05).sum() > 50 and (passes["Lines"][..., 3] > 0.5).sum() > 200)
    # The node editor, filling the window, framed on the tree.
    area = area_of('VIEW_3D')
    area.type = 'NODE_EDITOR'
    space = area.spaces.active
    space.tree_type = 'CompositorNodeTree'
    space.show_backdrop = False
    space.show_region_ui = space.show_region_toolbar = False
    bpy.context.preferences.view.smooth_view = 0  # View All jumps instead of animating
    # View All frames the tree with wide margins (about half size here): closer, step by step,
    # until it spans 85 % of the editor's width or height.
    region = region_of(area)

    def extent():
        corners = []
        for node in scene.node_tree.nodes:  # the nodes' bounds, in the region's pixels
            (x, y), (w, h) = node.location, node.dimensions
            corners += [region.view2d.view_to_region(x, y, clip=False),
                        region.view2d.view_to_region(x + w, y - h, clip=False)]
        return np.min(corners, axis=0), np.max(corners, axis=0)

    for _ in range(2):
        area.tag_redraw()
        yield 1.0
        with bpy.context.temp_override(window=window(), area=area, region=region):
            bpy.ops.node.select_all(action='DESELECT')
            bpy.ops.node.view_all()
            for _ in range(20):
                low, high = extent()
                if np.any((high - low) > 0.85 * np.array([region.width, region.height])):
                    break
                bpy.ops.view2d.zoom_in()
    area.tag_redraw()
    yield 1.0
    low, high = extent()
    (x0, y0), (x1, y1) = low - 30, high + 30
    x0, y0, x1, y1 = max(int(x0), 0), max(int(y0), 0), min(int(x1), region.width), min(int(y1), region.height)
    win_h = window().height
    box = [region.x + x0, win_h - (region.y + y1), region.x + x1, win_h - (region.y + y0)]
    px = shot("compositor", "The compositor recomposing Combined from EdgeLight's passes", box=box)
    check("compositor: the node tree is drawn", px.std() > 0.05, f"std {px.std():.3f}")
    area.type = 'VIEW_3D'


def clamp_note_shot():
    """The material panel's note when the radius is more than the edges' faces allow."""
    scene = new_scene("Clamp", 320, 240)
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=2.0)
    mat = material("Clamped", (0.5, 0.5, 0.55))
    mat.use_nodes = False  # a short Surface panel: EdgeLight's panel shows below it
    mat.edgelight.radius = 5.0
    cube = from_bmesh(scene, "ClampedCube", bm, mat)
    add_camera(scene, (4.5, -5.5, 4.0), (0.0, 0.0, 0.0))
    add_sun(scene, (0.3, -0.6, 0.8))
    show_scene(scene)
    yield from wait_for_viewport()
    props = area_of('PROPERTIES')
    if props is None:
        check("clamp note: a Properties editor", False)
        return
    window().view_layer.objects.active = cube
    cube.select_set(True, view_layer=window().view_layer)
    props.tag_redraw()
    yield 0.5  # the editor offers the Material tab once it has drawn with an active object
    props.spaces.active.context = 'MATERIAL'
    props.tag_redraw()
    yield 1.0
    note = addon().host.ui.radius_clamp_note(mat, scene)
    win_h = window().height
    box = [props.x, win_h - (props.y + props.height), props.x + props.width, win_h - props.y]
    shot("clamp_note", "The material panel when the faces allow less than the Radius", box=box)
    check("clamp note: the material panel says the radius is clamped", len(note) == 2 and note[0] == "12 of 12 edges clamped", str(note))


def steps():
    # The pointer rests over the window: a tooltip would open over whatever it points at.
    bpy.context.preferences.view.show_tooltips = False
    yield 1.0
    groups = {"clamp_note": clamp_note_shot, "highlights": highlight_shots, "lines": line_shots,
              "toon": toon_shots, "compositor": compositor_shots}
    only = [g for g in os.environ.get("EDGELIGHT_DOCS_SHOTS", "").split(",") if g]  # while adjusting one
    for name, group in groups.items():
        if not only or name in only:
            yield from group()


def run():
    addon().host.engine.capture = True  # the viewport's counters and the render's passes are read here
    ui_session.run(steps, "docs session")


run()
