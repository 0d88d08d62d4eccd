"""Ink lines (silhouette + crease + border) on libcgal-demo's meshes: EdgeLight against EEVEE +
Freestyle and against Grease Pencil Line Art, all in one Blender run (ratios are what to read:
the machine is shared).

    BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b --factory-startup \
        --python bench/lines_bench.py -- --mesh-dir build/meshes [--size 640x480] [--repeat 3] \
        [--out out/lines_bench.csv] [--meshes cow,fandisk,bunny00,armadillo] [--limit 300]

Per mesh, back to back, at the same resolution, camera, sun and 1 sample per pixel:

  EdgeLight              EDGELIGHT engine, highlights off, lines off (surface only)
  EdgeLight + lines      the same with silhouette + crease + border lines
  EEVEE                  BLENDER_EEVEE, taa_render_samples = 1
  EEVEE + Freestyle      the same with a Freestyle line set: silhouette + crease + border, visible
  Line Art eval          a Grease Pencil object with a Line Art modifier on the mesh (contour, which
                         in Line Art includes silhouettes and mesh borders, + crease): the time of
                         one depsgraph update after tagging the object, i.e. the modifier's work
  EEVEE + Line Art       a final EEVEE render with that Grease Pencil object in the scene (the
                         render depsgraph evaluates Line Art again in every render)

Crease threshold: 60 degrees between face normals (EdgeLight / Auto Smooth convention) is
180 - 60 = 120 degrees between the faces for Freestyle and Line Art: the same edges.

Each method renders once to warm up (shader compiles; that render also writes
out/lines_bench/MESH_METHOD.png); then REPEAT rounds time every method once each, round-robin, so
that the shared host's slow drifts hit all methods alike; the median is kept. A method whose
warm-up took longer than --limit seconds is not repeated: its warm-up is recorded and noted.
The Grease Pencil object stays in the scene with hide_render set except for its own render
(render depsgraphs leave hidden objects out, so no other method evaluates Line Art).
Writes a CSV (--out) and a markdown table beside it (same name, .md), and prints the table.
"""
import argparse
import datetime
import math
import os
import statistics
import sys
import tarfile
import time

import bpy
import numpy as np
from mathutils import Vector

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
CREASE_DEG = 60.0  # EdgeLight / Auto Smooth convention: angle between the face normals
LINE_PX = 1.5
VIEW_YAW_DEG = {"armadillo": 180.0}  # turn the model about Z to face the camera

METHODS = [
    # key,               label
    ("edgelight",        "EdgeLight"),
    ("edgelight_lines",  "EdgeLight + lines"),
    ("eevee",            "EEVEE"),
    ("eevee_freestyle",  "EEVEE + Freestyle"),
    ("lineart_eval",     "Line Art eval"),
    ("eevee_lineart",    "EEVEE + Line Art"),
]


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="lines_bench.py")
    p.add_argument("--mesh-dir", default=os.path.join(ROOT, "build", "meshes"))
    p.add_argument("--meshes", default="cow,fandisk,bunny00,armadillo")
    p.add_argument("--size", default="640x480")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--out", default=os.path.join(ROOT, "out", "lines_bench.csv"))
    p.add_argument("--png-dir", default=None, help="default: out/lines_bench beside --out")
    p.add_argument("--limit", type=float, default=300.0,
                   help="seconds: a method whose warm-up frame took longer is recorded once")
    a = p.parse_args(argv)
    a.width, a.height = (int(v) for v in a.size.lower().split("x"))
    a.meshes = [m for m in a.meshes.split(",") if m]
    if a.png_dir is None:
        a.png_dir = os.path.join(os.path.dirname(os.path.abspath(a.out)), "lines_bench")
    return a


def log(msg):
    print(f"[lines_bench {time.strftime('%H:%M:%S')}] {msg}", flush=True)


# ---------------------------------------------------------------------------------------------
# Meshes

