"""Scenes and pixel regions of the highlight's ground truth (bench/ground_truth.py,
bench/cycles_bevel.py).

Every part is drawn in the fandisk sample's place (its camera, sun and material), scaled into its
bounding box, smooth-shaded with 30-degree sharp edges. Parts: the samples (`cube`, `fandisk`),
any libcgal-demo `data/meshes/NAME.off`, and the parts bench/parts.py builds.

Regions: every error is reported over pixels near where the fillets change the image ("all"),
split into the outline (the part's silhouette against the background and where one part of it
passes in front of another, with a jump in depth or along the mesh's contour edges: a fillet
moves both inwards, which no overlay on the sharp mesh can follow) and the interior; the
interior is broken down into corners (where rounded edges meet or a crease ends or turns: the
fillets' corner patches) and the rest, along convex and along concave edges."""
import math
import os
import tarfile

import bmesh
import bpy
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CREASE = math.radians(30.0)
RESOLUTION = (480, 360)  # the ground truth's frame: its regions are saved at this size
REF_SEGMENTS = 32        # the reference fillets' segments
MASK_DILATE = 3
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"  # libcgal-demo's meshes


def off_mesh(name):
    """(vertices, faces) of libcgal-demo's data/meshes/NAME.off: EDGELIGHT_MESH_DIR/NAME.off (ctest
    passes the build's meshes, cmake/SampleMeshes.cmake extracts them; unset: build/meshes), else
    the Debian package's data.tar.gz (the benchmarks' other parts)."""
    mesh_dir = os.environ.get("EDGELIGHT_MESH_DIR") or os.path.join(ROOT, "build", "meshes")
    path = os.path.join(mesh_dir, name + ".off")
    if os.path.exists(path):
        with open(path) as f:
            text = f.read()
    elif os.path.exists(CGAL_DATA):
        with tarfile.open(CGAL_DATA) as tar:
            text = tar.extractfile(f"data/meshes/{name}.off").read().decode()
    else:
        raise FileNotFoundError(f"{name}.off: neither {path} (EDGELIGHT_MESH_DIR; the meshes "
                                f"cmake/SampleMeshes.cmake extracts) nor {CGAL_DATA} (libcgal-demo)")
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


def built_mesh(name):
    import parts
    bm = parts.BUILT[name]()
    verts = np.array([v.co[:] for v in bm.verts], float)
    faces = [[v.index for v in f.verts] for f in bm.faces]
    bm.free()
    return verts, faces


def open_scene(name, radius, samples, resolution):
    """A sample scene, or any other part in the fandisk sample's place."""
    import parts
    sample = os.path.join(ROOT, "blend_samples", name + ".blend")
    bpy.ops.wm.open_mainfile(filepath=sample if os.path.exists(sample) else
                             os.path.join(ROOT, "blend_samples", "fandisk.blend"))
    if not os.path.exists(sample):
        ob = bpy.data.objects["Fandisk"]
        old = np.array([v.co[:] for v in ob.data.vertices])
        verts, faces = built_mesh(name) if name in parts.BUILT else off_mesh(name)
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
            me.auto_smooth_angle = CREASE
        else:  # 4.1+ has no auto smooth: the same creases marked sharp
            mark_creases_sharp(me)
        for mat in ob.data.materials:
            me.materials.append(mat)
        ob.data = me
    s = edgelight_scene(resolution, samples)
    for mat in bpy.data.materials:
        mat.edgelight.radius = radius
        mat.edgelight.K = 1.0
    return s


def mark_creases_sharp(me):
    """Marks sharp the edges whose faces fold by more than CREASE, and the open ones: auto
    smooth's rule, on Blender 4.1+ (which has none)."""
    bm = bmesh.new()
    bm.from_mesh(me)
    sharp = [len(e.link_faces) != 2 or e.calc_face_angle(0.0) > CREASE for e in bm.edges]
    bm.free()
    attr = me.attributes.get("sharp_edge") or me.attributes.new("sharp_edge", 'BOOLEAN', 'EDGE')
    attr.data.foreach_set("value", sharp)
    me.update()


