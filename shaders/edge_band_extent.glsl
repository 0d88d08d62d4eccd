/* How far across its edge line a rounded edge's band reaches, and the sides of the quad that
 * covers it (edge_highlight.vert.glsl). Needs highlight_arc.glsl and edge_band.glsl. */

/* Half the quad's width in pixels at world point `at` on the edge: half a pixel past the widest
 * the band can be there, with the fold of either end. */
float el_half_width_px(vec3 at)
{
  float dist = frame.eye.w > 0.5 ? length(frame.eye.xyz - at) : 1.0;
  float px_per_unit = frame.camera.x / max(dist, 1e-20);
  /* The whole arc's projected width. Bands wider than a pixel lie where the fillet's image is
   * (edge_band.glsl): up to its tangent length r tan(alpha / 2) = r |N1 - N2| / |N1 + N2| from
   * the line on either side. */
  float reach_px = 0.0;
  for (int k = 0; k < 2; k++) { /* the fold at either end (el_edge_frame) */
    vec3 E, n1, n2;
    el_edge_frame(float(k), E, n1, n2);
    float tangent = length(n1 - n2) / max(length(n1 + n2), 1e-3);
    reach_px = max(reach_px, max(0.5 * length(n1 - n2), tangent) * edge_radius * px_per_unit);
  }
  return min(reach_px, 2048.0) + 0.5 + 1.0 / 64.0;
}

/* Where the band lies across the edge line at world point `at`, line parameter t there
 * (pixels along `across`, low and high): the visible arc's image, as the fragment shader finds
 * it per pixel (edge_band.glsl). */
vec2 el_band_px(vec3 at, float t, vec4 clip_at, vec2 across)
{
  bool persp = frame.eye.w > 0.5;
  vec3 V = el_safe_normalize(persp ? frame.eye.xyz - at : -frame.view_dir.xyz);
  float world_per_px = (persp ? length(frame.eye.xyz - at) : 1.0) / frame.camera.x;
  vec3 E, n1, n2;
  el_edge_frame(t, E, n1, n2);
  ElArc g = el_arc(E, n1, n2, V);
  vec3 P = el_safe_normalize(cross(el_safe_normalize(E), V));
  vec4 q1 = frame.projection * (frame.view * vec4(at + P * world_per_px, 1.0));
  float side = dot((q1.xy / q1.w - clip_at.xy / clip_at.w) * frame.viewport.xy, across) < 0.0 ? -1.0 : 1.0;
  vec2 ends = el_band_ends(g, P, edge_fold) * (side * edge_radius / world_per_px);
  return vec2(min(ends.x, ends.y), max(ends.x, ends.y));
}

/* The quad's sides across the edge line w0 -> w1 (clip positions c0, c1; pixels along `across`,
 * low and high, before the pixel's footprint is added: el_footprint_reach): where the band
 * really lies (mostly on one side of the line), the union of its extents at both ends, widened
 * by how far it can move as the view ray and the arc turn along the edge, within +-reach (the
 * band's widest). */
vec2 el_quad_sides(vec3 w0, vec3 w1, vec4 c0, vec4 c1, vec2 across, float reach)
{
  vec2 b0 = el_band_px(w0, 0.0, c0, across), b1 = el_band_px(w1, 1.0, c1, across);
  bool persp = frame.eye.w > 0.5;
  vec3 E = el_safe_normalize(edge_dir);
  vec3 V0 = el_safe_normalize(persp ? frame.eye.xyz - w0 : -frame.view_dir.xyz);
  vec3 V1 = el_safe_normalize(persp ? frame.eye.xyz - w1 : -frame.view_dir.xyz);
  /* The band turns with P = E x V / |E x V|: by about the ray's turn over |E x V|. */
  float turn = 2.0 * asin(min(0.5 * length(V1 - V0), 1.0));
  float s_min = max(min(length(cross(E, V0)), length(cross(E, V1))), 1e-3);
  /* Between the ends the arc turns with its faces' shading normals (el_edge_frame): the band
   * moves by about that turn, in radians, times its reach; a pixel may take the frame of a
   * point up to half an edge past either end (edge_band_pixel.glsl, along the line): twice. */
  float frame_turn = max(length(edge_turn1), length(edge_turn2));
  float margin = reach * min(4.0 * turn / s_min + 2.0 * frame_turn, 1.0) + 1.0 / 32.0;
  float lo = clamp(min(b0.x, b1.x) - margin, -reach, reach);
  return vec2(lo, clamp(max(b0.y, b1.y) + margin, lo, reach));
}
