/* What one pixel shows of a rounded edge's band (edge_highlight.frag.glsl): EdgeLight's method
 * (docs/highlight_math.md, section 15), at every width. The band lies where the fillet's image
 * really lies, and the pixel is shaded with the part of the arc whose image it covers. Needs
 * highlight_arc.glsl, edge_shading.glsl and edge_band.glsl. */

/* Premultiplied (W Is, W) of the pixel whose centre is `pc`, at edge point X seen along unit V;
 * `across`: the pixel centre's distance from the edge line in pixels (along edge_screen.zw).
 * Zero where the pixel shows none of the band. */
vec4 el_band_pixel(vec2 pc, vec3 X, vec3 V, float world_per_px, float across)
{
  ElArc g = el_arc(edge_dir, edge_n1, edge_n2, V);
  float s = sqrt(dot(g.view, g.view)); /* |E x V| */
  if (!(g.width > 0.0) || !(s > 0.0)) {
    return vec4(0.0);
  }
  float ramp = el_axial_ramp(s);
  vec3 P = el_safe_normalize(cross(el_safe_normalize(edge_dir), V));
  /* Which way P points on screen (the sign of its image along edge_screen's normal). */
  vec4 q0 = frame.projection * (frame.view * vec4(X, 1.0));
  vec4 q1 = frame.projection * (frame.view * vec4(X + P * world_per_px, 1.0));
  float side = dot((q1.xy / q1.w - q0.xy / q0.w) * frame.viewport.xy, edge_screen.zw) < 0.0 ? -1.0 : 1.0;
  vec2 ends = el_band_ends(g, P, edge_fold) * (side * edge_radius / world_per_px);
  float b0 = min(ends.x, ends.y), b1 = max(ends.x, ends.y);
  float pa = max(across - 0.5, b0), pb = min(across + 0.5, b1);
  float cover = clamp(pb - pa, 0.0, 1.0);
  /* The band's ends on the face this pixel lies over (band_ends.py): the pixel's centre on the
   * body's side of each cut. Two bands meeting on a cut then split its pixels exactly (a
   * filtered cut would leave a seam: bands blend over each other, they do not add); the
   * jittered samples antialias the cut as they do the outline. */
  bool on_f1 = across * edge_far.z >= 0.0;
  vec2 cut0 = on_f1 ? edge_cut0.xy : edge_cut0.zw, cut1 = on_f1 ? edge_cut1.xy : edge_cut1.zw;
  if (dot(pc - edge_screen.xy, cut0) < 0.0 || dot(pc - edge_far.xy, cut1) < 0.0) {
    return vec4(0.0);
  }
  float W = clamp(tint.w * cover, 0.0, 1.0) * ramp;
  if (!(W > 0.0 && b1 > b0)) {
    return vec4(0.0);
  }
  /* Fractions of the band from vis.lo's end. */
  float fa = (pa - ends.x) / (ends.y - ends.x), fb = (pb - ends.x) / (ends.y - ends.x);
  ElArc sub = el_sub_arc(g, clamp(min(fa, fb), 0.0, 1.0), clamp(max(fa, fb), 0.0, 1.0));
  vec3 col = el_edge_colour(sub, X, V, edge_dir);
  return vec4(col * W, W);
}
