"""A scripted UI session under xvfb-run, for the viewport tests (not run by runner.py):

    xvfb-run -s "-screen 0 1400x1000x24" blender --factory-startup --addons edgelight \
        blend_samples/cube.blend --python tests/blender/viewport_session.py -- OUT_DIR

Steps run from a timer so Blender's event loop draws between them. Prints a pass/fail line
per check and 'viewport: N passed, N failed'; exits 1 on any failure.
"""
import json
import os
import sys

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ui_session  # noqa: E402
from ui_session import check  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else "/tmp/edgelight_viewport"
os.makedirs(OUT, exist_ok=True)
A, B = np.array((-1.0, -1.0, 1.0)), np.array((1.0, -1.0, 1.0))  # the cube's glinting edge


def view3d():
    for window in bpy.context.window_manager.windows:
        for area in window.screen.areas:
            if area.type == 'VIEW_3D':
                region = next(r for r in area.regions if r.type == 'WINDOW')
                return window, area, region
    raise RuntimeError("no 3D view")


def counters():
    import edgelight
    state = edgelight.host.viewport.last_state
    return state.counters.as_dict() if state else {}


def redraw():
    _, area, _ = view3d()
    area.tag_redraw()


def screenshot(name):
    window, area, region = view3d()
    path = os.path.join(OUT, name + ".png")
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.screen.screenshot(filepath=path)
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float32).reshape(h, w, img.channels)
    bpy.data.images.remove(img)
    return px, path


def note_area(name, area):
    """Records where `area` is in screenshot `name` (OUT/areas.json: left, top, right, bottom from
    the top-left), for scripts/docs_images.py to crop the docs' copy to it."""
    path, boxes = os.path.join(OUT, "areas.json"), {}
    if os.path.exists(path):
        with open(path) as f:
            boxes = json.load(f)
    top = bpy.context.window_manager.windows[0].height - (area.y + area.height)
    boxes[name] = [area.x, top, area.x + area.width, top + area.height]
    with open(path, "w") as f:
        json.dump(boxes, f, indent=1)


def to_window_pixels(points):
    """World points -> screenshot pixels (bottom-left origin), through the 3D view's matrices."""
    _, _, region = view3d()
    rv3d = region.data
    m = np.array(rv3d.perspective_matrix, dtype=np.float64)
    p = np.c_[np.asarray(points, np.float64), np.ones(len(points))] @ m.T
    ndc = p[:, :2] / p[:, 3:4]
    return (ndc * 0.5 + 0.5) * np.array([region.width, region.height]) + np.array([region.x, region.y])


def properties_editor():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == 'PROPERTIES')
    return window, area, next(r for r in area.regions if r.type == 'WINDOW')


def panel_polls(names):
    """{panel: its poll in the Properties editor's context} (False for a name this Blender lacks)."""
    window, area, region = properties_editor()
    out = {}
    with bpy.context.temp_override(window=window, area=area, region=region):
        for name in names:
            cls = getattr(bpy.types, name, None)
            out[name] = bool(cls and cls.poll(bpy.context))
    return out


# tab: (object made active, panels that must show, panels that must not)
TABS = {
    'MATERIAL': ("Cube", ("EEVEE_MATERIAL_PT_context_material", "EDGELIGHT_PT_material_surface", "EDGELIGHT_PT_material"),
                 ("EEVEE_MATERIAL_PT_surface", "EEVEE_MATERIAL_PT_volume", "EEVEE_MATERIAL_PT_settings", "MATERIAL_PT_freestyle_line")),
    'DATA': (None, ("DATA_PT_context_light", "EDGELIGHT_PT_light"),
             ("DATA_PT_EEVEE_light", "DATA_PT_EEVEE_shadow", "DATA_PT_light")),
    'WORLD': ("Cube", ("WORLD_PT_context_world", "EEVEE_WORLD_PT_surface"), ("EEVEE_WORLD_PT_volume",)),
}


def properties_tabs():
    window, area, _ = properties_editor()
    view_layer = bpy.context.view_layer
    light = next(ob for ob in bpy.context.scene.objects if ob.type == 'LIGHT')
    active = view_layer.objects.active
    previous = area.spaces.active.context
    for tab, (ob_name, shown, hidden) in TABS.items():
        view_layer.objects.active = bpy.data.objects[ob_name] if ob_name else light
        area.spaces.active.context = tab
        area.tag_redraw()
        yield 0.5
        px, path = screenshot("properties_" + tab.lower())
        note_area("properties_" + tab.lower(), area)
        crop = px[area.y:area.y + area.height, area.x:area.x + area.width, :3]
        polls = panel_polls(shown + hidden)
        check(f"{tab.lower()} tab: Blender's panels EdgeLight honours show, the others don't",
              all(polls[n] for n in shown) and not any(polls[n] for n in hidden) and crop.std() > 0.02,
              f"{path}: {polls}")
    area.spaces.active.context = previous
    view_layer.objects.active = active


