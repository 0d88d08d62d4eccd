"""Every difference between Blender versions the add-on meets (3.4 through 5.x) lives here.

Nothing else in the add-on checks bpy.app.version or probes for an API.
"""
import bpy
import numpy as np


def _edge_attribute(mesh, name, dtype):
    attr = mesh.attributes.get(name)
    if attr is None or attr.domain != 'EDGE':
        return None
    out = np.empty(len(mesh.edges), dtype=dtype)
    attr.data.foreach_get("value", out)
    return out


def _edge_property(mesh, prop, dtype):
    if not hasattr(bpy.types.MeshEdge, "bl_rna") or prop not in bpy.types.MeshEdge.bl_rna.properties:
        return None
    out = np.empty(len(mesh.edges), dtype=dtype)
    mesh.edges.foreach_get(prop, out)
    return out


def _edge_data(mesh, attribute, legacy, dtype):
    # Attributes first (4.0+, and 5.0's freestyle_edge), legacy MeshEdge properties otherwise.
    for get in (lambda: _edge_attribute(mesh, attribute, dtype), lambda: _edge_property(mesh, legacy, dtype)):
        value = get()
        if value is not None:
            return value
    return np.zeros(len(mesh.edges), dtype=dtype)


def edge_sharp(mesh):
    return _edge_data(mesh, "sharp_edge", "use_edge_sharp", bool)


def edge_seam(mesh):
    return _edge_data(mesh, ".uv_seam", "use_seam", bool)


def edge_freestyle(mesh):
    return _edge_data(mesh, "freestyle_edge", "use_freestyle_mark", bool)


def edge_bevel_weight(mesh):
    return _edge_data(mesh, "bevel_weight_edge", "bevel_weight", np.float32)


def corner_normals(mesh):
    """(loops, 3) float32 normals as Blender shades them (smooth, flat, sharp edges, custom)."""
    out = np.empty(len(mesh.loops) * 3, dtype=np.float32)
    if hasattr(mesh, "corner_normals"):  # 4.1+
        mesh.corner_normals.foreach_get("vector", out)
    else:
        mesh.calc_normals_split()  # on the evaluated copy, never the user's mesh
        mesh.loops.foreach_get("normal", out)
    return out.reshape(-1, 3)


def triangle_material_index(mesh):
    tris = mesh.loop_triangles
    out = np.empty(len(tris), dtype=np.int32)
    if "material_index" in bpy.types.MeshLoopTriangle.bl_rna.properties:
        tris.foreach_get("material_index", out)
        return out
    poly = np.empty(len(tris), dtype=np.int32)
    tris.foreach_get("polygon_index", poly)
    attr = mesh.attributes.get("material_index")
    if attr is None:
        return np.zeros(len(tris), dtype=np.int32)
    per_poly = np.empty(len(mesh.polygons), dtype=np.int32)
    attr.data.foreach_get("value", per_poly)
    return per_poly[poly]


# 5.0 always renders worlds and materials with their node trees; `use_nodes` is deprecated there
# (a DeprecationWarning on every read) and a file's node-less world is versioned into a tree.
_ALWAYS_NODES = bpy.app.version >= (5, 0)


def uses_nodes(id_block):
    """Whether a World or Material renders from its node tree."""
    if id_block.node_tree is None:
        return False
    return _ALWAYS_NODES or id_block.use_nodes


def alpha_blend(material):
    """How EEVEE cuts a material by its alpha: ('OPAQUE' | 'CLIP' | 'HASHED' | 'BLEND', the clip
    threshold). 4.2+ (EEVEE Next) has a render method instead: Dithered is hashed, Blended
    blended; 3.4's Blend Mode Opaque ignores the alpha."""
    method = getattr(material, "surface_render_method", None)
    if method is not None:
        return ('BLEND' if method == 'BLENDED' else 'HASHED'), 0.5
    return getattr(material, "blend_method", 'OPAQUE'), float(getattr(material, "alpha_threshold", 0.5))


def shadow_mode(material):
    """How a material casts shadows in EEVEE: ('OPAQUE' | 'CUT' | 'NONE', how a cut cuts: 'CLIP'
    or 'HASHED'). 3.4: its Shadow Mode (Clip, Hashed; None casts nothing), whatever its Blend
    Mode; 4.2+ (EEVEE Next): Transparent Shadows (on by default), hashed as its surface."""
    if hasattr(material, "surface_render_method"):
        return ('CUT' if getattr(material, "use_transparent_shadow", True) else 'OPAQUE'), 'HASHED'
    method = getattr(material, "shadow_method", 'OPAQUE')
    if method in {'CLIP', 'HASHED'}:
        return 'CUT', method
    return ('NONE' if method == 'NONE' else 'OPAQUE'), 'CLIP'


def write_pass(render_pass, pixels):
    """pixels: (h * w, 4) float32. Newer versions take a flat array, 3.4 a 2-D one."""
    try:
        render_pass.rect.foreach_set(pixels.reshape(-1))
    except TypeError:
        render_pass.rect.foreach_set(pixels.reshape(-1, 4))




