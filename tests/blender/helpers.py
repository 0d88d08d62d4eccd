"""Shared by the add-on tests: open samples, render, find scene points in the image."""
import importlib
import os
import sys
import unittest

import bpy
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SAMPLES = os.path.join(ROOT, "blend_samples")
# The add-on's module: "edgelight" as a legacy add-on (3.4), "bl_ext.user_default.edgelight"
# as an installed extension (4.2+). Set by scripts/blender_tests.sh.
MODULE = os.environ.get("EDGELIGHT_MODULE", "edgelight")
# None when this Blender draws with the GPU here, else why not (runner.py probes once).
GPU_UNAVAILABLE = None


def addon():
    return importlib.import_module(MODULE)


def is_module_build():
    """Blender as a Python module (PyPI's bpy) has no executable of its own."""
    return not bpy.app.binary_path


def blender_command(script, *args, addon=True):
    """The command that runs `script` in a new headless Blender of this version (with the add-on
    enabled unless addon=False), as `blender -b --addons MODULE --python script -- args` does."""
    if is_module_build():
        return [sys.executable, os.path.join(HERE, "bpy_module.py"), "run" if addon else "run-bare",
                script, "--", *args]
    enable = ["--addons", MODULE] if addon else []
    return [bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1", *enable,
            "--python", script, "--", *args]


def needs_gpu():
    if GPU_UNAVAILABLE:
        raise unittest.SkipTest("needs the GPU")  # the reason: the runner's one "GPU tests skipped" line


def open_sample(name, **scene_settings):
    bpy.ops.wm.open_mainfile(filepath=os.path.join(SAMPLES, name + ".blend"))
    scene = bpy.context.scene
    scene.render.engine = "EDGELIGHT"
    scene.view_settings.view_transform = 'Standard'
    scene.edgelight.samples = scene_settings.pop("samples", 1)
    for key, value in scene_settings.items():
        setattr(scene.edgelight, key, value)
    return scene


def set_world_color(scene, rgb):
    """The world colour, in the node tree too: 5.0 versions a node-less world into one and
    renders from it, so world.color alone no longer changes what renders there."""
    scene.world.color = rgb
    if scene.world.node_tree:
        for node in scene.world.node_tree.nodes:
            if node.type == 'BACKGROUND':
                node.inputs["Color"].default_value = (*rgb, 1.0)


def render(resolution=None, expect_error=False):
    """Renders the current scene; returns the engine's record of it (pixels, buffers, camera).

    An engine ERROR report makes the operator raise RuntimeError, as Blender does for any
    operator; with expect_error the record is returned with the error text under "raised"."""
    needs_gpu()
    scene = bpy.context.scene
    if resolution:
        scene.render.resolution_x, scene.render.resolution_y = resolution
        scene.render.resolution_percentage = 100
    engine = addon().host.engine
    engine.capture = True
    engine.last_render.clear()
    try:
        bpy.ops.render.render()
    except RuntimeError as e:
        if not expect_error:
            raise
        return dict(addon().host.engine.last_render, raised=str(e))
    if expect_error:
        raise AssertionError("the render reported no error")
    return dict(addon().host.engine.last_render)


def project(rec, points):
    """World points -> pixel coordinates (x right, y up, pixel centres at .5)."""
    cam = rec["camera"]
    p = np.c_[np.asarray(points, np.float64), np.ones(len(points))]
    clip = (cam.projection @ cam.view @ p.T).T
    ndc = clip[:, :2] / clip[:, 3:4]
    return (ndc * 0.5 + 0.5) * np.array([cam.width, cam.height])


def env_specular(spec, n, nv):
    """lighting.glsl's el_env_specular: what a uniform world of radiance 1 puts into the specular
    lobe of F0 `spec` and Blinn exponent n at cos(angle to the eye) nv (the shaders' copy is
    pinned by the tests that use this one)."""
    spec = np.asarray(spec, np.float64)
    rough = (2.0 / (max(n, 0.0) + 2.0)) ** 0.25
    r = rough * np.array([-1.0, -0.0275, -0.572, 0.022]) + np.array([1.0, 0.0425, 1.04, -0.04])
    a004 = min(r[0] * r[0], 2.0 ** (-9.28 * min(max(nv, 0.0), 1.0))) * r[0] + r[1]
    a, b = -1.04 * a004 + r[2], 1.04 * a004 + r[3]
    return np.maximum((spec * a + b) * (1.0 + spec * (1.0 / max(a + b, 1e-4) - 1.0)), 0.0)


