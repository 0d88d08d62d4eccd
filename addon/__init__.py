"""EdgeLight: rounded-edge highlights, ink lines and toon shading as a Blender render engine."""

bl_info = {
    "name": "EdgeLight",
    "author": "EdgeLight developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Render Properties > Render Engine > EdgeLight",
    "description": "Rounded-edge highlights without bevel geometry, ink lines and toon shading, live and in final renders",
    "category": "Render",
}

from .extract import color_ramp  # noqa: E402
from .host import engine, properties, render_passes, svg_output, ui, versioning  # noqa: E402


def register():
    properties.register()
    versioning.register()
    color_ramp.register()
    render_passes.register()
    engine.register()
    ui.register()
    svg_output.register()  # its panel sits in ui's Lines panel


def unregister():
    svg_output.unregister()
    ui.unregister()
    engine.unregister()
    render_passes.unregister()
    color_ramp.unregister()
    versioning.unregister()
    properties.unregister()
