"""The bridge: what the add-on shares with the other host (edgelight-render). The C ABI of
libedgelight (native.py, through ctypes; the file check before it is mapped, library_check.py;
each platform's file, platforms.py) and the shader contracts in shaders/*.json (shader_specs.py).
No bpy: the lowest layer, imported by every other (docs/architecture.md, "Layers")."""