def mesh_path(mesh_dir, name, fallback_dir):
    """MESH_DIR/NAME.off, else extracted from libcgal-demo's data.tar.gz into fallback_dir."""
    path = os.path.join(mesh_dir, name + ".off")
    if os.path.exists(path):
        return path
    path = os.path.join(fallback_dir, name + ".off")
    if not os.path.exists(path):
        os.makedirs(fallback_dir, exist_ok=True)
        with tarfile.open(CGAL_DATA) as tar:
            member = tar.getmember(f"data/meshes/{name}.off")
            with tar.extractfile(member) as src, open(path, "wb") as dst:
                dst.write(src.read())
    return path


def read_off(path):
    """(vertices float32 (n, 3), faces list of index arrays): OFF with optional comments, counts
    on the header line or the next one, and per-face colours after the indices."""
    with open(path) as f:
        lines = [ln.split("#", 1)[0].strip() for ln in f]
    lines = [ln for ln in lines if ln]
    head = lines[0]
    if not head.endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    rest = head[head.index("OFF") + 3:].split()
    i = 1
    if not rest:
        rest, i = lines[1].split(), 2
    nv, nf = int(rest[0]), int(rest[1])
    verts = np.array([ln.split()[:3] for ln in lines[i:i + nv]], dtype=np.float64)
    face_lines = lines[i + nv:i + nv + nf]
    rows = [ln.split() for ln in face_lines]
    if all(r[0] == "3" for r in rows):
        faces = np.array([r[1:4] for r in rows], dtype=np.int64)
    else:
        faces = [np.array(r[1:1 + int(r[0])], dtype=np.int64) for r in rows]
    return verts, faces


def build_mesh_object(name, verts, faces):
    """A flat-shaded mesh object, centred and scaled so its largest extent is 2, Y-up -> Z-up,
    turned by VIEW_YAW_DEG about Z."""
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    v = (verts - (lo + hi) / 2.0) * (2.0 / float((hi - lo).max()))
    v = np.stack([v[:, 0], -v[:, 2], v[:, 1]], axis=1)  # Y-up -> Z-up
    yaw = math.radians(VIEW_YAW_DEG.get(name, 0.0))
    c, s_ = math.cos(yaw), math.sin(yaw)
    v = np.stack([c * v[:, 0] - s_ * v[:, 1], s_ * v[:, 0] + c * v[:, 1], v[:, 2]], axis=1).astype(np.float32)
    if isinstance(faces, np.ndarray):
        counts = np.full(len(faces), faces.shape[1], dtype=np.int32)
        loops = faces.reshape(-1).astype(np.int32)
    else:
        counts = np.array([len(f) for f in faces], dtype=np.int32)
        loops = np.concatenate(faces).astype(np.int32)
    starts = np.zeros(len(counts), dtype=np.int32)
    starts[1:] = np.cumsum(counts)[:-1]
    me = bpy.data.meshes.new(name)
    me.vertices.add(len(v))
    me.vertices.foreach_set("co", v.reshape(-1))
    me.loops.add(len(loops))
    me.loops.foreach_set("vertex_index", loops)
    me.polygons.add(len(counts))
    me.polygons.foreach_set("loop_start", starts)
    me.polygons.foreach_set("loop_total", counts)
    me.update(calc_edges=True)
    me.validate(verbose=False)
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def mesh_counts(ob):
    me = ob.data
    counts = np.empty(len(me.polygons), dtype=np.int32)
    me.polygons.foreach_get("loop_total", counts)
    return int((counts - 2).sum()), len(me.edges)


# ---------------------------------------------------------------------------------------------
# Scene

def enable_edgelight():
    """The EdgeLight add-on (installed by scripts/install_addon.sh); exits with a clear message
    if Blender cannot find it."""
    import addon_utils
    if addon_utils.enable("edgelight", default_set=True) is None:
        sys.exit("lines_bench: the EdgeLight add-on is not installed "
                 "(BLENDER_USER_SCRIPTS=$(scripts/install_addon.sh) blender -b ...)")
    import edgelight
    edgelight.host.engine.capture = True  # error reports are read from the render's record
    return edgelight


