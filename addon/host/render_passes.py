"""Render passes beside Combined, offered the way Cycles and EEVEE offer theirs: Blender's Depth,
Normal, Mist, Object Index and Material Index when the view layer asks for them (use_pass_z,
use_pass_normal, use_pass_mist, use_pass_object_index, use_pass_material_index), and EdgeLight's own
Highlights, Lines and Surface, switched on per view layer (View Layer Properties -> EdgeLight
Passes). How Combined is recomposed from them: docs/addon.md, "Render passes".
"""
from types import SimpleNamespace

import bpy
import numpy as np

from .. import compat
from .panel_base import EdgeLightPanel

# Where nothing was drawn, Depth holds what Cycles and EEVEE write there.
BACKGROUND_DEPTH = 1e10
# Blender's name of the Object Index pass (the compositor's Render Layers socket).
OBJECT_INDEX = compat.OBJECT_INDEX_PASS
MATERIAL_INDEX = compat.MATERIAL_INDEX_PASS
# Buffers made from the first sample's ids ("ids": instance + 1, surface id), not drawn themselves.
FROM_IDS = ("object_index", "material_index")

# EdgeLight's own passes: (pass name, view-layer setting, frame buffer)
OWN_PASSES = (
    ("Highlights", "use_pass_highlights", "highlight"),
    ("Lines", "use_pass_lines", "lines"),
    ("Surface", "use_pass_surface", "surface"),
)


def _requery(self, context):
    """Blender asks the engine again which passes exist (the compositor's Render Layers node
    grows or loses its sockets)."""
    view_layer = getattr(context, "view_layer", None)
    if view_layer is not None:
        view_layer.update_render_passes()


class EdgeLightViewLayerSettings(bpy.types.PropertyGroup):
    use_pass_highlights: bpy.props.BoolProperty(
        name="Highlights", default=False, update=_requery,
        description="The rounded edges' highlight bands, premultiplied RGBA (colour times weight, "
                    "weight) less what each takes out of the faces under it: laid over Surface "
                    "they give the highlighted surface")
    use_pass_lines: bpy.props.BoolProperty(
        name="Lines", default=False, update=_requery,
        description="The ink lines alone, premultiplied RGBA (colour times opacity, opacity): "
                    "laid over the highlighted surface")
    lines_as_pass: bpy.props.BoolProperty(
        name="Lines as Render Pass", default=False, update=_requery,
        description="Keep the ink out of Combined and write it to the Lines pass alone, as "
                    "Freestyle's As Render Pass does: a glare or grade on Combined leaves the ink "
                    "alone, and the compositor lays Lines over the result")
    use_pass_surface: bpy.props.BoolProperty(
        name="Surface", default=False, update=_requery,
        description="The shaded surface without highlights or lines, averaged over the samples, "
                    "premultiplied RGBA (transparent where nothing was drawn)")


def enabled(view_layer):
    """[(pass name, channels, channel ids, type, frame buffer)] the view layer asks for,
    Combined first (frame buffer None: the image itself)."""
    out = [("Combined", 4, "RGBA", 'COLOR', None)]
    if view_layer.use_pass_z:
        out.append(("Depth", 1, "Z", 'VALUE', "depth"))
    if view_layer.use_pass_normal:
        out.append(("Normal", 3, "XYZ", 'VECTOR', "normal"))
    if view_layer.use_pass_mist:
        out.append(("Mist", 1, "Z", 'VALUE', "mist"))
    if view_layer.use_pass_object_index:
        out.append((OBJECT_INDEX, 1, "X", 'VALUE', "object_index"))
    if view_layer.use_pass_material_index:
        out.append((MATERIAL_INDEX, 1, "X", 'VALUE', "material_index"))
    settings = getattr(view_layer, "edgelight", None)
    for name, prop, buffer in OWN_PASSES:
        if settings is not None and (getattr(settings, prop) or (buffer == "lines" and settings.lines_as_pass)):
            out.append((name, 4, "RGBA", 'COLOR', buffer))
    return out