def world_on_arc(inp, eye_at_x, shading, ambient):
    """The world's light on a rounded edge as el_edge_colour takes it: ambient times the diffuse
    colour and the tinted lobe's albedo at the arc's mean cosine to the eye (the reference's
    diffuse mean with the eye as the light). `inp`: the pixel's native.HighlightInput;
    `eye_at_x`: the direction from its point to the eye."""
    native = addon().bridge.native
    light = list(inp.light)
    v = np.asarray(eye_at_x, np.float64)
    inp.light[:] = (v / np.linalg.norm(v)).tolist()
    try:
        nv = native.highlight_reference(inp).diffuse
    finally:
        inp.light[:] = light
    return np.array(ambient) * (np.array(shading.base_color)
                                + np.array(shading.tint) * env_specular(shading.spec_color, shading.shininess, nv))


def luminance(rgb):
    return rgb[..., 0] * 0.2126 + rgb[..., 1] * 0.7152 + rgb[..., 2] * 0.0722


def sample(image, xy):
    """Nearest pixel of (h, w, C) image at pixel coordinates xy."""
    x = np.clip(np.floor(xy[..., 0]).astype(int), 0, image.shape[1] - 1)
    y = np.clip(np.floor(xy[..., 1]).astype(int), 0, image.shape[0] - 1)
    return image[y, x]


def highlight_change(rec):
    """Per pixel, how much the highlight pass changes the image: its premultiplied pass's largest
    channel. A band laid over the surface has alpha W; a silhouette's band is a change of colour
    with no alpha (docs/highlight_math.md, "The band at the outline")."""
    return np.abs(np.asarray(rec["highlight"])).max(axis=-1)


def edge_profile(rec, image, a, b, ts, offsets):
    """Values of `image` across the projected edge a-b: (len(ts), len(offsets), C)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    pts = a[None] + np.asarray(ts)[:, None] * (b - a)[None]
    xy = project(rec, pts)
    sa, sb = project(rec, [a, b])
    d = (sb - sa) / np.linalg.norm(sb - sa)
    n = np.array([-d[1], d[0]])
    grid = xy[:, None, :] + np.asarray(offsets)[None, :, None] * n[None, None, :]
    return sample(image, grid)


def empty_scene(width=400, height=400, **scene_settings):
    """A factory-empty scene rendered by EdgeLight: no objects, a dark world, one sample."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import addon_utils
    addon_utils.enable(MODULE, default_set=True)  # a factory reset disables add-ons
    scene = bpy.context.scene
    scene.render.engine = "EDGELIGHT"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = 'Standard'
    world = bpy.data.worlds.new("World")
    world.use_nodes = False
    world.color = (0.05, 0.05, 0.05)
    scene.world = world
    scene.edgelight.samples = scene_settings.pop("samples", 1)
    for key, value in scene_settings.items():
        setattr(scene.edgelight, key, value)
    return scene


def look_at(ob, location, target):
    from mathutils import Vector
    ob.location = location
    ob.rotation_euler = (Vector(target) - Vector(location)).to_track_quat('-Z', 'Y').to_euler()


def add_camera(location, target=(0.0, 0.0, 0.0), lens=50.0):
    scene = bpy.context.scene
    ob = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    ob.data.lens = lens
    scene.collection.objects.link(ob)
    look_at(ob, location, target)
    scene.camera = ob
    return ob


def add_sun(direction_to_light=(0.3, -0.5, 1.0), strength=3.0, name="Sun"):
    """A sun shining from `direction_to_light` towards the origin."""
    ob = bpy.data.objects.new(name, bpy.data.lights.new(name, 'SUN'))
    ob.data.energy = strength
    bpy.context.scene.collection.objects.link(ob)
    d = np.asarray(direction_to_light, float)
    look_at(ob, tuple(d), (0.0, 0.0, 0.0))
    return ob