def edgelight_scene(resolution, samples):
    """The open file's scene rendered by EdgeLight at `resolution` (100 %), `samples` samples and
    the Standard view transform (errors are measured on display values)."""
    s = bpy.context.scene
    s.render.engine = "EDGELIGHT"
    s.render.resolution_x, s.render.resolution_y = resolution
    s.render.resolution_percentage = 100
    s.view_settings.view_transform = 'Standard'
    s.edgelight.samples = samples
    return s


def px_per_unit_at_centre(s):
    """f / d at the meshes' bounding-box centre: a radius times this is its image in pixels."""
    cam = s.camera
    f = cam.data.lens / cam.data.sensor_width * s.render.resolution_x
    pts = [ob.matrix_world @ v.co for ob in s.objects if ob.type == 'MESH' for v in ob.data.vertices]
    centre = sum(pts, pts[0] * 0.0) / len(pts)
    return f / (cam.matrix_world.translation - centre).length


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


def _project(s, points, with_w=False):
    """World points -> (x, y) pixel coordinates, y up (as the render's arrays), and w > 0 (and
    w itself, the view depth, with with_w)."""
    cam = s.camera
    depsgraph = bpy.context.evaluated_depsgraph_get()
    rx, ry = s.render.resolution_x, s.render.resolution_y
    proj = np.array(cam.calc_matrix_camera(depsgraph, x=rx, y=ry))
    view = np.array(cam.matrix_world.inverted())
    p = np.c_[points, np.ones(len(points))] @ (proj @ view).T
    front = p[:, 3] > 0
    xy = (p[:, :2] / np.where(front, p[:, 3], 1.0)[:, None] * 0.5 + 0.5) * np.array([rx, ry])
    return (xy, front, p[:, 3]) if with_w else (xy, front)


def _raster(s, segments, shape, inv_depth=None, depth_tol=0.02):
    """Pixels the world segments (N, 2, 3) pass through (sampled every half pixel); with
    inv_depth (the sharp mesh's 1 / view depth), only where they are in view: no farther than
    the surface there by depth_tol (relative)."""
    img = np.zeros(shape, bool)
    if not len(segments):
        return img
    a, front_a, wa = _project(s, segments[:, 0], True)
    b, front_b, wb = _project(s, segments[:, 1], True)
    both = front_a & front_b
    for p, q, w0, w1 in zip(a[both], b[both], wa[both], wb[both]):
        n = int(np.ceil(np.linalg.norm(q - p) * 2.0)) + 1
        t = np.linspace(0.0, 1.0, n)
        xy = np.floor(p + t[:, None] * (q - p)).astype(int)
        ok = (xy[:, 0] >= 0) & (xy[:, 0] < shape[1]) & (xy[:, 1] >= 0) & (xy[:, 1] < shape[0])
        if inv_depth is not None:
            w = 1.0 / ((1.0 - t) / w0 + t / w1)  # the view depth along the segment's image
            xy, w = xy[ok], w[ok]
            ok = inv_depth[xy[:, 1], xy[:, 0]] * w <= 1.0 + depth_tol
        img[xy[ok, 1], xy[ok, 0]] = True
    return img


def edge_classes(s):
    """World segments of the rounded edges (faces meeting at more than 30 degrees), convex and
    concave, the world points where rounded edges meet or end (corners), and the edges with one
    face turned to the camera and one away (the mesh's contours, rounded or not: where one part
    of the surface passes in front of the next with no jump in depth, as a tooth's flank over
    its root, the fillets behind move what shows past it)."""
    convex, concave, corners, contours = [], [], [], []
    eye = s.camera.matrix_world.translation
    for ob in (o for o in s.objects if o.type == 'MESH'):
        bm = bmesh.new()
        bm.from_mesh(ob.data)
        bm.transform(ob.matrix_world)
        bm.normal_update()
        rounded = {e for e in bm.edges if len(e.link_faces) == 2 and e.calc_face_angle(0.0) > CREASE}
        for e in rounded:
            (convex if e.is_convex else concave).append([v.co[:] for v in e.verts])
        for e in bm.edges:
            to_eye = eye - 0.5 * (e.verts[0].co + e.verts[1].co)
            if len(e.link_faces) == 2 and \
                    (e.link_faces[0].normal.dot(to_eye) > 0.0) != (e.link_faces[1].normal.dot(to_eye) > 0.0):
                contours.append([v.co[:] for v in e.verts])
        for v in bm.verts:
            mine = [e for e in v.link_edges if e in rounded]
            if not mine:
                continue
            if len(mine) != 2:
                corners.append(v.co[:])
                continue
            d = [(e.other_vert(v).co - v.co).normalized() for e in mine]
            if d[0].dot(d[1]) > -math.cos(CREASE):  # the crease turns: a corner
                corners.append(v.co[:])
        bm.free()
    arr = lambda x: np.array(x, float).reshape(-1, *np.shape(x)[1:]) if x else np.zeros((0, 2, 3))  # noqa: E731
    return arr(convex), arr(concave), np.array(corners, float).reshape(-1, 3), arr(contours)


