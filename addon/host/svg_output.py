"""SVG output of the ink lines: the scene setting (Render Properties -> EdgeLight Lines -> SVG
Output), the file written beside each rendered frame, and the operator that exports a view.

The SVG holds the lines the line pass drew, with the same visibility (vector_lines.py)."""
import os
import time

import bpy

from ..linework import svg_write, vector_lines
from .panel_base import EdgeLightPanel

# A render-based export (the operator without a 3D view, e.g. headless) names its file and view
# layer in this window-manager property for the render it starts (the window manager's
# properties are never saved): the engine writes that layer's SVG there in place of the frame's
# path. The operator sets and clears it.
_REQUEST = "edgelight_svg_export"
_IMAGE_EXTENSIONS = {".png", ".jpg", ".jpeg", ".exr", ".tif", ".tiff", ".bmp", ".tga", ".hdr", ".jp2",
                     ".webp", ".cin", ".dpx", ".rgb", ".sgi"}


class EdgeLightSvgSettings(bpy.types.PropertyGroup):
    enabled: bpy.props.BoolProperty(
        name="SVG Output", default=False,
        description="Write the visible ink lines of each rendered frame as an SVG file beside it "
                    "(<output path>_####.svg), one layer per line type")


class EdgeLightSvgExport(bpy.types.PropertyGroup):
    """What the export operator asks of the render it starts: the SVG of `view_layer` at `path`."""
    path: bpy.props.StringProperty(subtype='FILE_PATH')
    view_layer: bpy.props.StringProperty()


def export_request(layer):
    """The path the export operator asked the running render to write for view layer `layer`,
    or ""."""
    wms = bpy.data.window_managers
    request = getattr(wms[0], _REQUEST, None) if len(wms) else None
    return request.path if request is not None and request.path and request.view_layer == layer else ""


def wanted(scene, layer):
    return bool(export_request(layer)) or scene.edgelight_svg.enabled


def frame_svg_path(scene, layer=None, still=False, view=None):
    """The frame's output path with .svg for the image extension (and the view layer's name
    when the scene renders several). `still`: named as Blender names a still it writes
    (render(write_still=True): the output path without a frame number), not an animation's frame.
    `view`: a multiview render's view, whose file suffix (_L, _R) its images carry too."""
    if still:
        path = scene.render.filepath
        if scene.render.use_file_extension:
            path += scene.render.file_extension
    else:
        path = scene.render.frame_path(frame=scene.frame_current)
    root, ext = os.path.splitext(path)
    if ext.lower() in _IMAGE_EXTENSIONS:
        path = root
    if layer and sum(1 for v in scene.view_layers if v.use) > 1:
        path += "_" + bpy.path.clean_name(layer)
    if view and view in scene.render.views:
        path += scene.render.views[view].file_suffix
    return bpy.path.abspath(path) + ".svg"


def write(path, scene_data, camera, line_settings, vector, view=None):
    """Writes the SVG of one frame from its line record (frame.LineRecord); returns its size in
    bytes. `view`: svg_write.document's."""
    instances = vector_lines.instances_of(scene_data, vector.view_segments)
    strokes = vector_lines.strokes(instances, line_settings, camera, vector.depth, vector.ids, vector.rounded)
    root = svg_write.document(strokes, line_settings, camera.width, camera.height, view=view)
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    svg_write.write(path, root)
    return os.path.getsize(path)


def write_render(scene, layer, scene_data, camera, line_settings, vector, record, view=None, still=False,
                 eye=None):
    """The engine's hook after a frame: the frame's SVG (or the pending export's); `view`, the
    part of the drawn frame Blender asked for (svg_write.document); `still`, `eye` (the
    multiview view): frame_svg_path's `still` and `view`."""
    if line_settings is None or vector is None:
        return
    start = time.perf_counter()
    path = export_request(layer) or frame_svg_path(scene, layer, still, eye)
    size = write(path, scene_data, camera, line_settings, vector, view)
    # The record outlives the render only for tests (engine.capture).
    record.update(svg=path, svg_bytes=size, svg_seconds=time.perf_counter() - start, vector=vector)


