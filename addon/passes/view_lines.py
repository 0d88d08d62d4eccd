"""Per instance, the line batches a frame draws: each geometry's static ones and the
view-dependent silhouettes and contours (native view calls)."""
from .. import lines as ink
from .. import native


def line_instances(scene, gpu_meshes, view_batches):
    """[(matrix, {type: (batch, count)}, instance id)]: each instance's static line batches (shared by the
    instances of a mesh) and its own view-dependent ones (view_batches[i] for instance i)."""
    out = []
    for i, inst in enumerate(scene.instances):
        if inst.holdout:  # a hole in the image: no ink of its own, though it hides what lies behind
            continue
        batches_of = dict(gpu_meshes[id(inst.mesh)].lines)
        if view_batches and i < len(view_batches) and view_batches[i]:
            batches_of.update(view_batches[i])
        out.append((inst.matrix, batches_of, i + 1))  # i + 1: the instance's surface id
    return out


def view_line_segments(scene, camera, line_settings, counters=None, rounded=False):
    """Per instance, type -> LineSegments of the view-dependent types (native view calls). An
    instance the library refuses (a singular transform, say) gets none, and a report. With
    `rounded`, silhouettes of rounded edges lie on the fillets' outline (lines.view_lines); an
    instance whose move fails keeps them on its sharp edges, with a report."""
    out, seen = [], {}
    for inst in scene.instances:
        index = seen[id(inst.mesh)] = seen.get(id(inst.mesh), -1) + 1
        if inst.holdout:  # a hole in the image has no ink
            out.append({})
            continue
        try:
            try:
                out.append(ink.view_lines(inst.mesh, index, inst.matrix, camera, line_settings, counters, rounded))
            except (native.NativeError, ArithmeticError, IndexError, ValueError) as e:
                if not rounded:
                    raise
                # Moving them onto the rounded outline failed (the library's el_outline_lines, or
                # the records it is given): the object's silhouettes stay on its sharp edges, and
                # the render goes on. Should the view itself have failed, the retry says so.
                _report(scene, f"{inst.mesh.name}: silhouettes left on the sharp edges ({type(e).__name__}: {e})")
                out.append(ink.view_lines(inst.mesh, index, inst.matrix, camera, line_settings, counters, False))
        except native.NativeError as e:
            _report(scene, f"{inst.mesh.name}: no silhouettes or contours ({e.message})")
            out.append({})
    return out


def _report(scene, note):
    if note not in scene.reports:
        scene.reports.append(note)