def _split_texts(items, labels, checks, in_split=False):
    """From UILayout.introspect(): the texts of property-split labels (a split's first column)
    and of checkboxes in a split's value column (a boolean property drawn with its name); a
    checkbox outside a split has the panel's whole width."""
    for item in items:
        if not isinstance(item, dict):
            continue
        split = item.get("type") == 'LAYOUT_SPLIT'
        if split and item.get("items"):
            labels += [b["draw_string"] for b in item["items"][0].get("items", [])
                       if isinstance(b, dict) and b.get("draw_string") and "rna" not in b]
        rna = item.get("rna", "")
        if in_split and rna and item.get("draw_string"):
            struct, prop = rna.split("[")[0].rsplit(".", 1)
            owner = getattr(bpy.types, struct, None) or next(  # add-on groups are not in bpy.types
                (c for c in bpy.types.PropertyGroup.__subclasses__() if c.__name__ == struct), None)
            prop_rna = owner.bl_rna.properties.get(prop) if owner else None
            if prop_rna is not None and prop_rna.type == 'BOOLEAN':
                checks.append(item["draw_string"])
        _split_texts(item.get("items", ()), labels, checks, in_split or split)


def text_width(text):
    import blf
    style = bpy.context.preferences.ui_styles[0].widget_label
    try:
        blf.size(0, style.points * bpy.context.preferences.system.ui_scale)
    except TypeError:  # 3.4 still takes a dpi
        blf.size(0, style.points, 72)
    return blf.dimensions(0, text)[0]


def panel_labels():
    """Every label EdgeLight's panels draw fits where Blender's own "Render Engine" label does:
    the property split gives labels 40 % of the row and values 60 %, so a label may be as wide as
    "Render Engine" and a checkbox's text 1.5 times that less the box. Read from what the panels
    really laid out (UILayout.introspect) and measured in the UI's font."""
    import edgelight
    from edgelight.host.panel_base import EdgeLightPanel
    window, area, _ = properties_editor()
    panels = [cls for cls in edgelight.host.ui.CLASSES if getattr(cls, "bl_context", None) in ("render", "material", "data")]
    texts, probes, polled = {}, [], set()
    # A registered panel's draw cannot be swapped (Blender holds the function): each panel is
    # drawn again by a probe panel of the same tab that calls its draw and reads the layout.
    def probe_of(cls):
        def draw(self, context):
            cls.draw(self, context)
            labels, checks = [], []
            _split_texts(self.layout.introspect(), labels, checks)
            texts[cls.__name__] = (labels, checks)

        def poll(_probe, context):
            shown = cls.poll(context)
            if shown:
                polled.add(cls.__name__)
            return shown
        name = "EDGELIGHT_PT_probe_" + cls.__name__[len("EDGELIGHT_PT_"):]
        return type(name, (EdgeLightPanel, bpy.types.Panel), {
            "bl_idname": name, "bl_label": cls.bl_label, "bl_context": cls.bl_context,
            "draw": draw, "poll": classmethod(poll)})
    for cls in panels:
        probes.append(probe_of(cls))
        bpy.utils.register_class(probes[-1])
    view_layer = bpy.context.view_layer
    light = next(ob for ob in bpy.context.scene.objects if ob.type == 'LIGHT')
    active, previous = view_layer.objects.active, area.spaces.active.context
    lines_on = bpy.context.scene.edgelight.use_lines
    bpy.context.scene.edgelight.use_lines = True
    try:
        for tab, ob in (('RENDER', None), ('MATERIAL', bpy.data.objects["Cube"]), ('DATA', light)):
            view_layer.objects.active = ob or active
            yield 0.3
            area.spaces.active.context = tab
            area.tag_redraw()
            yield 0.5
    finally:
        for probe in probes:
            bpy.utils.unregister_class(probe)
        bpy.context.scene.edgelight.use_lines = lines_on
        view_layer.objects.active = active
        area.spaces.active.context = previous
    reference = text_width("Render Engine")
    box = 30 * bpy.context.preferences.system.ui_scale  # the checkbox and its margins: 1.5 UI units
    too_wide = [(name, t, round(text_width(t))) for name, (labels, checks) in texts.items()
                for t, limit in [(t, reference) for t in labels] + [(t, 1.5 * reference - box) for t in checks]
                if text_width(t) > limit]
    boxes = sorted({(t, round(text_width(t))) for _labels, checks in texts.values() for t in checks})
    unmeasured = sorted(polled - set(texts))  # shown, but its draw failed before the layout was read
    check("panels: every EdgeLight label fits where Blender's 'Render Engine' does",
          len(texts) >= 10 and not unmeasured and not too_wide, f"drawn {sorted(texts)}; limits {reference:.0f} px, checkboxes "
          f"{1.5 * reference - box:.0f} px; too wide {too_wide}; checkboxes {boxes}; unmeasured {unmeasured}")
    crease = [t for labels, _ in texts.values() for t in labels if "Crease" in t or "Normals" in t]
    check("panels: the crease angle shown once", crease == ["Crease Angle"], f"{crease}")


