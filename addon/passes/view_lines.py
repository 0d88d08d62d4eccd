"""Per instance, the line batches a frame draws: each geometry's static ones and the
view-dependent silhouettes and contours (native view calls)."""
from .. import lines as ink
from .. import native


def line_instances(scene, gpu_meshes, view_batches):
    """[(matrix, {type: (batch, count)}, instance id)]: each instance's static line batches (shared by the
    instances of a mesh) and its own view-dependent ones (view_batches[i] for instance i)."""
    out = []
    for i, inst in enumerate(scene.instances):
        batches_of = dict(gpu_meshes[id(inst.mesh)].lines)
        if view_batches and i < len(view_batches) and view_batches[i]:
            batches_of.update(view_batches[i])
        out.append((inst.matrix, batches_of, i + 1))  # i + 1: the instance's surface id
    return out


def view_line_segments(scene, camera, line_settings, counters=None, rounded=False):
    """Per instance, type -> LineSegments of the view-dependent types (native view calls). An
    instance the library refuses (a singular transform, say) gets none, and a report. With
    `rounded`, silhouettes of rounded edges lie on the fillets' outline (lines.view_lines)."""
    out, seen = [], {}
    for inst in scene.instances:
        index = seen[id(inst.mesh)] = seen.get(id(inst.mesh), -1) + 1
        try:
            out.append(ink.view_lines(inst.mesh, index, inst.matrix, camera, line_settings, counters, rounded))
        except native.NativeError as e:
            note = f"{inst.mesh.name}: no silhouettes or contours ({e.message})"
            if note not in scene.reports:
                scene.reports.append(note)
            out.append({})
    return out