def setup_scene(args):
    scene = bpy.context.scene
    for ob in list(scene.objects):
        bpy.data.objects.remove(ob, do_unlink=True)
    r = scene.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = args.width, args.height, 100
    r.image_settings.file_format = 'PNG'
    r.film_transparent = False
    scene.view_settings.view_transform = 'Standard'
    scene.frame_set(1)

    # A light grey world so that black lines read against it.
    world = scene.world or bpy.data.worlds.new("World")
    scene.world = world
    world.color = (0.7, 0.7, 0.7)
    if world.use_nodes and world.node_tree:
        for node in world.node_tree.nodes:
            if node.type == 'BACKGROUND':
                node.inputs["Color"].default_value = (0.7, 0.7, 0.7, 1.0)
                node.inputs["Strength"].default_value = 0.5

    cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    cam.data.type = 'PERSP'
    cam.data.lens = 50.0
    cam.data.sensor_fit = 'AUTO'
    scene.collection.objects.link(cam)
    scene.camera = cam

    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", 'SUN'))
    sun.data.energy = 3.0
    sun.rotation_mode = 'QUATERNION'  # light from above, a little left of the camera
    sun.rotation_quaternion = (-Vector((0.4, -1.3, 1.2)).normalized()).to_track_quat('-Z', 'Y')
    scene.collection.objects.link(sun)

    mat = bpy.data.materials.new("Clay")
    mat.diffuse_color = (0.8, 0.8, 0.8, 1.0)
    mat.use_nodes = True
    bsdf = next((n for n in mat.node_tree.nodes if n.type == 'BSDF_PRINCIPLED'), None)
    if bsdf is not None:
        bsdf.inputs["Base Color"].default_value = (0.8, 0.8, 0.8, 1.0)
        bsdf.inputs["Roughness"].default_value = 0.6
    mat.edgelight.use_rounding = False  # no rounded-edge highlights: lines are what is compared

    # Freestyle: one line set, visible silhouette + crease + border, 1.5 px black lines.
    r.line_thickness_mode = 'ABSOLUTE'
    r.line_thickness = LINE_PX
    vl = bpy.context.view_layer
    vl.use_freestyle = True
    fs = vl.freestyle_settings
    fs.mode = 'EDITOR'
    fs.crease_angle = math.radians(180.0 - CREASE_DEG)
    fs.use_culling = False
    fs.use_smoothness = False
    fs.use_suggestive_contours = False
    fs.use_ridges_and_valleys = False
    fs.use_material_boundaries = False
    fs.as_render_pass = False
    for ls in list(fs.linesets)[1:]:
        fs.linesets.remove(ls)
    ls = fs.linesets[0] if len(fs.linesets) else fs.linesets.new("Lines")
    ls.show_render = True
    ls.select_by_visibility = True
    ls.visibility = 'VISIBLE'
    ls.select_by_edge_types = True
    ls.select_by_face_marks = False
    ls.select_by_collection = False
    ls.select_by_image_border = True
    ls.edge_type_negation = 'INCLUSIVE'
    ls.edge_type_combination = 'OR'
    for t in ("silhouette", "border", "crease", "ridge_valley", "suggestive_contour",
              "material_boundary", "contour", "external_contour", "edge_mark"):
        setattr(ls, "select_" + t, t in ("silhouette", "border", "crease"))
        setattr(ls, "exclude_" + t, False)
    style = ls.linestyle or bpy.data.linestyles.new("Ink")
    ls.linestyle = style
    style.color = (0.0, 0.0, 0.0)
    style.alpha = 1.0
    style.thickness = LINE_PX
    style.thickness_position = 'CENTER'
    style.chaining = 'PLAIN'
    style.use_chaining = True
    r.use_freestyle = False
    return scene, cam, mat