def steps():
    window, area, region = view3d()
    area.spaces.active.shading.type = 'RENDERED'
    area.spaces.active.overlay.show_overlays = False
    region.data.view_perspective = 'CAMERA'
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.view3d.view_center_camera()
    bpy.context.scene.view_settings.view_transform = 'Standard'
    yield 1.5
    redraw()
    yield 1.0

    # 1. Rendered shading shows the highlight along the cube's glinting edge.
    px, path = screenshot("rendered")
    note_area("rendered", area)
    lum = px[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    ts = np.linspace(0.2, 0.8, 9)
    line = to_window_pixels(A[None] + ts[:, None] * (B - A)[None])
    s0, s1 = to_window_pixels([A, B])
    d = (s1 - s0) / np.linalg.norm(s1 - s0)
    n = np.array([-d[1], d[0]])
    def at(xy):
        x, y = np.floor(xy).astype(int).T
        return lum[np.clip(y, 0, lum.shape[0] - 1), np.clip(x, 0, lum.shape[1] - 1)]
    glint = np.max([at(line + o * n) for o in np.arange(-2.0, 2.5, 0.5)], axis=0)
    faces = np.maximum(at(line + 10 * n), at(line - 10 * n))
    check("screenshot shows the glint brighter than both faces", (glint > faces + 0.03).all(),
          f"{path}: margin min {np.min(glint - faces):.3f}")
    c0 = counters()
    check("viewport drew with EdgeLight", c0.get("passes", 0) >= 1 and c0.get("edges_drawn", 0) > 0, json.dumps(c0))

    # 2. A redraw with nothing changed: no native call, no upload, no pass.
    redraw()
    yield 0.5
    c1 = counters()
    check("static redraw: zero native calls", c1["native_calls"] == c0["native_calls"])
    check("static redraw: zero uploads", c1["uploads"] == c0["uploads"])
    check("static redraw: cache hit, no pass", c1["cache_hits"] > c0["cache_hits"] and c1["passes"] == c0["passes"],
          json.dumps(c1))

    # 3. Moving the view: view-dependent work only.
    region.data.view_perspective = 'PERSP'
    region.data.view_distance *= 1.2
    redraw()
    yield 0.5
    c2 = counters()
    check("moved view: no native call, no upload", c2["native_calls"] == c1["native_calls"] and c2["uploads"] == c1["uploads"])
    check("moved view: view-dependent pass", c2["view_changes"] > c1["view_changes"] and c2["passes"] > c1["passes"],
          json.dumps(c2))

    # 4. Editing one mesh rebuilds only that object.
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(4.0, 0.0, 0.0))
    yield 0.5
    redraw()
    yield 0.5
    c3 = counters()
    cube = bpy.data.objects["Cube"]
    cube.data.vertices[0].co.z -= 0.2
    cube.data.update()
    yield 0.5
    redraw()
    yield 0.5
    c4 = counters()
    check("edited mesh: one object re-extracted", c4["extracts"] - c3["extracts"] == 1, f"{c3['extracts']} -> {c4['extracts']}")
    check("edited mesh: one native build", c4["native_calls"] - c3["native_calls"] == 1)
    # Its surface, edge and corner batches (a cube: one slot, eight corners).
    check("edited mesh: only its batches uploaded", 0 < c4["uploads"] - c3["uploads"] <= 3, f"{c3['uploads']} -> {c4['uploads']}")

    # 5. A material change: new shading, no native call; a radius change re-uploads edges only.
    mat = bpy.data.materials["Cube"]
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.1, 0.3, 0.8, 1.0)
    yield 0.5
    redraw()
    yield 0.5
    c5 = counters()
    check("material colour: no native call, no upload", c5["native_calls"] == c4["native_calls"] and c5["uploads"] == c4["uploads"],
          f"{c4['uploads']} -> {c5['uploads']}")
    check("material colour: a new image", c5["passes"] > c4["passes"])
    mat.edgelight.radius = 0.05
    yield 0.5
    redraw()
    yield 0.5
    c6 = counters()
    check("material radius: no native call, only the edge and corner batches re-uploaded",
          c6["native_calls"] == c5["native_calls"] and c6["uploads"] - c5["uploads"] == 2, f"{c5['uploads']} -> {c6['uploads']}")
    from edgelight.host.clamp_notes import NOTES as notes
    held = notes.radius_clamps(mat)  # no final render at 0.05 yet: the view's own
    check("material radius: the panel's clamp note counts the edges the view chose again",
          held is not None and held[1] > 0, f"{held}")

    # 6. Ink lines: silhouettes are view-dependent (native view calls on a new view only),
    # creases static (rebuilt when their angle changes, with no mesh build).
    before, _ = screenshot("before_lines")
    scene = bpy.context.scene
    scene.edgelight.use_lines = True
    scene.edgelight.line_silhouette.width = 3.0
    yield 0.5
    redraw()
    yield 0.5
    after, path = screenshot("lines")
    note_area("lines", area)
    c7 = counters()
    dark = lambda img: int((img[..., :3].max(axis=2) < 0.02).sum())  # noqa: E731
    check("lines: drawn in the viewport, black ink on screen", c7["lines_drawn"] > 0 and dark(after) > dark(before) + 200,
          f"{path}: {c7['lines_drawn']} segments, dark pixels {dark(before)} -> {dark(after)}")
    check("lines: silhouettes from a native view call, no mesh build",
          c7["view_calls"] > c6["view_calls"] and c7["native_calls"] == c6["native_calls"], json.dumps(c7))
    redraw()
    yield 0.5
    c8 = counters()
    check("lines: static redraw makes no view call and no upload",
          c8["view_calls"] == c7["view_calls"] and c8["view_uploads"] == c7["view_uploads"] and c8["uploads"] == c7["uploads"]
          and c8["cache_hits"] > c7["cache_hits"])
    region.data.view_rotation.rotate(__import__("mathutils").Euler((0.0, 0.0, 0.3)))
    redraw()
    yield 0.5
    c9 = counters()
    check("lines: moved view re-runs view calls only",
          c9["view_calls"] > c8["view_calls"] and c9["native_calls"] == c8["native_calls"] and c9["uploads"] == c8["uploads"],
          f"view calls {c8['view_calls']} -> {c9['view_calls']}")
    scene.edgelight.crease_angle = 1.2
    yield 0.5
    redraw()
    yield 0.5
    c10 = counters()
    check("lines: crease angle change re-chooses static lines without a mesh build",
          c10["native_calls"] == c9["native_calls"] and c10["uploads"] > c9["uploads"], f"uploads {c9['uploads']} -> {c10['uploads']}")

    # 7. Geometry Nodes instances: 100 studs from one cone, one native mesh for all of them;
    # moving their host re-extracts nothing.

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import edgelight
    import scene_zoo as zoo
    state = edgelight.host.viewport.last_state
    before_instances = len(state.instances)

    def studs(nodes, links, group_in):
        grid = nodes.new('GeometryNodeMeshGrid')
        grid.inputs["Vertices X"].default_value = grid.inputs["Vertices Y"].default_value = 10
        cone = nodes.new('GeometryNodeMeshCone')
        cone.inputs["Radius Bottom"].default_value = 0.05
        cone.inputs["Depth"].default_value = 0.2
        inst = nodes.new('GeometryNodeInstanceOnPoints')
        links.new(grid.outputs["Mesh"], inst.inputs["Points"])
        links.new(cone.outputs["Mesh"], inst.inputs["Instance"])
        return inst.outputs["Instances"]

    host = zoo.box("Studs", 0.1, (0.0, 0.0, 1.2))
    zoo.geometry_nodes(host, studs)
    yield 0.5
    redraw()
    yield 0.5
    c11 = counters()
    check("instances: 100 Geometry Nodes instances drawn from one native mesh",
          len(state.instances) == before_instances + 100 and c11["native_calls"] == c10["native_calls"] + 1,
          f"instances {before_instances} -> {len(state.instances)}, native calls {c10['native_calls']} -> {c11['native_calls']}")
    host.location.x += 0.2
    yield 0.5
    redraw()
    yield 0.5
    c12 = counters()
    check("instances: moving their host re-extracts nothing",
          c12["native_calls"] == c11["native_calls"] and c12["extracts"] == c11["extracts"] and c12["passes"] > c11["passes"],
          f"extracts {c11['extracts']} -> {c12['extracts']}")
    # A material's bad X-Toon image (1 x 1) falls back for that material with a report; the
    # view keeps drawing.
    tiny = bpy.data.images.new("Tiny", 1, 1)
    mat = zoo.material("Studs", (0.2, 0.4, 0.8))
    mat.edgelight.shading = 'XTOON'
    mat.edgelight.xtoon_image = tiny
    tile = zoo.box("Tile", 0.3, (0.0, 0.0, 1.5))
    tile.data.materials.append(mat)
    yield 0.5
    redraw()
    yield 0.5
    c13 = counters()
    note = [r for r in state.reports if "X-Toon image 'Tiny'" in r]
    check("X-Toon: a 1 x 1 image falls back for its material, the view keeps drawing",
          len(note) == 1 and c13["passes"] > c12["passes"], f"reports {state.reports[-2:]}")
    bpy.data.objects.remove(host)
    bpy.data.objects.remove(tile)

    # 7b. The status bar and what is drawn follow the scene: a broken object's note goes with
    # it, the edge counts follow a material change with the view unchanged, and a collection
    # hidden with its eye in the view layer is not drawn (Blender 3.4 still lists its objects).
    broken = zoo.mesh_object("Broken", [(5.0, 0.0, 0.0), (6.0, 0.0, 0.0), (6.0, 1.0, 0.0)], [(0, 1, 2)])
    broken.data.vertices[1].co = (float("nan"), 0.0, 0.0)
    yield 0.5
    redraw()
    yield 0.5
    said = [r for r in state.reports if r.startswith("Broken:")]
    bpy.data.objects.remove(broken)
    yield 0.5
    redraw()
    yield 0.5
    check("status bar: a broken object's note goes when it is deleted",
          len(said) == 1 and not [r for r in state.reports if r.startswith("Broken:")], f"{said} -> {state.reports}")
    c16 = counters()
    cube_mat = bpy.data.materials["Cube"]
    cube_mat.edgelight.radius = 0.0
    yield 0.5
    redraw()
    yield 0.5
    c17 = counters()
    cube_mat.edgelight.radius = 0.05
    check("status bar: edge counts follow a radius change, the view unchanged",
          c17["edges_drawn"] < c16["edges_drawn"] and c17["view_changes"] == c16["view_changes"],
          f"edges drawn {c16['edges_drawn']} -> {c17['edges_drawn']}")
    plain = state.status_text
    bpy.context.scene.edgelight.show_debug_stats = True
    yield 0.5
    redraw()
    yield 0.5
    counted = state.status_text
    bpy.context.scene.edgelight.show_debug_stats = False
    check("status bar: the engine's counters only with Debug's Developer Counters",
          "drawn" not in plain and "native calls" not in plain and "edges" in counted and "native calls" in counted,
          f"{plain!r} / {counted!r}")
    extra = bpy.data.collections.new("Extra")
    bpy.context.scene.collection.children.link(extra)
    ball = zoo.box("Hidden", 0.5, (0.0, 2.5, 0.5), extra)
    yield 0.5
    redraw()
    yield 0.5
    shown = len(state.instances)
    bpy.context.view_layer.layer_collection.children["Extra"].hide_viewport = True
    yield 0.5
    redraw()
    yield 0.5
    hidden = len(state.instances)
    bpy.context.view_layer.layer_collection.children["Extra"].hide_viewport = False
    yield 0.5
    redraw()
    yield 0.5
    check("a collection hidden with its eye is not drawn, and is again when shown",
          hidden == shown - 1 and len(state.instances) == shown, f"instances {shown} -> {hidden} -> {len(state.instances)}")
    bpy.data.objects.remove(ball)
    bpy.data.collections.remove(extra)

    # SVG export of the 3D view's own lines (not the scene camera's): the operator in the view.
    region.data.view_perspective = 'PERSP'
    svg_path = os.path.join(OUT, "view_lines.svg")
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.edgelight.export_svg(filepath=svg_path)
    import xml.etree.ElementTree as ET
    ok, detail = False, "no file"
    if os.path.exists(svg_path):
        root = ET.parse(svg_path).getroot()
        strokes = [e for e in root.iter() if e.tag.endswith(("polyline", "path", "line"))]
        view_box = root.get("viewBox", "")
        ok = len(strokes) > 0 and view_box.split()[2:] == [str(region.width), str(region.height)]
        detail = f"{len(strokes)} strokes, viewBox {view_box}, view {region.width} x {region.height}"
    check("SVG: the operator exports the 3D view's visible lines at the view's size", ok, detail)

    # 8. Blender's own panels in the Properties editor: the Material, Light and World tabs show
    # the panels whose settings EdgeLight honours (their poll passes in that editor) and not
    # EEVEE's that it ignores; each tab is drawn and captured.
    yield from properties_tabs()
    yield from panel_labels()

    # 9. The toon ramp's colour-ramp widget: an edit (published on the message bus as the
    # widget does) reaches the viewport through the material.
    mat = bpy.data.materials["Cube"]
    mat.edgelight.shading = 'RAMP'
    mat.edgelight.shade_ramp = edgelight.extract.color_ramp.new_ramp(((0.0, (0.1, 0.1, 0.3)), (0.5, (0.9, 0.8, 0.2))))
    yield 0.5
    redraw()
    yield 0.5
    c14 = counters()
    element = edgelight.extract.color_ramp.ramp_of(mat.edgelight).elements[1]
    element.color = (0.9, 0.2, 0.2, 1.0)
    bpy.msgbus.publish_rna(key=element.path_resolve("color", False))
    yield 0.5
    redraw()
    yield 0.5
    c15 = counters()
    check("ramp widget edit: a new viewport image", c15["passes"] > c14["passes"], f"passes {c14['passes']} -> {c15['passes']}")
    mat.edgelight.shading = 'PHONG'
    yield 0.2

    # 9b. Cast shadows in the viewport (docs/shadows.md): a floor under the cubes and a sun; with
    # Shadows on, the floor darkens where their shadow falls, and nothing gets brighter. (The
    # sample file is older than shadows, so it opened with them off: versioning, layout 6.)
    scene = bpy.context.scene
    bpy.ops.mesh.primitive_plane_add(size=40.0, location=(0.0, 0.0, -1.5))
    floor = bpy.context.object
    sun = bpy.data.objects.new("ShadowSun", bpy.data.lights.new("ShadowSun", 'SUN'))
    sun.data.energy, sun.rotation_euler = 1.5, (-0.5, 0.4, 0.0)  # the shadow falls towards the view
    scene.collection.objects.link(sun)
    # The file's own lights off meanwhile: under them the floor is white past the display's range.
    others = [ob for ob in scene.objects if ob.type == 'LIGHT' and ob is not sun and not ob.hide_viewport]
    for ob in others:
        ob.hide_viewport = True
    check("shadows: an older file opens with Shadows off", not scene.edgelight.use_shadows)
    yield 0.5
    redraw()
    yield 0.5
    off, _ = screenshot("shadows_off")
    scene.edgelight.use_shadows = True
    yield 0.5
    redraw()
    yield 0.5
    on, path = screenshot("shadows_on")
    weights = np.array([0.2126, 0.7152, 0.0722])
    change = off[..., :3] @ weights - on[..., :3] @ weights
    check("shadows: the viewport draws the cubes' shadow on the floor",
          (change > 0.05).sum() > 500 and (change < -0.02).sum() < 20,
          f"{path}: {(change > 0.05).sum()} pixels darker, {(change < -0.02).sum()} brighter")
    scene.edgelight.use_shadows = False
    bpy.data.objects.remove(floor)
    bpy.data.objects.remove(sun)
    for ob in others:
        ob.hide_viewport = False
    yield 0.5

    # 9c. An image into a material's Base Color in the viewport: the material's objects are
    # read again (their corners' UVs for the image), and the image shows.
    mat = bpy.data.materials["Cube"]
    tree = mat.node_tree
    bsdf = tree.nodes["Principled BSDF"]
    before_img, _ = screenshot("before_image")
    c16 = counters()
    red = bpy.data.images.new("RedImage", 8, 8)
    red.generated_color = (1.0, 0.0, 0.0, 1.0)
    tex = tree.nodes.new('ShaderNodeTexImage')
    tex.image = red
    tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    yield 0.5
    redraw()
    yield 0.5
    c17 = counters()
    after_img, path = screenshot("image")
    reddish = lambda img: int(((img[..., 0] > 0.15) & (img[..., 0] > 3.0 * img[..., 2])).sum())  # noqa: E731
    check("image in Base Color: the object is read again, and the image shows",
          c17["extracts"] > c16["extracts"] and reddish(after_img) > reddish(before_img) + 2000,
          f"{path}: extracts {c16['extracts']} -> {c17['extracts']}, red pixels {reddish(before_img)} -> {reddish(after_img)}")
    tree.nodes.remove(tex)
    yield 0.5

    # 9d. An Environment Texture in the world (world_light.py): the viewport reads the world again
    # and shows its image behind the objects and in their light; taken out, the world's colour
    # is back.
    world = bpy.context.scene.world
    world.use_nodes = True
    wtree = world.node_tree
    background = next(n for n in wtree.nodes if n.type == 'BACKGROUND')
    green = bpy.data.images.new("GreenSky", 64, 32, float_buffer=True)
    green.pixels.foreach_set(np.tile(np.float32([0.05, 0.8, 0.1, 1.0]), 64 * 32))
    before_env, _ = screenshot("before_environment")
    env = wtree.nodes.new('ShaderNodeTexEnvironment')
    env.image = green
    wtree.links.new(env.outputs["Color"], background.inputs["Color"])
    yield 0.5
    redraw()
    yield 0.5
    after_env, path = screenshot("environment")
    greenish = lambda img: int(((img[..., 1] > 0.3) & (img[..., 1] > 2.0 * img[..., 0])).sum())  # noqa: E731
    check("environment texture: the viewport shows the world's image",
          greenish(after_env) > greenish(before_env) + 20000,
          f"{path}: green pixels {greenish(before_env)} -> {greenish(after_env)}")
    # Turning it (a Mapping node's rotation) draws again: the image is half green, half red.
    halves = bpy.data.images.new("HalfSky", 64, 32, float_buffer=True)
    px = np.tile(np.float32([0.05, 0.8, 0.1, 1.0]), (32, 64, 1))
    px[:, 32:] = (0.8, 0.05, 0.1, 1.0)
    halves.pixels.foreach_set(px.reshape(-1))
    env.image = halves
    mapping = wtree.nodes.new('ShaderNodeMapping')
    wtree.links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    coords = wtree.nodes.new('ShaderNodeTexCoord')
    wtree.links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
    yield 0.5
    redraw()
    yield 0.5
    before_turn, _ = screenshot("environment_halves")
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, 3.14159265)
    yield 0.5
    redraw()
    yield 0.5
    turned, path = screenshot("environment_turned")
    reddish_sky = lambda img: int(((img[..., 0] > 0.3) & (img[..., 0] > 2.0 * img[..., 1])).sum())  # noqa: E731
    check("environment texture: turning its Mapping node draws it turned",
          abs(reddish_sky(turned) - reddish_sky(before_turn)) > 20000,
          f"{path}: red pixels {reddish_sky(before_turn)} -> {reddish_sky(turned)}")
    for node in (env, mapping, coords):
        wtree.nodes.remove(node)
    yield 0.5
    redraw()
    yield 0.5
    gone, path = screenshot("environment_removed")
    check("environment texture: taken out, the world's colour is back",
          greenish(gone) < greenish(before_env) + 200, f"{path}: green pixels {greenish(gone)}")

    # 10. A final render started from the UI as an artist would (a render job with its own GPU
    # context, not -b).
    import edgelight
    edgelight.host.engine.capture = True
    edgelight.host.engine.last_render.clear()
    bpy.context.scene.edgelight.samples = 2
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.render.render('INVOKE_DEFAULT')
    for _ in range(120):
        yield 0.5
        if "stats" in edgelight.host.engine.last_render and not bpy.app.is_job_running('RENDER'):
            break
    rec = edgelight.host.engine.last_render
    hl = rec.get("highlight")
    check("F12 from the UI completes with highlights", hl is not None and (hl[..., 3] > 0).sum() > 100,
          f"edges drawn {getattr(rec.get('stats'), 'edges_drawn', None)}")

    # 9. A multi-sample F12: progress per sample and partial images reach Blender while it
    # renders; Esc pressed in the render window (xdotool, from a shell: Blender's own event loop
    # is what is measured). On 3.4 the main thread waits for the render's GPU context lock
    # until render() returns (docs/addon.md, "Progress and cancel"), so the freeze and the
    # cancel are measured and printed, not required.
    import subprocess
    import time
    edgelight.host.engine.last_render.clear()
    scene = bpy.context.scene
    yield from set_ints([("scene.edgelight.samples", 64), ("scene.render.resolution_x", 1920),
                         ("scene.render.resolution_y", 1080), ("scene.render.resolution_percentage", 100)])
    esc = subprocess.Popen(["sh", "-c", "sleep 2; w=$(xdotool search --name 'Blender Render' | tail -1); "
                            "[ -n \"$w\" ] && xdotool key --window \"$w\" Escape"])
    invoked = time.monotonic()
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.render.render('INVOKE_DEFAULT')
    ticks = [invoked]
    for _ in range(1200):
        yield 0.1
        ticks.append(time.monotonic())
        if "stats" in edgelight.host.engine.last_render and not bpy.app.is_job_running('RENDER'):
            break
    esc.wait(timeout=30)
    rec = edgelight.host.engine.last_render
    progress = rec.get("progress", [])
    done = [p[0] for p in progress]
    span = progress[-1][2] - progress[0][2] if progress else 0.0
    stats = rec.get("stats")
    check("F12 progress: reported after every sample, while rendering",
          done == list(range(1, len(done) + 1)) and len(done) == getattr(stats, "samples", -1) and span > 0.2,
          f"{len(done)} progress reports over {span:.2f} s, {rec.get('previews', 0)} partial images")
    print(f"NOTE F12 from the UI: longest main-thread pause {np.max(np.diff(ticks)):.2f} s; Esc at 2 s: "
          f"{getattr(stats, 'samples', None)}/{getattr(stats, 'samples_requested', None)} samples drawn", flush=True)
    yield from failed_render(window, area, region)


