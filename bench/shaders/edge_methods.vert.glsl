/* The edge pass's quad for every method (edge_methods.glsl). EdgeLight's is the add-on's
 * (edge_band_extent.glsl, compiled as el_partial_*); the whole-arc and paper methods centre the
 * band on the line and shade short edges once, here. */
#undef el_half_width_px
#undef el_quad_sides
#undef el_band_pixel

float el_half_width_px(vec3 at)
{
  if (EL_EDGE_METHOD == EL_METHOD_PARTIAL || EL_EDGE_METHOD == EL_METHOD_QUADRATURE) {
    return el_partial_half_width_px(at);
  }
  float dist = frame.eye.w > 0.5 ? length(frame.eye.xyz - at) : 1.0;
  float px_per_unit = frame.camera.x / max(dist, 1e-20);
  /* The whole arc's projected width, centred on the line. The paper's method draws a one-pixel
   * line whatever the width. */
  float reach_px = 0.5 * edge_radius * length(edge_n1 - edge_n2) * px_per_unit;
  float half_px = min(reach_px, 2048.0) + 0.5 + 1.0 / 64.0;
  return EL_EDGE_METHOD == EL_METHOD_PAPER ? max(half_px, 1.0 + 1.0 / 64.0) : half_px;
}

/* Short edges under the whole-arc methods: shaded once, at the midpoint, by the edge's one
 * shading vertex (corner.w = 1), which provides both triangles' flat outputs edge_color and
 * edge_arc (the add-on's passes/batches.py orders the quads' triangles for it). */
void el_shade_short_edge(vec3 w0, vec3 w1, vec4 c0, vec4 c1)
{
  edge_color = vec4(0.0);
  edge_arc = vec2(0.0);
  vec2 s0 = (c0.xy / c0.w * 0.5 + 0.5) * frame.viewport.xy;
  vec2 s1 = (c1.xy / c1.w * 0.5 + 0.5) * frame.viewport.xy;
  float len = length(s1 - s0);
  bool whole_arc = EL_EDGE_METHOD == EL_METHOD_WHOLE || EL_EDGE_METHOD == EL_METHOD_PAPER;
  if (whole_arc && len < EL_SHADE_PER_EDGE_BELOW_PX && corner.w > 0.5) {
    vec3 mid = 0.5 * (w0 + w1);
    vec3 Vm = frame.eye.w > 0.5 ? frame.eye.xyz - mid : -frame.view_dir.xyz;
    vec3 Vu = el_safe_normalize(Vm);
    ElArc g = el_arc(edge_dir, edge_n1, edge_n2, Vu);
    edge_color = vec4(el_edge_colour(g, mid, Vu, edge_dir), 1.0);
    edge_arc = vec2(g.width, sqrt(dot(g.view, g.view))); /* visible width, |E x V| */
  }
}

/* The quad's sides: fitted to where the band lies (EdgeLight's method, unless EL_TIGHT_QUADS is
 * false), else symmetric about the line. Called once per vertex after culling, it also shades a
 * short edge for the whole-arc methods. */
vec2 el_quad_sides(vec3 w0, vec3 w1, vec4 c0, vec4 c1, vec2 across, float reach)
{
  el_shade_short_edge(w0, w1, c0, c1);
  if (EL_TIGHT_QUADS && (EL_EDGE_METHOD == EL_METHOD_PARTIAL || EL_EDGE_METHOD == EL_METHOD_QUADRATURE)) {
    return el_partial_quad_sides(w0, w1, c0, c1, across, reach);
  }
  return vec2(-reach, reach);
}