# Blender's Object and Material Index render passes: 5.0 renamed them from "IndexOB" and "IndexMA"
# (Cycles registers the same).
OBJECT_INDEX_PASS = "Object Index" if bpy.app.version >= (5, 0) else "IndexOB"
MATERIAL_INDEX_PASS = "Material Index" if bpy.app.version >= (5, 0) else "IndexMA"


def eevee_engine_id():
    """EEVEE's engine id: BLENDER_EEVEE in 3.4 and 5.x, BLENDER_EEVEE_NEXT in 4.2 to 4.5."""
    items = bpy.types.RenderSettings.bl_rna.properties["engine"].enum_items
    return next(i.identifier for i in items if i.identifier.startswith("BLENDER_EEVEE"))


# Blender's own panels EdgeLight shows, beyond the engine-neutral ones, by what they show. The
# names are the same in 3.4, 4.2, 4.5 and 5.0 (looked up in each; the EEVEE Next and 5.0
# renames touched only panels EdgeLight leaves out), so one table serves every version; a name a
# version lacks is passed over.
SHOWN_PANELS = (
    "EEVEE_MATERIAL_PT_context_material",  # the slot list, New and the material's ID template
    "EEVEE_WORLD_PT_surface",  # the world's Background node, or world.color without nodes
)
# EEVEE's material Surface panel (the Principled BSDF's inputs, or without nodes the viewport
# colour, roughness and metallic EdgeLight reads) is drawn by ui.EDGELIGHT_PT_material_surface,
# after EdgeLight's own material panel instead of above it.
# Engine-neutral panels ('BLENDER_RENDER') left out, by name part: Freestyle's (EdgeLight draws
# its own lines), motion blur (not supported), and the light's type-only panel and area size
# (EdgeLight's own light panel shows the type with the settings it reads). EEVEE's light panel,
# shadow, volume, material settings and preview panels are never added: they show settings
# EdgeLight ignores.
_HIDDEN = ("freestyle", "motion_blur", "DATA_PT_light", "DATA_PT_area")


def _hidden(name):
    lower = name.lower()
    return name in _HIDDEN or any(part in lower for part in _HIDDEN if part.islower())


def compat_panels():
    """Built-in panels that list Blender's own engines and should show for EdgeLight too."""
    named = [(name, getattr(bpy.types, name)) for name in dir(bpy.types)]
    named = [(name, cls) for name, cls in named if isinstance(getattr(cls, "COMPAT_ENGINES", None), set)]
    # The node editor's copies of panels (NODE_DATA_PT_light, ...) share their original's set:
    # a set any hidden panel uses stays untouched.
    hidden_sets = {id(cls.COMPAT_ENGINES) for name, cls in named if _hidden(name)}
    panels = []
    for name, cls in named:
        engines = cls.COMPAT_ENGINES
        if id(engines) in hidden_sets:
            continue
        # 'BLENDER_RENDER' marks the engine-neutral panels (output, camera, colour management,
        # custom properties); Workbench-only ones (its lighting, colour, film) don't apply.
        if "BLENDER_RENDER" in engines or name in SHOWN_PANELS:
            panels.append(cls)
    return panels



def texture(size, fmt, data=None, layers=0):
    """GPUTexture with keyword arguments (keyword-only in 5.0); `layers` > 0: a 2D array."""
    import gpu
    extra = {"layers": layers} if layers else {}
    if data is None:
        return gpu.types.GPUTexture(size, format=fmt, **extra)
    return gpu.types.GPUTexture(size, format=fmt, data=data, **extra)


def write_pass_channels(render_pass, pixels):
    """pixels: (h * w, channels) float32 for a pass of any channel count (1 Depth, 3 Normal, 4
    colour). 4.2+ take a flat array, 3.4 one row per pixel."""
    pixels = np.ascontiguousarray(pixels, np.float32).reshape(-1, render_pass.channels)
    try:
        render_pass.rect.foreach_set(pixels.reshape(-1))
    except TypeError:
        render_pass.rect.foreach_set(pixels)


def polygon_normals(mesh):
    """(polygons, 3) float32 unit normals of the polygons (4.1+ keeps them in polygon_normals)."""
    out = np.empty(len(mesh.polygons) * 3, dtype=np.float32)
    if hasattr(mesh, "polygon_normals"):
        mesh.polygon_normals.foreach_get("vector", out)
    else:
        mesh.polygons.foreach_get("normal", out)
    return out.reshape(-1, 3)


def declare_depth_write(info, mode):
    """Declares how a program changes gl_FragDepth (programs.json depth_write: ANY, GREATER or
    LESS) on its GPUShaderCreateInfo. Blender 4.x+ declares gl_FragDepth depth_unchanged for a
    program that declares nothing, and a driver may then test and store the rasterised depth in
    place of the written one (NVIDIA does: docs/lines.md, "Depth on every GPU"); Metal declares
    no depth output at all. Where create-infos take it (4.5+), it is declared there. 4.2 has no
    such call but defines come before its declaration, so depth_unchanged is defined as the
    wanted layout; 3.4 declares no layout (the default is any), where the define is unused."""
    if hasattr(info, "depth_write"):
        info.depth_write(mode)
    else:
        info.define("depth_unchanged", "depth_" + mode.lower())
