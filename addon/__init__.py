"""EdgeLight: rounded-edge highlights, ink lines and toon shading as a Blender render engine."""

bl_info = {
    "name": "EdgeLight",
    "author": "EdgeLight developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Render Properties > Render Engine > EdgeLight",
    "description": "Thin highlights on rounded edges without bevel geometry, live and in final renders",
    "category": "Render",
}

from . import engine, properties, ui, versioning  # noqa: E402


def register():
    properties.register()
    versioning.register()
    engine.register()
    ui.register()


def unregister():
    ui.unregister()
    engine.unregister()
    versioning.unregister()
    properties.unregister()