def occluding_contours(inv_depth, jump=0.03):
    """Pixels next to a jump in depth of more than `jump` (relative) to a neighbour: where one
    part of the surface passes in front of another (a bore's far wall behind its rim)."""
    d = np.where(inv_depth > 0.0, 1.0 / np.maximum(inv_depth, 1e-30), 0.0)
    out = np.zeros(d.shape, bool)
    for axis in (0, 1):
        a, b = d, np.roll(d, 1, axis)
        step = (a > 0) & (b > 0) & (np.abs(a - b) > jump * np.minimum(a, b))
        out |= step | np.roll(step, -1, axis)
    return out


def regions(s, changed, covered, width_px, inv_depth=None):
    """Boolean pixel masks by region (see the module's docstring). `changed`: where the
    reference differs from the sharp mesh or EdgeLight draws a band; `covered`: the sharp mesh's
    coverage; inv_depth: its 1 / view depth, whose jumps are outlines inside the coverage."""
    mask = dilate(changed, MASK_DILATE)
    reach = MASK_DILATE + int(math.ceil(1.5 * width_px))
    edge = dilate(~covered, 1) & covered
    convex, concave, corner_pts, contours = edge_classes(s)
    if inv_depth is not None:
        edge |= (occluding_contours(inv_depth) | _raster(s, contours, mask.shape, inv_depth)) & covered
    outline = mask & dilate(edge, reach)
    corner_img = np.zeros(mask.shape, bool)
    xy, front = _project(s, corner_pts) if len(corner_pts) else (np.zeros((0, 2)), np.zeros(0, bool))
    xy = np.floor(xy[front]).astype(int)
    ok = (xy[:, 0] >= 0) & (xy[:, 0] < mask.shape[1]) & (xy[:, 1] >= 0) & (xy[:, 1] < mask.shape[0])
    corner_img[xy[ok, 1], xy[ok, 0]] = True
    interior = mask & ~outline
    corners = interior & dilate(corner_img, reach)
    along = interior & ~corners
    near_convex = dilate(_raster(s, convex, mask.shape), reach)
    near_concave = dilate(_raster(s, concave, mask.shape), reach)
    return {
        "all": mask,
        "interior": interior,
        "convex": along & near_convex & ~near_concave,
        "concave": along & near_concave & ~near_convex,
        "corners": corners,
        "outline": outline,
    }


def errors(image, reference, m):
    """RMSE, max and PSNR (dB) of display values over mask m, and its pixel count."""
    if not m.any():
        return float("nan"), float("nan"), float("nan"), 0
    diff = display(image)[m] - display(reference)[m]
    mse = float(np.mean(diff ** 2))
    return math.sqrt(mse), float(np.abs(diff).max()), 10.0 * math.log10(1.0 / max(mse, 1e-12)), int(m.sum())


def write_csv(path, header, rows):
    """The rows so far (rewritten after every part and width, so a long run leaves its results)."""
    with open(path, "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(",".join(str(v) if not isinstance(v, float) else f"{v:.6g}" for v in r) + "\n")


def parts_and_radii(parts, widths, resolution):
    """(part, width in pixels, the radius of that width at the part's centre) for every part and
    width, each part's scale measured once."""
    for name in parts:
        ppu = px_per_unit_at_centre(open_scene(name, 0.01, 1, resolution))
        for width in widths:
            yield name, width, width / ppu