def frame_camera(cam, ob, scene):
    """Perspective camera looking at the mesh from a 3/4 view, the bounding sphere in frame."""
    co = np.empty(len(ob.data.vertices) * 3, dtype=np.float32)
    ob.data.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3)
    centre = (co.min(axis=0) + co.max(axis=0)) / 2.0
    radius = float(np.linalg.norm(co - centre, axis=1).max())
    aspect = scene.render.resolution_x / scene.render.resolution_y
    half_w = math.atan(cam.data.sensor_width / 2.0 / cam.data.lens)  # sensor_fit AUTO: the wider side
    half = math.atan(math.tan(half_w) / aspect) if aspect >= 1.0 else half_w
    dist = radius / math.sin(half) * 1.02
    direction = Vector((0.9, -1.3, 0.7)).normalized()
    cam.location = Vector(centre.tolist()) + direction * dist
    cam.rotation_mode = 'QUATERNION'
    cam.rotation_quaternion = (-direction).to_track_quat('-Z', 'Y')
    cam.data.clip_start = max(1e-3, dist - radius * 1.5)
    cam.data.clip_end = dist + radius * 1.5


# ---------------------------------------------------------------------------------------------
# Methods: each sets the scene up and returns a teardown (or None)

def set_edgelight(scene, lines):
    scene.render.engine = "EDGELIGHT"
    scene.render.use_freestyle = False
    el = scene.edgelight
    el.samples = 1
    el.highlights = False
    el.use_lines = lines
    el.crease_angle = math.radians(CREASE_DEG)
    el.hidden_lines = 'OFF'  # visible lines only, like the Freestyle line set
    for k in ("line_silhouette", "line_crease", "line_border"):
        style = getattr(el, k)
        style.enabled, style.width, style.unit, style.taper = True, LINE_PX, 'PIXELS', 0.0
    for k in ("line_contour", "line_marked", "line_material"):
        getattr(el, k).enabled = False


def set_eevee(scene, freestyle):
    scene.render.engine = enable_edgelight().compat.eevee_engine_id()
    scene.eevee.taa_render_samples = 1
    scene.render.use_freestyle = freestyle


def add_lineart(scene, mesh_ob, crease_deg=CREASE_DEG, thickness=10, screen_space=False):
    """Line Art (a Grease Pencil object) drawing `mesh_ob`'s visible silhouettes and creases
    above `crease_deg` between face normals, in black: (its object, its modifier). thickness 10
    is about Freestyle's 1.5 px at 640x480 (thinner strokes fade out in places); screen_space
    makes the thickness pixels, like the other renderers' widths."""
    gpd = bpy.data.grease_pencils.new("LineArt")
    if screen_space:
        gpd.stroke_thickness_space = 'SCREENSPACE'
    gp_ob = bpy.data.objects.new("LineArt", gpd)
    scene.collection.objects.link(gp_ob)
    layer = gpd.layers.new("Lines", set_active=True)
    layer.frames.new(scene.frame_current)  # Line Art writes into the layer's current frame
    ink = bpy.data.materials.new("LineArtInk")
    bpy.data.materials.create_gpencil_data(ink)
    ink.grease_pencil.color = (0.0, 0.0, 0.0, 1.0)
    ink.grease_pencil.show_fill = False
    gpd.materials.append(ink)
    mod = gp_ob.grease_pencil_modifiers.new("LineArt", 'GP_LINEART')
    mod.source_type = 'OBJECT'
    mod.source_object = mesh_ob
    mod.target_layer = layer.info
    mod.target_material = ink
    mod.use_contour = True      # silhouettes; Line Art also marks mesh borders as contour
    mod.use_crease = True
    for flag in ("use_loose", "use_material", "use_edge_mark", "use_intersection",
                 "use_light_contour", "use_shadow"):  # the last two not on every version
        if hasattr(mod, flag):
            setattr(mod, flag, False)
    mod.crease_threshold = math.radians(180.0 - crease_deg)  # face angle, like Freestyle
    mod.use_crease_on_smooth = True  # crease on every face whatever its shading flag
    mod.level_start = mod.level_end = 0  # visible lines only
    mod.thickness = thickness
    return gp_ob, mod


def lineart_stroke_count(gp_ob):
    deps = bpy.context.evaluated_depsgraph_get()
    ev = gp_ob.evaluated_get(deps)
    return sum(len(f.strokes) for layer in ev.data.layers for f in layer.frames)


# ---------------------------------------------------------------------------------------------
# Timing

