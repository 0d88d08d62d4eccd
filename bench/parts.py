"""CAD-like parts built by script (bmesh), for the highlight's ground truth (bench/ground_truth.py)
and the tests that pin it (tests/blender/test_fillet_parts.py). Each returns a new bmesh with
outward normals, about 2 units across, centred near the origin; the caller frees it. They are the
shapes real parts broke the band on: concave steps, holes, teeth, shoulders, polygon sides cut by
collinear vertices, and creases running along modelled fillets (chains of short edges)."""
import math

import bmesh
import bpy
from mathutils import Matrix


def _prism(profile, depth, bm=None):
    """The closed xz-polygon `profile` (counter-clockwise seen from -y) extruded along y over
    [-depth / 2, depth / 2]: two n-gon caps and one quad per side."""
    bm = bm or bmesh.new()
    a = [bm.verts.new((x, -0.5 * depth, z)) for x, z in profile]
    b = [bm.verts.new((x, 0.5 * depth, z)) for x, z in profile]
    bm.faces.new(a[::-1])
    bm.faces.new(b)
    for i in range(len(profile)):
        j = (i + 1) % len(profile)
        bm.faces.new((a[i], a[j], b[j], b[i]))
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces[:])
    return bm


def _revolve(profile, steps=48):
    """The closed (radius, z) polygon `profile` (away from the axis) turned about z: a solid of
    revolution with quads only."""
    bm = bmesh.new()
    verts = [bm.verts.new((r, 0.0, z)) for r, z in profile]
    edges = [bm.edges.new((verts[i], verts[(i + 1) % len(verts)])) for i in range(len(verts))]
    bmesh.ops.spin(bm, geom=verts + edges, cent=(0, 0, 0), axis=(0, 0, 1), dvec=(0, 0, 0),
                   angle=2.0 * math.pi, steps=steps, use_merge=True, use_duplicate=False)
    bmesh.ops.remove_doubles(bm, verts=bm.verts[:], dist=1e-6)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces[:])
    return bm


def _cylinder(radius, depth, at=(0.0, 0.0, 0.0), segments=24):
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=True, segments=segments, radius1=radius, radius2=radius, depth=depth,
                          matrix=Matrix.Translation(at))
    return bm


def _subtract(bm, cutters):
    """bm minus the union of the cutter bmeshes (the Boolean modifier, as an
    artist would cut holes); frees the cutters, returns a new bmesh."""
    scene = bpy.context.scene
    target = bpy.data.objects.new("PartTarget", bpy.data.meshes.new("PartTarget"))
    bm.to_mesh(target.data)
    bm.free()
    scene.collection.objects.link(target)
    made = [target]
    for k, c in enumerate(cutters):
        ob = bpy.data.objects.new(f"PartCutter{k}", bpy.data.meshes.new(f"PartCutter{k}"))
        c.to_mesh(ob.data)
        c.free()
        scene.collection.objects.link(ob)
        made.append(ob)
        mod = target.modifiers.new(f"Cut{k}", 'BOOLEAN')
        mod.operation = 'DIFFERENCE'
        # The Exact solver's faces differ from run to run (the same vertices, split into other
        # polygons: its threads), and the Bevel modifier's fillets with them (the flange's reference
        # left unbevelled in some runs); the Fast solver's do not ('FLOAT' from 5.0).
        solvers = {item.identifier for item in mod.bl_rna.properties["solver"].enum_items}
        mod.solver = 'FAST' if 'FAST' in solvers else 'FLOAT'
        mod.object = ob
    depsgraph = bpy.context.evaluated_depsgraph_get()
    out = bmesh.new()
    out.from_object(target, depsgraph)
    for ob in made:
        me = ob.data
        bpy.data.objects.remove(ob)
        bpy.data.meshes.remove(me)
    bmesh.ops.recalc_face_normals(out, faces=out.faces[:])
    return out


def l_step():
    """A step: one concave edge (x = 0, z = 0, along y) between five convex ones."""
    return _prism([(-1, -1), (1, -1), (1, 0), (0, 0), (0, 1), (-1, 1)], 2.0)


def flange():
    """A disc with a boss (a concave ring at its foot), a bore and six bolt holes."""
    bm = _revolve([(0.2, -0.15), (1.0, -0.15), (1.0, 0.15), (0.45, 0.15), (0.45, 0.55), (0.2, 0.55)])
    holes = [_cylinder(0.09, 0.6, (0.72 * math.cos(k * math.pi / 3), 0.72 * math.sin(k * math.pi / 3), 0.0))
             for k in range(6)]
    return _subtract(bm, holes)


def gear(teeth=14):
    """A spur gear: trapezoid teeth (convex tips, concave roots), a bore, 0.4 thick."""
    outer, root, pts = 1.0, 0.8, []
    for k in range(teeth):
        a = 2.0 * math.pi * k / teeth
        step = 2.0 * math.pi / teeth
        for frac, r in ((0.0, root), (0.15, outer), (0.45, outer), (0.6, root)):
            pts.append((r * math.cos(a + frac * step), r * math.sin(a + frac * step)))
    bm = _prism(pts, 0.4)  # the xz profile extruded along y: the gear's axis is y
    bore = _cylinder(0.3, 1.0, segments=24)
    bmesh.ops.rotate(bore, verts=bore.verts[:], cent=(0, 0, 0), matrix=Matrix.Rotation(math.pi / 2, 3, 'X'))
    return _subtract(bm, [bore])


def hollow_shaft():
    """A tube with a shoulder: an outer step (concave ring) and a bore, along z."""
    return _revolve([(0.35, -1.0), (0.8, -1.0), (0.8, 0.1), (0.55, 0.1), (0.55, 1.0), (0.35, 1.0)])


def cut_box(cuts=3):
    """A 2 x 1.4 x 1 box whose top edges carry `cuts` extra collinear vertices each (as imports
    leave them): n-gon sides whose loop triangles have zero area."""
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.0, matrix=Matrix.Diagonal((2.0, 1.4, 1.0, 1.0)))
    top = [e for e in bm.edges if all(v.co.z > 0.49 for v in e.verts)]
    bmesh.ops.subdivide_edges(bm, edges=top, cuts=cuts)
    return bm


def filleted_box():
    """A 2 x 1.4 x 0.8 box whose vertical edges are modelled fillets (4 segments, 22.5 degrees
    apart: below the crease angle, so not rounded); its top and bottom rims run along them as
    chains of short edges."""
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.0, matrix=Matrix.Diagonal((2.0, 1.4, 0.8, 1.0)))
    vertical = [e for e in bm.edges if abs(e.verts[0].co.z - e.verts[1].co.z) > 0.5]
    bmesh.ops.bevel(bm, geom=vertical, offset=0.3, offset_type='OFFSET', segments=4, profile=0.5,
                    affect='EDGES')
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces[:])
    return bm


BUILT = {
    "l_step": l_step,
    "flange": flange,
    "gear": gear,
    "hollow_shaft": hollow_shaft,
    "cut_box": cut_box,
    "filleted_box": filleted_box,
}
