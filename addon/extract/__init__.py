"""Reading Blender: the evaluated scene into immutable per-mesh and per-instance data
(scene_sync.py, kept across renders by render_cache.py), materials and their node chains
(materials.py, material_inputs.py, node_program.py, textures.py), the world's light
(world_light.py, environment_filter.py). It reads the user's data; it writes only what an
artist's operator asks for (a material's toon ramp, color_ramp.py) (docs/architecture.md,
"Layers")."""
