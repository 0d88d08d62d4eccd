/* Colour of a rounded edge at world point X seen along unit V: ambient plus, per light, the
 * diffuse and specular arc means (highlight_arc.glsl) over the arc `g` (the part of it a pixel
 * sees: edge_band_pixel.glsl). */
vec3 el_edge_colour(ElArc g, vec3 X, vec3 V, vec3 edge)
{
  float n = spec_color.w;
  /* The world on the arc: its lobe's albedo at the arc's mean cosine to the eye. */
  float nv = el_arc_mean(g, V, edge, 1.0);
  vec3 col = frame.ambient.rgb * (base_color.rgb + tint.rgb * el_env_specular(spec_color.rgb, n, nv));
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    vec3 L, E;
    light_at(i, X, L, E);
    E *= el_light_shadow(i, X, L); /* the arc's own normal varies: it steps off towards the light */
    vec3 H = el_safe_normalize(L + V);
    float spec = el_arc_mean(g, H, edge, n);
    float diff = el_arc_mean(g, L, edge, 1.0);
    col += E * (base_color.rgb * (diff / 3.14159265) + tint.rgb * spec_color.rgb * blinn_norm(n) * spec);
  }
  return col;
}

/* Colour of a sharp face of unit normal N at world point X seen along unit V, as the surface pass
 * shades it (Blinn-Phong mode): what a band replaces of it (el_faces_under_band). */
vec3 el_face_colour(vec3 N, vec3 X, vec3 V)
{
  vec3 col = frame.ambient.rgb * (base_color.rgb + el_env_specular(spec_color.rgb, spec_color.w, dot(N, V)));
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    col += el_blinn_phong(i, X, N, V, base_color.rgb, spec_color.rgb, spec_color.w);
  }
  return col;
}
