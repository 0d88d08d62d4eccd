"""Rounded-edge methods against real rounded geometry (issue 6): frame time and error near edges.

    blender -b --factory-startup --addons edgelight --python bench/ground_truth.py -- [OUT.csv] [SCENES] [WIDTHS]

Ground truth: the same mesh with its rounded edges replaced by circular fillets of radius r
(Bevel modifier, 32 segments, hardened normals), drawn by EdgeLight with highlights off (so the
surface shading is exactly the other methods') and REF_SAMPLES jittered samples per pixel.
Methods, all at SAMPLES samples: highlights off; the paper's 1-pixel method; EdgeLight before
issue 6 (whole-arc mean); EdgeLight (default: partial arcs); the per-pixel reference integral
(EdgeLight's band with the kernel by 256-point quadrature in the shader); the Bevel modifier with
1, 2, 4, 8 segments and highlights off. The edge methods are chosen with EDGELIGHT_EDGE_METHOD
(shaders/edge_band.glsl).

Widths are the fillet radius in pixels at the object's centre, r f / d. Errors are over the
pixels within 3 px of where the rounded edges change the image (the reference against the sharp
mesh) or where EdgeLight draws a band ("all"), and over those of them away from the object's
outline ("interior": the outline of a filleted mesh moves inwards, which an overlay on the sharp
mesh cannot follow), on display values (the Standard view transform's sRGB
curve, clipped to [0, 1]): RMSE over pixels and channels, max, PSNR = 10 log10(1 / MSE).
Times: median of REPEAT renders after one warm-up, all methods of one scene and width back to
back. Writes OUT.csv (default out/ground_truth.csv) and the method images as .npy beside it;
bench/plot_ground_truth.py draws the plots and the markdown tables.
"""
import math
import os
import statistics
import sys
import time

import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import fillets  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else os.path.join(ROOT, "out", "ground_truth.csv")
SCENES = ARGS[1].split(",") if len(ARGS) > 1 else ["cube", "fandisk"]
WIDTHS = [float(w) for w in ARGS[2].split(",")] if len(ARGS) > 2 else [0.3, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0]
RESOLUTION = (480, 360)
SAMPLES = 8
REF_SAMPLES = 64
REF_SEGMENTS = 32
REPEAT = 3
MASK_DILATE = 3

# name, edge method (None: highlights off), bevel segments (0: the sharp mesh)
METHODS = [
    ("off", None, 0),
    ("paper", "paper", 0),
    ("whole-arc (before)", "whole", 0),
    ("EdgeLight", "partial", 0),
    ("reference integral", "quadrature", 0),
    ("bevel 1", None, 1),
    ("bevel 2", None, 2),
    ("bevel 4", None, 4),
    ("bevel 8", None, 8),
]


def off_mesh(name):
    """(vertices, faces) of libcgal-demo's data/meshes/NAME.off (from EDGELIGHT_MESH_DIR or the
    Debian package's data.tar.gz)."""
    import tarfile
    path = os.path.join(os.environ.get("EDGELIGHT_MESH_DIR", os.path.join(ROOT, "build", "meshes")), name + ".off")
    if os.path.exists(path):
        text = open(path).read()
    else:
        with tarfile.open("/usr/share/doc/libcgal-dev/data.tar.gz") as tar:
            text = tar.extractfile(f"data/meshes/{name}.off").read().decode()
    words = [w for line in text.splitlines() for w in line.split("#")[0].split()]
    nv, nf = int(words[1]), int(words[2])
    vals = words[4:]
    verts = np.array(vals[:3 * nv], float).reshape(nv, 3)
    faces, k = [], 3 * nv
    for _ in range(nf):
        n = int(vals[k])
        faces.append([int(v) for v in vals[k + 1:k + 1 + n]])
        k += 1 + n
    return verts, faces


def open_scene(name, radius, samples):
    """A sample scene, or (for any other name) libcgal-demo's NAME.off in the fandisk sample's
    place: its camera, sun and material, the mesh scaled into fandisk's bounding box."""
    sample = os.path.join(ROOT, "blend_samples", name + ".blend")
    bpy.ops.wm.open_mainfile(filepath=sample if os.path.exists(sample) else
                             os.path.join(ROOT, "blend_samples", "fandisk.blend"))
    if not os.path.exists(sample):
        ob = bpy.data.objects["Fandisk"]
        old = np.array([v.co[:] for v in ob.data.vertices])
        verts, faces = off_mesh(name)
        lo, hi = verts.min(0), verts.max(0)
        scale = np.ptp(old, 0).max() / np.ptp(verts, 0).max()
        verts = (verts - 0.5 * (lo + hi)) * scale + 0.5 * (old.min(0) + old.max(0))
        me = bpy.data.meshes.new(name)
        me.from_pydata(verts.tolist(), [], faces)
        me.update()
        for p in me.polygons:
            p.use_smooth = True
        if hasattr(me, "use_auto_smooth"):  # 3.x: smooth faces, sharp creases (as the fandisk sample)
            me.use_auto_smooth = True
            me.auto_smooth_angle = math.radians(30.0)
        for mat in ob.data.materials:
            me.materials.append(mat)
        ob.data = me
    s = bpy.context.scene
    s.render.engine = "EDGELIGHT"
    s.render.resolution_x, s.render.resolution_y = RESOLUTION
    s.render.resolution_percentage = 100
    s.view_settings.view_transform = 'Standard'
    s.edgelight.samples = samples
    for mat in bpy.data.materials:
        mat.edgelight.radius = radius
        mat.edgelight.K = 1.0
    return s