def render_once(png=None):
    scene = bpy.context.scene
    if png:
        scene.render.filepath = png
    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=bool(png))
    return time.perf_counter() - t0


def edgelight_errors():
    mod = sys.modules.get("edgelight.host.engine")
    if mod is None:
        return []
    return [m for lvl, m in mod.last_render.get("messages", []) if lvl == 'ERROR']


def time_eval(gp_ob):
    """One re-evaluation of the Line Art object: flush pending updates, tag, time the update."""
    vl = bpy.context.view_layer
    vl.update()
    gp_ob.update_tag()
    t0 = time.perf_counter()
    vl.update()
    return time.perf_counter() - t0


# ---------------------------------------------------------------------------------------------

def run_mesh(name, args, scene, cam, mat, results):
    path = mesh_path(args.mesh_dir, name, os.path.join(args.png_dir, "meshes"))
    t0 = time.perf_counter()
    verts, faces = read_off(path)
    ob = build_mesh_object(name, verts, faces)
    ob.data.materials.append(mat)
    frame_camera(cam, ob, scene)
    tris, edges = mesh_counts(ob)
    log(f"{name}: {tris} triangles, {edges} edges (loaded in {time.perf_counter() - t0:.1f} s)")
    row = {"mesh": name, "triangles": tris, "edges": edges}

    # The Line Art object exists throughout, hidden from render except for its own render:
    # render depsgraphs leave hide_render objects out, so the other methods never evaluate it.
    gp_ob, _ = add_lineart(scene, ob)
    gp_ob.hide_render = True
    bpy.context.view_layer.update()
    row["lineart_strokes"] = lineart_stroke_count(gp_ob)

    def lineart_render_setup():
        set_eevee(scene, freestyle=False)
        gp_ob.hide_render = False

    setups = {
        "edgelight": lambda: set_edgelight(scene, lines=False),
        "edgelight_lines": lambda: set_edgelight(scene, lines=True),
        "eevee": lambda: set_eevee(scene, freestyle=False),
        "eevee_freestyle": lambda: set_eevee(scene, freestyle=True),
        "lineart_eval": None,
        "eevee_lineart": lineart_render_setup,
    }
    if not row["lineart_strokes"]:
        log(f"  WARNING: Line Art produced no strokes on {name}")
    active = [key for key, _ in METHODS]
    times = {key: [] for key in active}
    notes = {key: [] for key in active}

    def measure(key, png=None):
        gp_ob.hide_render = True
        if key == "lineart_eval":
            return time_eval(gp_ob)
        setups[key]()
        t = render_once(png)
        if key.startswith("edgelight"):
            for err in edgelight_errors():
                if err not in notes[key]:
                    notes[key].append("ERROR: " + err)
        return t

    # Warm-ups, one per method (shader compiles, first Line Art evaluation); each writes its PNG.
    over_limit = {}
    for key in active:
        png = None if key == "lineart_eval" else os.path.join(args.png_dir, f"{name}_{key}.png")
        warm = measure(key, png)
        log(f"  {name} {key}: warm-up {warm * 1e3:.0f} ms")
        if warm > args.limit:
            over_limit[key] = warm
            times[key].append(warm)
            notes[key].append(f"one frame only ({warm:.0f} s > {args.limit:.0f} s limit; includes warm-up)")

    # Timed runs, round-robin over the methods so that the shared host's drifts hit all alike.
    for i in range(args.repeat):
        for key in active:
            if key in over_limit:
                continue
            times[key].append(measure(key))
        log(f"  {name} round {i + 1}/{args.repeat}: " + ", ".join(
            f"{key} {times[key][-1] * 1e3:.0f}" for key in active if key not in over_limit) + " ms")
    gp_ob.hide_render = True
    scene.render.use_freestyle = False

    for key, _ in METHODS:
        row[key] = {"times": times[key], "median": statistics.median(times[key]), "note": "; ".join(notes[key])}
        log(f"{name} {key}: median {row[key]['median'] * 1e3:.1f} ms {row[key]['note']}")
    if not row["lineart_strokes"]:
        row["lineart_eval"]["note"] = "Line Art produced no strokes"
    t0 = time.perf_counter()
    bpy.context.view_layer.update()
    log(f"  untagged depsgraph update: {(time.perf_counter() - t0) * 1e3:.2f} ms; "
        f"Line Art strokes: {row['lineart_strokes']}")

    # Unlinked, not freed: in 3.4 setting target_material from Python adds no user, so freeing
    # the modifier reports an "ID user decrement error" on the ink material.
    scene.collection.objects.unlink(gp_ob)
    me = ob.data
    bpy.data.objects.remove(ob, do_unlink=True)
    bpy.data.meshes.remove(me)
    results.append(row)