def lines_in_combined(view_layer):
    """Whether Combined carries the ink (off: Lines as Render Pass)."""
    settings = getattr(view_layer, "edgelight", None)
    return not (settings is not None and settings.lines_as_pass)


def register_passes(engine, scene, view_layer):
    for name, channels, chan_id, kind, _ in enabled(view_layer):
        engine.register_pass(scene, view_layer, name, channels, chan_id, kind)


def buffers_wanted(view_layer):
    """{frame buffer: None} for frame.render to fill: only what an enabled pass needs (Mist is
    made from the depth, the index passes from the ids)."""
    wanted = [buffer for *_, buffer in enabled(view_layer) if buffer]
    out = {buffer: None for buffer in wanted if buffer != "mist" and buffer not in FROM_IDS}
    if "mist" in wanted:
        out["depth"] = None
    if any(buffer in FROM_IDS for buffer in wanted):
        out["ids"] = None
    return out


def from_ids(buffers, view_layer, instances):
    """Replaces the first sample's ids in `buffers` by the index passes the view layer asks for."""
    ids = buffers.pop("ids", None)
    if ids is None:
        return
    if view_layer.use_pass_object_index:
        buffers["object_index"] = object_index(ids, instances)
    if view_layer.use_pass_material_index:
        buffers["material_index"] = material_index(ids, instances)


# A scene without a world: Blender's defaults of World.mist_settings.
DEFAULT_MIST = SimpleNamespace(start=5.0, depth=25.0, falloff='QUADRATIC')
# Blender's mist falloffs as the exponent Cycles raises the linear mist to.
MIST_FALLOFF = {'QUADRATIC': 2.0, 'LINEAR': 1.0, 'INVERSE_QUADRATIC': 0.5}


def mist(inv_depth, camera, mist_settings):
    """The Mist pass ((h, w, 1) float32) from the first sample's 1 / view depth (0: nothing drawn),
    as Cycles writes it: the distance from the eye along each pixel centre's ray, ((d - start) /
    depth) clamped to [0, 1] and raised to the falloff's exponent; 1 where nothing was drawn."""
    h, w = inv_depth.shape[:2]
    inv = inv_depth[..., 0] if inv_depth.ndim == 3 else inv_depth
    drawn = inv > 0.0
    z = np.where(drawn, 1.0 / np.where(drawn, inv, 1.0), 0.0)
    if camera.orthographic:
        d = z
    else:  # the ray through the pixel centre at view depth 1: its length scales the depth
        p = np.asarray(camera.projection, np.float64)
        x = (np.arange(w) + 0.5) / w * 2.0 - 1.0
        y = (np.arange(h) + 0.5) / h * 2.0 - 1.0
        # x_ndc = (p00 X + p02 Z) / -Z with Z = -1 at depth 1 (likewise y): X = (x_ndc + p02) / p00
        rx = (x[None, :] + p[0, 2]) / p[0, 0]
        ry = (y[:, None] + p[1, 2]) / p[1, 1]
        d = z * np.sqrt(1.0 + rx * rx + ry * ry)
    start, depth = float(mist_settings.start), max(float(mist_settings.depth), 1e-12)
    m = np.clip((d - start) / depth, 0.0, 1.0) ** MIST_FALLOFF.get(mist_settings.falloff, 1.0)
    m[~drawn] = 1.0
    return m.astype(np.float32)[..., None]


def object_index(ids, instances):
    """The Object Index pass ((h, w, 1) float32) from the first sample's ids ((h, w, 2): instance
    + 1, 0 where nothing was drawn; then the face): each pixel's object pass_index, 0 where
    nothing was drawn, as Cycles writes it (the pixel centre's object, not filtered)."""
    table = np.array([0.0] + [inst.pass_index for inst in instances], np.float32)
    index = np.rint(ids[..., 0]).astype(np.int64)
    index[(index < 0) | (index >= len(table))] = 0
    return table[index][..., None]