def px_per_unit_at_centre(s):
    """r f / d at the meshes' bounding-box centre: the radius' image in pixels."""
    cam = s.camera
    f = cam.data.lens / cam.data.sensor_width * s.render.resolution_x
    pts = [ob.matrix_world @ v.co for ob in s.objects if ob.type == 'MESH' for v in ob.data.vertices]
    centre = sum(pts, pts[0] * 0.0) / len(pts)
    return f / (cam.matrix_world.translation - centre).length


def render():
    import edgelight
    edgelight.engine.capture = True  # the pass buffers below come from the render's record
    t0 = time.perf_counter()
    bpy.ops.render.render()
    dt = time.perf_counter() - t0
    return dt, np.array(edgelight.engine.last_render["pixels"][..., :3], np.float64)


def display(rgb):
    c = np.clip(rgb, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)


def dilate(mask, k):
    out = mask.copy()
    for dy in range(-k, k + 1):
        for dx in range(-k, k + 1):
            if dx * dx + dy * dy <= k * k:
                out |= np.roll(np.roll(mask, dy, 0), dx, 1)
    return out


def configure(name, radius, method, segments, samples):
    s = open_scene(name, radius, samples)
    if segments:
        fillets.add_fillets(s, radius, segments)
    elif method is None:
        s.edgelight.highlights = False
    os.environ["EDGELIGHT_EDGE_METHOD"] = method or "partial"
    return s


def timed(name, radius, method, segments, samples, repeat):
    configure(name, radius, method, segments, samples)
    render()  # warm-up: shader compiles, modifier evaluation
    runs = [render() for _ in range(repeat)]
    return statistics.median(t for t, _ in runs), runs[-1][1]


def main():
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    rows, bands = [], {}
    for name in SCENES:
        s = open_scene(name, 0.01, 1)
        ppu = px_per_unit_at_centre(s)
        for width in WIDTHS:
            radius = width / ppu
            t_ref, ref = timed(name, radius, None, REF_SEGMENTS, REF_SAMPLES, 1)
            images, times = {}, {}
            for label, method, segments in METHODS:
                times[label], images[label] = timed(name, radius, method, segments, SAMPLES, REPEAT)
                import edgelight
                if method == "partial":  # where EdgeLight draws a band (its highlight alpha)
                    bands[name, width] = np.asarray(edgelight.engine.last_render["highlight"])[..., 3]
                if label == "off":  # the sharp mesh's outline
                    covered = np.asarray(edgelight.engine.last_render["surface"])[..., 3] > 0.5
                    outline = dilate(~covered, 1) & covered
                print(f"{name} {width:4.1f}px {label:22s} {times[label]:.3f} s", flush=True)
            dref = display(ref)
            changed = np.abs(dref - display(images["off"])).max(axis=2) > 1.0 / 255.0
            changed |= bands[name, width] > 1.0 / 255.0
            mask = dilate(changed, MASK_DILATE)
            # Interior: away from the outline, where a fillet also moves the silhouette inwards
            # (up to r tan(a / 2) = r px on the cube) and no overlay on the sharp mesh can follow.
            interior = mask & ~dilate(outline, MASK_DILATE + int(math.ceil(1.5 * width)))
            tag = f"{name}_{width:g}px"
            np.save(os.path.join(os.path.dirname(OUT), f"gt_{tag}_reference.npy"), ref.astype(np.float32))
            for label, _, _ in METHODS:
                errors = []
                for m in (mask, interior):
                    diff = display(images[label])[m] - dref[m]
                    mse = float(np.mean(diff ** 2))
                    errors += [math.sqrt(mse), float(np.abs(diff).max()), 10.0 * math.log10(1.0 / max(mse, 1e-12)), int(m.sum())]
                rows.append((name, width, radius, label, times[label], *errors))
                np.save(os.path.join(os.path.dirname(OUT), f"gt_{tag}_{label.split(' (')[0].replace(' ', '_')}.npy"),
                        images[label].astype(np.float32))
            rows.append((name, width, radius, f"reference (bevel {REF_SEGMENTS} segments; {REF_SAMPLES} spp)", t_ref,
                         0.0, 0.0, float("inf"), int(mask.sum()), 0.0, 0.0, float("inf"), int(interior.sum())))
            np.save(os.path.join(os.path.dirname(OUT), f"gt_{tag}_mask.npy"), mask)
            np.save(os.path.join(os.path.dirname(OUT), f"gt_{tag}_interior.npy"), interior)
            with open(OUT, "w") as f:
                f.write("scene,width_px,radius,method,time_s,rmse,max_err,psnr_db,mask_pixels,"
                        "rmse_interior,max_err_interior,psnr_db_interior,interior_pixels\n")
                for r in rows:
                    f.write(",".join(str(v) if not isinstance(v, float) else f"{v:.6g}" for v in r) + "\n")
    print("wrote", OUT)


main()
