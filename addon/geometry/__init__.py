"""Per-mesh geometry after classification: which edges each material rounds and at what radius
(edge_choice.py, radius_clamp.py), band ends, corner patches, shading normals, closed surfaces
and the rounded outline's records. Plain arrays in and out, asking the library for the kernels
(bridge). No bpy (docs/architecture.md, "Layers")."""
