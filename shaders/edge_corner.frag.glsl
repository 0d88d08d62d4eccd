/* Corner patch pass (docs/highlight_math.md, "Corner patches"): the pixel's view rays meet the
 * ball that rounds the corner; where the front hit's normal lies between the three faces'
 * normals, that point is the filleted corner's surface (the ball lies inside the filleted solid,
 * which is convex there, so its front point is the solid's), shaded as the surface pass shades a
 * point and tinted as the bands are. Four sub-samples a pixel give the patch's coverage c. The
 * patch replaces what the bands put under it over that fraction, at the material's weight K: two
 * draws, the first (EL_CORNER_COVER) scaling the target by 1 - c (MULTIPLY blending), the second
 * adding the premultiplied (K c Is, K c). Blending it over the bands instead left them showing
 * through by 1 - K: a bright disc at K < 1. */

/* Colour of the surface at world point X with unit normal N seen along unit V: the surface
 * pass's Blinn-Phong (lighting.glsl), the specular tinted as the bands' (edge_shading.glsl). */
vec3 el_corner_colour(vec3 X, vec3 N, vec3 V)
{
  vec3 albedo = base_color.rgb, f0 = spec_color.rgb;
  float n = spec_color.w;
#ifdef EL_BASE_TEXTURE
  /* Under an image, its node program at the corner's vertex (material_program.glsl). */
  ElMaterial m = el_material_at(corner_uv, corner_col);
  albedo = m.albedo;
  f0 = m.f0;
  n = m.n;
#endif
  vec3 col = material.emission.rgb + albedo * el_world_diffuse(N) +
             tint.rgb * el_world_specular(reflect(-V, N), n) * el_env_specular(f0, n, dot(N, V));
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    col += el_blinn_phong(i, X, N, V, albedo, tint.rgb * f0, n);
  }
  return col;
}

/* Ray from Q along unit D against the ball: the surface's unit normal where the patch could be,
 * or zero for a miss. Convex: the front hit, the normal pointing out of the ball. Concave: the
 * patch is the ball's far side, seen from the air inside it, the normal pointing back to the
 * centre. */
vec3 el_ball_normal(vec3 Q, vec3 D, out vec3 hit)
{
  vec3 m = Q - corner_centre;
  float b = dot(m, D);
  float disc = b * b - (dot(m, m) - corner_radius * corner_radius);
  hit = Q;
  if (!(disc >= 0.0)) {
    return vec3(0.0);
  }
  hit = Q + (-b - corner_fold * sqrt(disc)) * D;
  return corner_fold * (hit - corner_centre) / corner_radius;
}

/* Whether unit normal N lies in the spherical triangle of the three faces' normals. */
bool el_in_corner(vec3 N)
{
  float s = dot(corner_n1, cross(corner_n2, corner_n3)) < 0.0 ? -1.0 : 1.0;
  return s * dot(N, cross(corner_n1, corner_n2)) >= 0.0 && s * dot(N, cross(corner_n2, corner_n3)) >= 0.0 &&
         s * dot(N, cross(corner_n3, corner_n1)) >= 0.0;
}

void main()
{
  vec2 pc = gl_FragCoord.xy;
  bool persp = frame.eye.w > 0.5;
  vec3 Q = corner_point;
  /* The pixel's footprint on the plane through the centre, taken before any fragment of the
   * quad may be discarded (derivatives are undefined after a non-uniform discard). */
  vec3 step_x = dFdx(Q), step_y = dFdy(Q);
  vec3 D = persp ? normalize(Q - frame.eye.xyz) : frame.view_dir.xyz;
  float dist = persp ? length(corner_centre - frame.eye.xyz) : 1.0;
  float world_per_px = dist / frame.camera.x;

  /* Visibility, as the bands': over one of the corner's own faces it shows; over the
   * background only in the outline's own pixels; elsewhere no surface may lie nearer than the
   * sharp corner's along this ray (its faces' planes through the vertex: the ray enters a convex
   * corner where it crosses the last of the planes it enters by, a concave one where it crosses
   * the first) less half a pixel's footprint. */
  vec2 id = texelFetch(surface_id, ivec2(pc), 0).rg;
  bool own = id.x == instance_id && id.y > 0.0 &&
             (any(equal(vec3(id.y), corner_faces_a)) || any(equal(vec3(id.y), corner_faces_b)));
  if (!(id.y > 0.0)) {
    if (!el_outline_fringe(ivec2(pc))) {
      discard;
    }
  }
  else if (!own) {
    float t = -3.0e38 * corner_fold;
    vec3 ns[3] = vec3[3](corner_n1, corner_n2, corner_n3);
    for (int k = 0; k < 3; k++) {
      float dn = dot(D, ns[k]);
      if (dn < 0.0) {
        float tk = dot(corner_vertex - Q, ns[k]) / dn;
        t = corner_fold > 0.0 ? max(t, tk) : min(t, tk);
      }
    }
    float inv_surface = texelFetch(surface_depth, ivec2(pc), 0).r;
    float corner_depth = -(frame.view * vec4(Q + clamp(t, -1.0e30, 1.0e30) * D, 1.0)).z;
    if (inv_surface > 0.0 && corner_depth > 1.0 / inv_surface + 0.5 * world_per_px + 1e-5 * dist) {
      discard;
    }
  }

  /* Four sub-samples on a rotated grid over the pixel's footprint on the plane through the
   * centre. */
  const vec2 offs[4] = vec2[4](vec2(-0.125, -0.375), vec2(0.375, -0.125), vec2(0.125, 0.375), vec2(-0.375, 0.125));
  vec3 sum = vec3(0.0);
  float covered = 0.0;
#ifdef EL_SHADOWS
  el_shadow_lift = corner_radius; /* the ball lies inside the sharp corner the maps hold */
#endif
  for (int k = 0; k < 4; k++) {
    vec3 q = Q + offs[k].x * step_x + offs[k].y * step_y;
    vec3 d = persp ? normalize(q - frame.eye.xyz) : D;
    vec3 hit;
    vec3 N = el_ball_normal(q, d, hit);
    if (dot(N, N) > 0.5 && el_in_corner(N)) {
      sum += el_corner_colour(hit, N, -d);
      covered += 0.25;
    }
  }
  if (!(covered > 0.0)) {
    discard;
  }
#ifdef EL_CORNER_COVER
  out_color = vec4(1.0 - covered);
#else
  float W = clamp(tint.w, 0.0, 1.0) * covered;
  out_color = vec4(sum / (4.0 * covered) * W, W);
#endif
}
