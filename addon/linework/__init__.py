"""The ink as data: which edges each line type draws, chains and view lines (lines.py), the
line pass's visibility rule on the CPU (line_visibility.py) and the SVG output's strokes and
document (vector_lines.py, svg_write.py). No bpy (docs/architecture.md, "Layers")."""
