/* Light i seen from world point X: unit direction towards the light and the irradiance it
 * delivers on a surface facing it. Units follow Cycles: sun strength is irradiance (W/m^2), a
 * point or spot light of power P has intensity P / (4 pi), an area light of power P is a
 * one-sided Lambertian emitter, intensity P / pi * cos(emission angle). */
void light_at(int i, vec3 X, out vec3 L, out vec3 E)
{
  vec4 c = frame.light_color[i];
  int type = int(c.w + 0.5); /* EL_LIGHT_*: shaders/frame_data.json */
  if (type == EL_LIGHT_SUN) {
    L = -frame.light_direction[i].xyz;
    E = c.rgb;
    return;
  }
  vec3 d = frame.light_position[i].xyz - X;
  float r2 = max(dot(d, d), 1e-12);
  L = d * inversesqrt(r2);
  float along = dot(-L, frame.light_direction[i].xyz);
  if (type == EL_LIGHT_AREA) {
    E = c.rgb * max(along, 0.0) / (3.14159265 * r2);
    return;
  }
  E = c.rgb / (4.0 * 3.14159265 * r2);
  if (type == EL_LIGHT_SPOT) {
    float cos_edge = frame.light_direction[i].w;
    float blend = frame.light_spot[i].x;
    E *= smoothstep(cos_edge, mix(cos_edge, 1.0, max(blend, 1e-4)), along);
  }
}

#ifndef EL_SHADOW_LOOKUP
/* No shadows in this stage (shadows.glsl is listed before this file where they are looked up):
 * every light reaches everything. */
float el_light_shadow(int i, vec3 X, vec3 N)
{
  return 1.0;
}
#endif

/* Normalised Blinn-Phong lobe: (n + 8) / (8 pi) keeps the reflected energy steady as n grows. */
float blinn_norm(float n)
{
  return (n + 8.0) / (8.0 * 3.14159265);
}

/* What light i adds at world point X with unit normal N seen along unit V: Lambert diffuse of
 * `albedo` plus the normalised Blinn-Phong lobe of `spec` and exponent n, nothing where the light
 * is behind the surface or in the shadow of something between (el_light_shadow). The surface
 * pass and the corner patches shade with it alike. */
vec3 el_blinn_phong(int i, vec3 X, vec3 N, vec3 V, vec3 albedo, vec3 spec, float n)
{
  vec3 L, E;
  light_at(i, X, L, E);
  float nl = dot(N, L);
  if (nl <= 0.0) {
    return vec3(0.0);
  }
  E *= el_light_shadow(i, X, N);
  vec3 H = normalize(L + V);
  return E * (albedo * (nl / 3.14159265) + spec * blinn_norm(n) * pow(max(dot(N, H), 0.0), n));
}

/* What a uniform world of radiance 1 puts into the specular lobe of reflectance F0 `spec` and
 * Blinn exponent n seen at cos(angle to the normal) nv: the split sum (docs/highlight_math.md,
 * "The world's light on the specular lobe"). A uniform world's prefiltered radiance is itself at
 * every roughness, so only the lobe's directional albedo F0 A + B is left: Karis' fit of GGX's
 * (A, B) at the roughness whose GGX matches n (n = 2 / alpha^2 - 2, roughness = sqrt(alpha)),
 * times Fdez-Aguera's multiple-scattering gain, which keeps a rough metal's energy. */
vec3 el_env_specular(vec3 spec, float n, float nv)
{
  float rough = el_env_roughness(n); /* environment.glsl, listed before this file */
  vec4 r = rough * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
  float a004 = min(r.x * r.x, exp2(-9.28 * clamp(nv, 0.0, 1.0))) * r.x + r.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
  float e = max(ab.x + ab.y, 1e-4);
  /* Karis' B dips below zero at high roughness: no lobe reflects less than nothing. */
  return max((spec * ab.x + ab.y) * (1.0 + spec * (1.0 / e - 1.0)), vec3(0.0));
}

/* How an edge's radius in the object's units scales into world units under m (the Bevel
 * modifier's Amount is in object space too). The fillet's cross-section, square to the edge e,
 * meets each face along n x e (object space normals), which m stretches by |m (n x e)|; the band
 * is a circle, so it takes the mean of its two faces' stretches: under a non-uniform scale a
 * box's edges along the long axis keep their radius, as the modifier's do. Under a uniform scale
 * s it is s. viewport.py culls with the same measure. */
float el_radius_scale(mat4 m, vec3 na, vec3 nb, vec3 e)
{
  mat3 l = mat3(m);
  vec3 u = e / max(length(e), 1e-30);
  vec3 da = cross(na, u), db = cross(nb, u);
  float la = length(da), lb = length(db);
  if (!(la > 1e-6) || !(lb > 1e-6)) {
    return length(l * normalize(vec3(1.0))); /* no direction across the edge: the diagonal's */
  }
  return 0.5 * (length(l * da) / la + length(l * db) / lb);
}

/* A corner patch's ball, where three fillets of faces m1, m2, m3 meet: the mean of its three
 * edges' scales (el_radius_scale), so that it meets their bands. */
float el_ball_scale(mat4 m, vec3 m1, vec3 m2, vec3 m3)
{
  return (el_radius_scale(m, m1, m2, cross(m1, m2)) + el_radius_scale(m, m2, m3, cross(m2, m3)) +
          el_radius_scale(m, m3, m1, cross(m3, m1))) /
         3.0;
}

/* The cofactor matrix of m's linear part, signed by its determinant: a normal transformed by it
 * points as el_transform_normal's, not unit (for many normals under one transform). */
mat3 el_normal_matrix(mat4 m)
{
  vec3 c0 = m[0].xyz, c1 = m[1].xyz, c2 = m[2].xyz;
  return mat3(cross(c1, c2), cross(c2, c0), cross(c0, c1)) * (dot(c0, cross(c1, c2)) < 0.0 ? -1.0 : 1.0);
}

/* Normals transform by the inverse transpose of the linear part; the cofactor matrix is that
 * times det, so three cross products and det's sign give the direction without an inverse.
 * A singular transform (an object scaled to zero along an axis) still gives a finite normal:
 * the flattened surface's own normal where the cofactor has one, else +Z. */
vec3 el_transform_normal(mat4 m, vec3 n)
{
  vec3 c0 = m[0].xyz, c1 = m[1].xyz, c2 = m[2].xyz;
  mat3 cof = mat3(cross(c1, c2), cross(c2, c0), cross(c0, c1));
  vec3 r = cof * n;
  float len2 = dot(r, r);
  if (!(len2 > 1e-30)) {
    return vec3(0.0, 0.0, 1.0);
  }
  return r * (inversesqrt(len2) * (dot(c0, cross(c1, c2)) < 0.0 ? -1.0 : 1.0));
}

/* A side's normal halfway along an edge and its turn from its normal a at the first end to b at
 * the second, unit a and b (edge_data.mean_and_turn): normalize(mean + (t - 1/2) turn) is their
 * normalized blend at t. Where a == b, a itself and no turn, exactly. */
void el_mean_and_turn(vec3 a, vec3 b, out vec3 mean, out vec3 turn)
{
  if (a == b) {
    mean = a;
    turn = vec3(0.0);
    return;
  }
  vec3 m = 0.5 * (a + b);
  float len = max(length(m), 1e-30);
  mean = m / len;
  turn = (b - a) / len;
}
