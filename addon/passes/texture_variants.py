"""Which program variant draws a slot's node program and image (materials.BaseTexture): its
texture key, shared by the surface, edge and shadow passes, and the defines of that variant
(shaders/textures.glsl, material_program.glsl)."""
from ..bridge import shader_specs

# The surface program's shading modes, an image's extensions and its alpha's cuts
# (shaders/surface_modes.json).
SURFACE_MODES = shader_specs.enum("surface_modes.json", "EL_SURFACE_MODE")
EXTEND = shader_specs.enum("surface_modes.json", "EL_EXTEND")
ALPHA = shader_specs.enum("surface_modes.json", "EL_ALPHA")


def texture_key(s, mode, alpha=True):
    """(Closest, extension[, alpha]) of the variant that draws a slot's node program and image
    (its materials.BaseTexture) in the Phong mode, or in any mode cuts the surface by its
    image's alpha (`alpha`: the edge pass cuts nothing), or None."""
    cuts = alpha and s.texture is not None and s.texture.alpha != ALPHA["NONE"]
    if s.texture is None or (mode != SURFACE_MODES["PHONG"] and not cuts):
        return None
    source = s.texture.source
    key = (int(source.closest), EXTEND[source.extension]) if source is not None else (0, EXTEND["REPEAT"])
    return key + (int(s.texture.alpha),) if alpha else key  # the edge pass cuts nothing: no variants by alpha


def texture_defines(key):
    """The defines of the variant drawing an image with texture_key `key` (shaders/textures.glsl)."""
    if key is None:
        return {}
    return {"EL_BASE_TEXTURE": 1, "EL_TEX_CLOSEST": key[0], "EL_TEX_EXTEND": key[1],
            "EL_TEX_ALPHA": key[2] if len(key) > 2 else 0}
