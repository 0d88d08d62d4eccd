/* What one pixel shows of the band under every method (edge_methods.glsl). EdgeLight's is the
 * add-on's (edge_band_pixel.glsl, compiled as el_partial_band_pixel), and so is the quadrature
 * method's, with the quadrature kernel in el_edge_colour. */
#undef el_half_width_px
#undef el_quad_sides
#undef el_band_pixel

/* The share of the band [b0, b1]'s part in the pixel centred at `across` (its box across the
 * line, a pixel wide) that lies on N1's face's side of the line (at 0; edge_far.z: the side N1's
 * face lies on in the image). */
float el_share_on_n1(float across, float b0, float b1)
{
  float pa = max(across - 0.5, b0), pb = min(across + 0.5, b1);
  float on1 = edge_far.z >= 0.0 ? pb - max(pa, 0.0) : min(pb, 0.0) - pa;
  return pb > pa ? clamp(on1 / (pb - pa), 0.0, 1.0) : 0.5;
}

vec4 el_band_pixel(vec2 pc, vec3 X, vec3 V, float world_per_px, float across, out float share1, out float pixel1)
{
  if (EL_EDGE_METHOD == EL_METHOD_PARTIAL || EL_EDGE_METHOD == EL_METHOD_QUADRATURE) {
    return el_partial_band_pixel(pc, X, V, world_per_px, across, share1, pixel1);
  }
  /* These methods' pixel is a box a pixel wide across the line. The paper's line replaces
   * nothing but the pixel's mean (no faces-under correction). */
  pixel1 = clamp(0.5 + across * edge_far.z, 0.0, 1.0);
  share1 = pixel1;
  /* The whole-arc and paper methods: a band of projected width w (pixels) centred on the edge
   * line, the pixel's box-filtered coverage of it, and the whole visible arc's mean colour. It
   * is exact only if the band were centred and fell within one pixel; measured against fillets
   * it is off already at a pixel (BENCHMARKS.md). Short edges come shaded from the vertex
   * shader; long ones are shaded here, per pixel. */
  bool per_edge = edge_color.w > 0.5;
  ElArc g;
  float width, s;
  if (per_edge) {
    width = edge_arc.x;
    s = edge_arc.y;
  }
  else {
    g = el_arc(edge_dir, edge_n1, edge_n2, V);
    width = g.width;
    s = sqrt(dot(g.view, g.view)); /* |E x V| */
  }
  if (!(width > 0.0) || !(s > 0.0)) {
    return vec4(0.0);
  }
  float w_px = edge_radius * width / world_per_px;
  float ramp = el_axial_ramp(s);
  float cover = clamp(min(across + 0.5, 0.5 * w_px) - max(across - 0.5, -0.5 * w_px), 0.0, 1.0);
  if (EL_EDGE_METHOD == EL_METHOD_WHOLE) {
    share1 = el_share_on_n1(across, -0.5 * w_px, 0.5 * w_px);
  }
  if (EL_EDGE_METHOD == EL_METHOD_PAPER) {
    /* A one-pixel line whatever the width, weighted by the whole arc's image width. */
    if (per_edge) {
      g = el_arc(edge_dir, edge_n1, edge_n2, V);
    }
    float full = edge_radius * length(el_arc_normal(g, 0.0) - el_arc_normal(g, g.alpha)) / world_per_px;
    cover = clamp(1.0 - abs(across), 0.0, 1.0) * min(full, 1.0);
  }
  float W = clamp(tint.w * cover, 0.0, 1.0) * ramp;
  if (!(W > 0.0)) {
    return vec4(0.0);
  }
  vec3 col = per_edge ? edge_color.rgb : el_edge_colour(g, X, V, edge_dir);
  return vec4(col * W, W);
}