def window_screenshot(win, name):
    """A screenshot of window `win`, (h, w, 3) float from the top-left."""
    path = os.path.join(OUT, name + ".png")
    with bpy.context.temp_override(window=win, area=win.screen.areas[0]):
        bpy.ops.screen.screenshot(filepath=path)
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float32).reshape(h, w, img.channels)[::-1, :, :3]
    bpy.data.images.remove(img)
    return px, path


def set_ints(pairs):
    """Sets integer settings ((data path from the context, value), ...) through
    wm.context_set_int. Blender's write guard ("Writing to ID classes in this context is not
    allowed") is one flag shared by its threads, each Python call restoring the value it found:
    an F12 whose render() began while the main thread drew a panel puts back "refused" when it
    returns, and a timer's plain assignment is then refused for the rest of the session (CI,
    once). An operator's execute runs with writes allowed whatever the flag holds."""
    for _ in range(100):
        for path, value in pairs:
            bpy.ops.wm.context_set_int(data_path=path, value=value)
        got = [eval("bpy.context." + path) for path, _ in pairs]  # noqa: S307 (the test's own paths)
        if got == [value for _, value in pairs]:
            return
        yield 0.2
    raise RuntimeError(f"settings stayed {got}; wanted {pairs}")


RESOLUTION_SAMPLES = ("scene.render.resolution_x", "scene.render.resolution_y", "scene.edgelight.samples")