def _view_camera(context):
    """The 3D view's camera (viewport.viewport_camera) when it does not look through the scene camera."""
    from .viewport import viewport_camera
    rv3d, region = context.region_data, context.region
    if rv3d is None or region is None or rv3d.view_perspective == 'CAMERA':
        return None
    return viewport_camera(rv3d, region.width, region.height)


class EDGELIGHT_OT_export_svg(bpy.types.Operator):
    """Export the visible ink lines of this view as SVG (the 3D view's, or the scene camera's)"""
    bl_idname = "edgelight.export_svg"
    bl_label = "Export Lines as SVG"
    filepath: bpy.props.StringProperty(subtype='FILE_PATH')
    filter_glob: bpy.props.StringProperty(default="*.svg", options={'HIDDEN'})

    def invoke(self, context, event):
        if not self.filepath:
            self.filepath = frame_svg_path(context.scene)
        context.window_manager.fileselect_add(self)
        return {'RUNNING_MODAL'}

    def execute(self, context):
        from ..linework import lines
        if lines.settings_of(context.scene.edgelight) is None:
            self.report({'ERROR'}, "EdgeLight: no lines to export (turn on EdgeLight Lines)")
            return {'CANCELLED'}
        path = bpy.path.ensure_ext(bpy.path.abspath(self.filepath), ".svg")
        camera = _view_camera(context)
        if camera is None:
            # The scene camera: a render writes this view layer's (a render has a GPU context
            # even headless).
            if not context.view_layer.use:
                self.report({'ERROR'}, f"EdgeLight: view layer '{context.view_layer.name}' does not render "
                                       f"(its Use for Rendering is off): no lines to export")
                return {'CANCELLED'}
            request = getattr(context.window_manager, _REQUEST)
            request.path, request.view_layer = path, context.view_layer.name
            try:
                bpy.ops.render.render()
            finally:
                request.path, request.view_layer = "", ""
        else:
            self._export_view(context, camera, path)
        self.report({'INFO'}, f"EdgeLight: lines written to {path}")
        return {'FINISHED'}

    @staticmethod
    def _export_view(context, camera, path):
        from ..bridge import native
        from ..extract import scene_sync
        from ..linework import lines
        from ..passes import frame
        try:
            lib = native.load()  # as the engine loads it, without importing the engine
        except native.NativeError as e:
            raise RuntimeError(f"EdgeLight: native library unavailable: {e}") from None
        depsgraph = context.evaluated_depsgraph_get()
        line_settings = lines.settings_of(context.scene.edgelight)
        data = scene_sync.collect(depsgraph, lib=lib, line_settings=line_settings)
        out = frame.render(data, camera, frame.Settings(samples=1, highlights=False, lines=line_settings), vector=True)
        if out.lines is None:
            raise RuntimeError("EdgeLight: no sample was drawn for the SVG")
        write(path, data, camera, line_settings, out.lines)


class EDGELIGHT_PT_lines_svg(EdgeLightPanel, bpy.types.Panel):
    bl_label = "SVG Output"
    bl_context = "render"
    bl_parent_id = "EDGELIGHT_PT_lines"
    bl_options = {'DEFAULT_CLOSED'}

    def draw_header(self, context):
        self.layout.prop(context.scene.edgelight_svg, "enabled", text="")

    def draw(self, context):
        layout = self.layout
        layout.active = context.scene.edgelight.use_lines
        col = layout.column()
        col.active = context.scene.edgelight_svg.enabled
        col.label(text=bpy.path.basename(frame_svg_path(context.scene)), icon='FILE')
        layout.operator(EDGELIGHT_OT_export_svg.bl_idname, icon='EXPORT')


CLASSES = (EdgeLightSvgSettings, EdgeLightSvgExport, EDGELIGHT_OT_export_svg, EDGELIGHT_PT_lines_svg)


_register_classes, _unregister_classes = bpy.utils.register_classes_factory(CLASSES)


def register():
    _register_classes()
    bpy.types.Scene.edgelight_svg = bpy.props.PointerProperty(type=EdgeLightSvgSettings)
    setattr(bpy.types.WindowManager, _REQUEST, bpy.props.PointerProperty(type=EdgeLightSvgExport, options={'HIDDEN'}))


def unregister():
    delattr(bpy.types.WindowManager, _REQUEST)
    del bpy.types.Scene.edgelight_svg
    _unregister_classes()