def only_lines(scene, **enabled):
    """Turns lines on with only the named types enabled: only_lines(scene, crease=4.0) draws
    creases 4 px wide."""
    s = scene.edgelight
    s.use_lines = True
    for name in ("silhouette", "crease", "border", "contour", "marked", "material"):
        style = getattr(s, "line_" + name)
        style.enabled = name in enabled
        if name in enabled:
            style.width = enabled[name]
    return s


_EDGE_MARKS = {  # kind: (MeshEdge property of older versions, edge attribute of newer ones)
    "freestyle": ("use_freestyle_mark", "freestyle_edge"),
    "sharp": ("use_edge_sharp", "sharp_edge"),
    "seam": ("use_seam", ".uv_seam"),
}


def mark_edge(mesh, kind, index, value=True):
    """Marks one edge Freestyle / sharp / seam on any Blender version (5.0 keeps Freestyle marks
    in an attribute only)."""
    prop, attr_name = _EDGE_MARKS[kind]
    edge = mesh.edges[index]
    if hasattr(edge, prop):
        setattr(edge, prop, value)
        return
    attr = mesh.attributes.get(attr_name) or mesh.attributes.new(attr_name, 'BOOLEAN', 'EDGE')
    attr.data[index].value = value


def line_samples(rec, per_px=1, whole_segments=False):
    """Centre-line samples of every drawn line type of a render with SVG output on (its record's
    "vector"): per_px points a pixel along each segment (`whole_segments`: only segments wholly in
    front of the eye), each taken to the pixel under it, as the line pass's fragment there sees
    it. Yields (kind, style, pix (n, 2) int, p the pixel centres, q their closest points of the
    segment, shown: whether line_visibility's rule draws the stroke there, a crease past a
    rounded outline counted as not shown)."""
    a = addon()
    vl, vis = a.linework.vector_lines, a.linework.line_visibility
    cam, vec = rec["camera"], rec["vector"]
    h, w = rec["lines"].shape[:2]
    settings = a.linework.lines.settings_of(bpy.context.scene.edgelight)
    styles = dict(settings.styles)
    for matrix, segs, iid in vl.instances_of(rec["scene"], vec.view_segments):
        for kind in settings.types:
            seg = segs.get(kind)
            if seg is None or len(seg) == 0:
                continue
            sa, sb, za, zb, t0, t1, keep = vl.project(seg, matrix, cam)
            if whole_segments:
                keep &= (t0 == 0.0) & (t1 == 1.0)
            n = np.maximum(1, np.ceil(per_px * np.linalg.norm(sb - sa, axis=1))).astype(int)
            s = np.repeat(np.flatnonzero(keep), n[keep])
            k = np.arange(len(s)) - np.repeat(np.cumsum(n[keep]) - n[keep], n[keep])
            c = sa[s] + ((k + 0.5) / n[s])[:, None] * (sb[s] - sa[s])
            pix = np.floor(c).astype(int)
            inside = np.all((pix >= 0) & (pix < [w, h]), axis=1)
            s, pix = s[inside], pix[inside]
            p = pix + 0.5  # the fragment's pixel centre and its closest point on the segment
            ab = sb[s] - sa[s]
            t = np.clip(((p - sa[s]) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-12), 0.0, 1.0)
            q = sa[s] + t[:, None] * ab
            z = 1.0 / (1.0 / za[s] + t * (1.0 / zb[s] - 1.0 / za[s]))
            outline = kind in vis.OUTLINE_TYPES
            shown = vis.visible(q, z, seg.faces[s], iid, outline, vec.depth, vec.ids, cam.px_per_unit, True)
            shown &= ~(vec.rounded & vis.past_outline(p, z, seg.faces[s], iid, outline, vec.depth, vec.ids,
                                                          cam.px_per_unit, True))
            yield kind, styles[kind], pix, p, q, shown
