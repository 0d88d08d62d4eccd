"""Blender glue: the RenderEngine (engine.py: final renders; viewport.py: the 3D view), the
settings and their panels (properties.py, ui.py, ui_light.py, render_passes.py), versioning of
older files and the SVG operator (svg_output.py). The top layer: it may import every other
(docs/architecture.md, "Layers")."""
