/* The add-on's method functions that follow (edge_band_extent.glsl, edge_band_pixel.glsl) are
 * compiled under these names; edge_methods.vert.glsl and edge_methods.frag.glsl then define the
 * add-on's names for every method and call these for EdgeLight's own, so that method is the
 * add-on's code, not a copy. The quadrature kernel's el_arc_mean (edge_methods.glsl) ends here. */
#undef el_arc_mean
#define el_half_width_px el_partial_half_width_px
#define el_quad_sides el_partial_quad_sides
#define el_band_pixel el_partial_band_pixel
