"""Per instance, the line batches a frame draws: each geometry's static ones and the
view-dependent silhouettes and contours (native view calls)."""
import numpy as np

from ..bridge import native
from ..linework import lines as ink


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
    """Per instance, type -> LineSegments of the view-dependent types. The silhouettes of all
    instances of one mesh come from one library call (lines.silhouettes), the contours from
    each instance's native view. An instance the library refuses (a singular transform, say)
    gets none, and a report. With `rounded`, silhouettes of rounded edges lie on the fillets'
    outline; a mesh whose move fails keeps them on its sharp edges, with a report."""
    kinds = [k for k in line_settings.types if k in ink.VIEW_TYPES] if line_settings else []
    out = [{} for _ in scene.instances]
    if not kinds:
        return out
    groups, index = {}, []
    for i, inst in enumerate(scene.instances):
        group = groups.setdefault(id(inst.mesh), [])
        index.append(len(group))  # its place among its mesh's instances: its native view's key
        group.append(i)
    for members in groups.values():
        drawn = [i for i in members if not scene.instances[i].holdout]  # a hole in the image has no ink
        if not drawn:
            continue
        extract = scene.instances[drawn[0]].mesh
        if counters is not None:
            counters.view_calls += len(drawn)
        failed = set()  # an instance the library refused is reported once
        if "silhouette" in kinds:
            taper = line_settings.style("silhouette").taper > 0.0
            for i, seg in zip(drawn, _silhouettes(scene, extract, [scene.instances[i].matrix for i in drawn],
                                                   camera, taper, rounded)):
                if isinstance(seg, str):
                    _report(scene, f"{extract.name}: no silhouettes or contours ({seg})")
                    failed.add(i)
                else:
                    out[i]["silhouette"] = seg
        if "contour" in kinds:
            for i in drawn:
                if i in failed:
                    continue
                inst = scene.instances[i]
                try:
                    out[i]["contour"] = ink.contours(extract, index[i], inst.matrix, camera, line_settings)
                except native.NativeError as e:
                    _report(scene, f"{extract.name}: no silhouettes or contours ({e.status}: {e.message})")
    return out


def _silhouettes(scene, extract, matrices, camera, taper, rounded):
    """lines.silhouettes of the instances of one mesh; where the move onto the rounded outline
    fails (the library refusing the mesh's records), on the sharp edges with a report, and where
    the library refuses the views altogether, none (its message for each)."""
    try:
        try:
            return ink.silhouettes(extract, np.asarray(matrices), camera, taper, rounded)
        except (native.NativeError, ArithmeticError, IndexError, ValueError) as e:
            if not rounded:
                raise
            _report(scene, f"{extract.name}: silhouettes left on the sharp edges ({type(e).__name__}: {e})")
            return ink.silhouettes(extract, np.asarray(matrices), camera, taper, False)
    except native.NativeError as e:
        return [f"{e.status}: {e.message}"] * len(matrices)


def _report(scene, note):
    if note not in scene.reports:
        scene.reports.append(note)
