/* The material's albedo, F0 and Blinn exponent on the band: its colours, or under an image
 * (EL_BASE_TEXTURE) its node program where the pixel's band lies along the edge
 * (el_band_material, set by the pass from edge_uv: material_program.glsl), as the surface pass
 * takes them. */
#ifdef EL_BASE_TEXTURE
ElMaterial el_band_material;
#endif

vec3 el_albedo()
{
#ifdef EL_BASE_TEXTURE
  return el_band_material.albedo;
#else
  return base_color.rgb;
#endif
}

vec3 el_f0()
{
#ifdef EL_BASE_TEXTURE
  return el_band_material.f0;
#else
  return spec_color.rgb;
#endif
}

float el_shininess()
{
#ifdef EL_BASE_TEXTURE
  return el_band_material.n;
#else
  return spec_color.w;
#endif
}

/* Colour of a rounded edge at world point X seen along unit V: ambient plus, per light, the
 * diffuse and specular arc means (highlight_arc.glsl) over the arc `g` (the part of it a pixel
 * sees: edge_band_pixel.glsl). */
vec3 el_edge_colour(ElArc g, vec3 X, vec3 V, vec3 edge)
{
  float n = el_shininess();
  /* The world on the arc: its lobe's albedo at the arc's mean cosine to the eye. */
  float nv = el_arc_mean(g, V, edge, 1.0);
#ifdef EL_ENVIRONMENT
  /* Under an image the world differs along the arc: its irradiance and prefiltered radiance
   * at 8 Gauss points of the visible part, weighted as the arc's means are, by projected
   * width N.V (docs/highlight_math.md, "The world's environment on the arc"). */
  vec3 env_diff = vec3(0.0), env_refl = vec3(0.0);
  float wsum = 0.0;
  float mid = 0.5 * (g.vis.lo + g.vis.hi), half_len = 0.5 * max(g.vis.hi - g.vis.lo, 0.0);
  for (int j = 0; j < 8; j++) {
    float t = mid + half_len * ((j & 1) == 0 ? el_gl_x[j >> 1] : -el_gl_x[j >> 1]);
    vec3 N = g.a1 * cos(t) + g.b1 * sin(t);
    /* A floor on N.V: a window shrunk to a point on the horizon still has its mean. */
    float w = el_gl_w[j >> 1] * max(dot(N, V), 1e-6);
    env_diff += w * el_world_diffuse(N);
    env_refl += w * el_world_specular(reflect(-V, N), n);
    wsum += w;
  }
  vec3 col = el_albedo() * (env_diff / wsum) + tint.rgb * (env_refl / wsum) * el_env_specular(el_f0(), n, nv);
#else
  vec3 col = frame.ambient.rgb * (el_albedo() + tint.rgb * el_env_specular(el_f0(), n, nv));
#endif
  col += material.emission.rgb; /* the fillet glows as its faces do */
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    vec3 L, E;
    light_at(i, X, L, E);
    E *= el_light_shadow(i, X, L); /* the arc's own normal varies: it steps off towards the light */
    vec3 H = el_safe_normalize(L + V);
    float spec = el_arc_mean(g, H, edge, n);
    float diff = el_arc_mean(g, L, edge, 1.0);
    col += E * (el_albedo() * (diff / 3.14159265) + tint.rgb * el_f0() * blinn_norm(n) * spec);
  }
  return col;
}

/* Colour of a sharp face of unit normal N at world point X seen along unit V, as the surface pass
 * shades it (Blinn-Phong mode): what a band replaces of it (el_faces_under_band). */
vec3 el_face_colour(vec3 N, vec3 X, vec3 V)
{
  vec3 col = material.emission.rgb + el_albedo() * el_world_diffuse(N) +
             el_world_specular(reflect(-V, N), el_shininess()) * el_env_specular(el_f0(), el_shininess(), dot(N, V));
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    col += el_blinn_phong(i, X, N, V, el_albedo(), el_f0(), el_shininess());
  }
  return col;
}
