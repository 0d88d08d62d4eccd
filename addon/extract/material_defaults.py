"""Defaults of a material's EdgeLight settings, in one place: the settings' defaults
(properties.py) and the look of a slot without a material (materials.shading_of(None)) are
read from here. No bpy: plain-Python tests import it."""

ROUNDED = True                                # use_rounding: the material rounds its chosen edges
HIGHLIGHT_STRENGTH = 1.0                      # K
# The largest Highlight Strength: 1 draws the coverage a real rounded edge of the radius has.
# Above 1, W = clamp(K x covered length, 0, 1) saturates the band's partly covered pixels: on a
# band under a pixel wide that is the band of K times the radius, and on a wider band only its
# anti-aliasing is lost (stair-stepped rims). So a wider band is asked for with the radius, which
# stays a fillet's (radius_clamp.py); docs/addon.md, "Large settings".
K_MAX = 1.0                                   # K's largest value
RADIUS = 0.05                                 # object's local units, scaled with the object: Cycles'
                                              # Bevel node's default, the render this previews
RADIUS_LAYOUT_4 = 0.01                        # the default up to settings layout 4 (versioning.py)
TINT = (1.0, 1.0, 1.0)                        # multiplies the highlight's specular part
EDGES = frozenset({'ANGLE', 'SHARP', 'BEVEL'})  # selection: which rules choose the rounded edges
ANGLE_DEG = 30.0                              # angle: faces meeting at more than this are rounded
SHADING = 'PHONG'                             # shading: a key of shaders/surface_modes.json
