/* Edge highlight pass: the rounded edge's shading integrated over the part of its arc this pixel
 * sees (highlight_arc.glsl), weighted by the pixel's coverage of the projected band, depth-tested
 * against the surface pass. Output is premultiplied (W Is, W). */
void main()
{
  vec2 pc = gl_FragCoord.xy;
  vec3 X = edge_point;
  bool persp = frame.eye.w > 0.5;
  vec3 to_eye = persp ? frame.eye.xyz - X : -frame.view_dir.xyz;
  float dist = persp ? el_safe_length(to_eye) : 1.0;
  vec3 V = el_safe_normalize(to_eye);

  /* Visibility first (cheap): the edge lies on its own surface, whose depth at pixels next to the
   * line differs by up to the lateral distance times the faces' depth slope. */
  float world_per_px = dist / frame.camera.x;
  float across = dot(pc - edge_screen.xy, edge_screen.zw);
  float c1 = abs(dot(normalize(edge_n1), V)), c2 = abs(dot(normalize(edge_n2), V));
  float cmin = max(min(c1, c2), 1.0 / 16.0);
  float slope = sqrt(max(1.0 - cmin * cmin, 0.0)) / cmin;
  float bias = (abs(across) + 1.0) * world_per_px * (slope + 0.05) + 1e-5 * dist;
  float inv_surface = texelFetch(surface_depth, ivec2(pc), 0).r;
  float edge_depth = -(frame.view * vec4(X, 1.0)).z;
  if (inv_surface > 0.0 && edge_depth > 1.0 / inv_surface + bias) {
    discard;
  }

  /* Short edges come shaded from the vertex shader; long ones are shaded here, per pixel. */
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
    discard;
  }

  /* Coverage of the pixel by the band of projected width w (pixels) around the edge line. */
  float w_px = edge_radius * width / world_per_px;
  float cover = clamp(min(across + 0.5, 0.5 * w_px) - max(across - 0.5, -0.5 * w_px), 0.0, 1.0);
  float W = clamp(tint.w * cover, 0.0, 1.0) * el_axial_ramp(s);
  if (!(W > 0.0)) {
    discard;
  }

  vec3 col = per_edge ? edge_color.rgb : el_edge_colour(g, X, V, edge_dir);
  out_color = vec4(col * W, W);
}