def settings_when_allowed(scene, values):
    """Sets (resolution x, y, EdgeLight samples): set_ints."""
    yield from set_ints(list(zip(RESOLUTION_SAMPLES, values)))


def failed_render(window, area, region):
    """11. An F12 that fails (wider than the GPU's textures): the error shows where the artist is
    looking, not only in the Info editor: the render window's stats line carries it, and the
    status bar shows Blender's red report banner."""
    import gpu

    import edgelight
    scene = bpy.context.scene
    saved = scene.render.resolution_x, scene.render.resolution_y, scene.edgelight.samples
    # One pixel wider than this GPU's textures (16384 on llvmpipe, 32768 on others).
    yield from settings_when_allowed(scene, (gpu.capabilities.max_texture_size_get() + 1, 64, 1))
    edgelight.host.engine.last_render.clear()
    with bpy.context.temp_override(window=window, area=area, region=region):
        bpy.ops.render.render('INVOKE_DEFAULT')
    for _ in range(60):
        yield 0.5
        if edgelight.host.engine.last_render and not bpy.app.is_job_running('RENDER'):
            break
    yield 1.0
    yield from settings_when_allowed(scene, saved)
    errors = [m for level, m in edgelight.host.engine.last_render.get("messages", []) if level == 'ERROR']
    windows = bpy.context.window_manager.windows
    render_win = next((w for w in windows if any(a.type == 'IMAGE_EDITOR' for a in w.screen.areas) and w != window), None)
    if render_win is None:
        check("failed F12: a render window shows the result", False, f"{[w.screen.name for w in windows]}")
        return
    px, path = window_screenshot(render_win, "failed_render_window")
    # The stats line: light text in the image editor's main region's top 1.5 UI rows (below its
    # header, at the window's own scale).
    editor = next(a for a in render_win.screen.areas if a.type == 'IMAGE_EDITOR')
    main = next(r for r in editor.regions if r.type == 'WINDOW')
    top = render_win.height - (main.y + main.height)
    row = int(round(20 * bpy.context.preferences.system.ui_scale))
    band = px[top:top + int(1.5 * row)].max(axis=-1).max(axis=0) > 0.8
    text_end = int(np.nonzero(band)[0].max()) if band.any() else 0
    message = errors[0] if errors else ""
    check("failed F12: the render window's stats line carries the error",
          errors and text_end > text_width(message), f"{path}: text ends at {text_end} px, the error alone is "
          f"{text_width(message):.0f} px; {errors}")
    main, main_path = window_screenshot(window, "failed_render_status_bar")
    status = main[-24:]
    # The error report's banner: red, fading to a dark red after its flash (theme's Error).
    red = (status[..., 0] - status[..., 1] > 0.07) & (status[..., 0] - status[..., 2] > 0.08)
    check("failed F12: the status bar shows the red error banner", red.sum() > 200,
          f"{main_path}: {int(red.sum())} red pixels in the status bar")


def run():
    import edgelight
    edgelight.host.engine.capture = True  # keep the viewport state and renders for the counts read here
    ui_session.run(steps, "viewport")


run()