def material_index(ids, instances):
    """The Material Index pass ((h, w, 1) float32) from the first sample's ids: each pixel's
    material pass_index, through its instance's surface id -> triangle -> slot -> material
    (scene_sync.MeshExtract.surface_pass_indices), 0 where nothing was drawn or the slot has no
    material, as Cycles writes it."""
    # One table per extraction, concatenated; each instance points at its extraction's.
    tables, start, offset, size = [], {}, np.zeros(len(instances) + 1, np.int64), np.zeros(len(instances) + 1, np.int64)
    at = 1
    for i, inst in enumerate(instances, 1):
        key = id(inst.mesh)
        if key not in start:
            table = inst.mesh.surface_pass_indices()
            start[key] = (at, len(table))
            tables.append(table)
            at += len(table)
        offset[i], size[i] = start[key]
    flat = np.concatenate([np.zeros(1, np.float32)] + tables)
    inst = np.rint(ids[..., 0]).astype(np.int64)
    inst[(inst < 0) | (inst > len(instances))] = 0
    face = np.rint(ids[..., 1]).astype(np.int64)
    ok = (inst > 0) & (face >= 0) & (face < size[inst])
    return np.where(ok, flat[np.where(ok, offset[inst] + face, 0)], 0.0).astype(np.float32)[..., None]


def pass_pixels(buffer, data):
    """A frame buffer ((h, w, 4) float32; the index passes (h, w, 1)) as its render pass stores it."""
    if buffer == "depth":  # 1 / view depth, 0 = nothing drawn -> distance along the view axis
        inv = data[..., 0]
        out = np.full(inv.shape + (1,), BACKGROUND_DEPTH, np.float32)
        drawn = inv > 0.0
        out[drawn, 0] = 1.0 / inv[drawn]
        return out
    if buffer == "normal":
        return data[..., :3]
    if buffer == "lines":  # the line target keeps straight alpha; passes are premultiplied
        return np.concatenate([data[..., :3] * data[..., 3:4], data[..., 3:4]], axis=-1)
    return data


def write(result_layer, view_layer, buffers, record=None):
    """Writes every enabled pass that has its buffer; `record`, when a dict, receives what was
    written, by pass name (the tests' capture)."""
    for name, _, _, _, buffer in enabled(view_layer)[1:]:
        render_pass = result_layer.passes.get(name)
        data = buffers.get(buffer)
        if render_pass is None or data is None:
            continue  # cancelled before the buffer was drawn
        pixels = pass_pixels(buffer, data)
        compat.write_pass_channels(render_pass, pixels.reshape(-1, pixels.shape[-1]))
        if record is not None:
            record[name] = pixels


class VIEWLAYER_PT_edgelight_passes(EdgeLightPanel, bpy.types.Panel):
    bl_label = "EdgeLight Passes"
    bl_context = "view_layer"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        view_layer = context.view_layer
        col = layout.column(heading="Data")
        col.prop(view_layer, "use_pass_z")
        col.prop(view_layer, "use_pass_normal")
        col.prop(view_layer, "use_pass_mist")
        col = layout.column(heading="Indexes")
        col.prop(view_layer, "use_pass_object_index")
        col = layout.column(heading="EdgeLight")
        settings = view_layer.edgelight
        for _, prop, _ in OWN_PASSES:
            col.prop(settings, prop)
        col.prop(settings, "lines_as_pass")


_classes = (EdgeLightViewLayerSettings, VIEWLAYER_PT_edgelight_passes)


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(_classes)


def register():
    _register_classes()
    bpy.types.ViewLayer.edgelight = bpy.props.PointerProperty(type=EdgeLightViewLayerSettings)


def unregister():
    del bpy.types.ViewLayer.edgelight
    _unregister_classes()