def fmt_ms(cell):
    if not cell or cell["median"] is None:
        return "n/a"
    ms = cell["median"] * 1e3
    s = f"{ms:,.0f}" if ms >= 100 else f"{ms:.1f}"
    return s + ("*" if cell["note"].startswith("one frame only") else "")


def ratio(row, a, b):
    ca, cb = row.get(a), row.get(b)
    if not ca or not cb or ca["median"] is None or cb["median"] is None or cb["median"] <= 0:
        return "n/a"
    return f"{ca['median'] / cb['median']:.2f}"


def write_outputs(args, results):
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w") as f:
        f.write("mesh,triangles,edges,method,runs,median_ms,min_ms,max_ms,note\n")
        for row in results:
            for key, _ in METHODS:
                c = row[key]
                t = [x * 1e3 for x in c["times"]]
                vals = (f"{statistics.median(t):.3f},{min(t):.3f},{max(t):.3f}" if t else ",,")
                note = c["note"].replace(",", ";")
                f.write(f"{row['mesh']},{row['triangles']},{row['edges']},{key},{len(t)},{vals},{note}\n")

    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    lines = [
        f"Blender {bpy.app.version_string}, {args.width}x{args.height}, 1 sample per pixel, "
        f"median of {args.repeat} round-robin runs after a warm-up, ms per frame; crease {CREASE_DEG:.0f}° "
        f"between face normals (Freestyle and Line Art: {180 - CREASE_DEG:.0f}° face angle); "
        f"{datetime.date.today().isoformat()}, load {load}.",
        "",
        "| mesh | triangles | edges | " + " | ".join(label for _, label in METHODS)
        + " | Freestyle / EdgeLight lines | EEVEE+Freestyle / EEVEE | Line Art eval / EdgeLight lines |",
        "|---|---:|---:|" + "---:|" * (len(METHODS) + 3),
    ]
    for row in results:
        cells = [fmt_ms(row[key]) for key, _ in METHODS]
        lines.append(
            f"| {row['mesh']} | {row['triangles']:,} | {row['edges']:,} | " + " | ".join(cells) + " | "
            + " | ".join([ratio(row, "eevee_freestyle", "edgelight_lines"),
                          ratio(row, "eevee_freestyle", "eevee"),
                          ratio(row, "lineart_eval", "edgelight_lines")]) + " |")
    lines.append("")
    for row in results:
        for key, label in METHODS:
            note = row[key]["note"]
            if note:
                lines.append(f"- {row['mesh']}, {label}: {note}")
    lines.append("- `*`: a single frame, warm-up included (longer than the limit).")
    lines.append("- Line Art eval: one depsgraph update of the Grease Pencil object after `update_tag()` "
                 "(strokes: " + ", ".join(f"{r['mesh']} {r['lineart_strokes']:,}" for r in results) + ").")
    md = "\n".join(lines) + "\n"
    md_path = os.path.splitext(args.out)[0] + ".md"
    with open(md_path, "w") as f:
        f.write(md)
    print("\n" + md, flush=True)
    log(f"wrote {args.out}, {md_path}, PNGs in {args.png_dir}")


def main():
    args = parse_args()
    os.makedirs(args.png_dir, exist_ok=True)
    enable_edgelight()
    scene, cam, mat = setup_scene(args)
    log(f"Blender {bpy.app.version_string}")
    results = []
    for name in args.meshes:
        run_mesh(name, args, scene, cam, mat, results)
    write_outputs(args, results)


if __name__ == "__main__":
    main()
