"""Reading Blender: the evaluated scene into immutable per-mesh and per-instance data
(scene_sync.py, kept across renders by render_cache.py), materials and their node chains
(materials.py, material_inputs.py, node_program.py, textures.py), the world's light
(world_light.py, environment_filter.py). Reads, never writes, the user's data
(docs/architecture.md, "Layers")."""
