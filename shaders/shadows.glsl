/* Cast shadows (docs/shadows.md): how much of light i reaches world point X, from the light's
 * shadow maps (passes/shadow_pass.py draws them once per frame, from the light's centre). The
 * layers are square tiles of one atlas, `shadow_maps`, frame.shadow_map.w of them per row; each
 * holds, per texel, the depth of the nearest surface the layer's matrix (frame.shadow_matrix)
 * sees: clip z for an orthographic layer (a sun's cascade), clip w, the
 * distance along the layer's axis, for a perspective one (a spot, a cube face). Listed before
 * lighting.glsl in the fragment stage of the programs that shade; without EL_SHADOWS every light
 * reaches everything, as before. */
#define EL_SHADOW_LOOKUP

#ifdef EL_SHADOWS
/* How far past the normal offset a lookup steps off along N: a corner patch's ball lies inside
 * the sharp solid the maps were drawn from, up to its radius below the surface, so its pass sets
 * this to the radius (edge_corner.frag.glsl); the surface's points lie on the maps' surfaces. */
float el_shadow_lift = 0.0;

/* A layer's matrix is orthographic when its clip w does not depend on the point. */
bool el_shadow_ortho(mat4 m)
{
  return m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0;
}

/* Which layer of light i's maps covers X: a cube face by the axis X lies furthest along from
 * the light, a sun's cascade by X's depth from the camera; -1: none does. */
int el_shadow_layer(int i, vec3 X, vec4 s)
{
  int layer = int(s.x + 0.5);
  int kind = int(s.y + 0.5);
  if (kind == EL_SHADOW_CUBE) {
    vec3 d = X - frame.light_position[i].xyz;
    vec3 a = abs(d);
    int face = (a.x >= a.y && a.x >= a.z) ? (d.x >= 0.0 ? 0 : 1) : (a.y >= a.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5));
    return layer + face;
  }
  if (kind == EL_SHADOW_CASCADES) {
    float depth = dot(X - frame.eye.xyz, frame.view_dir.xyz);
    int n = int(s.z + 0.5);
    for (int c = 0; c < n; c++) {
      if (depth <= frame.shadow_split[i][c]) {
        return layer + c;
      }
    }
    return -1; /* past the last cascade: no shadow is drawn that far */
  }
  return layer;
}

/* The stored depth at texel p of `layer` (p clamped to the layer's tile). */
float el_shadow_depth(ivec2 p, int layer)
{
  int size = int(frame.shadow_map.x + 0.5);
  int per_row = int(frame.shadow_map.w + 0.5);
  ivec2 tile = ivec2(layer % per_row, layer / per_row) * size;
  return texelFetch(shadow_maps, tile + clamp(p, ivec2(0), ivec2(size - 1)), 0).r;
}

/* 1 where the stored depth at texel p of `layer` is not in front of v. */
float el_shadow_texel(ivec2 p, int layer, float v)
{
  return el_shadow_depth(p, layer) >= v ? 1.0 : 0.0;
}

/* The four texels around map position p (in texels), each compared, blended bilinearly: a hard
 * shadow's edge spread over one texel, as a comparison sampler's linear filter would. */
float el_shadow_bilinear(vec2 p, int layer, float v)
{
  p -= 0.5;
  ivec2 b = ivec2(floor(p));
  vec2 f = p - floor(p);
  float a = mix(el_shadow_texel(b, layer, v), el_shadow_texel(b + ivec2(1, 0), layer, v), f.x);
  float c = mix(el_shadow_texel(b + ivec2(0, 1), layer, v), el_shadow_texel(b + ivec2(1, 1), layer, v), f.x);
  return mix(a, c, f.y);
}

/* Point k of n on a Vogel (sunflower) disk of radius 1, turned by `turn` radians. */
vec2 el_vogel(int k, int n, float turn)
{
  float r = sqrt((float(k) + 0.5) / float(n));
  float a = float(k) * 2.39996323 + turn;
  return r * vec2(cos(a), sin(a));
}

#define EL_SHADOW_TAPS 16
#define EL_BLOCKER_TAPS 8

float el_light_shadow(int i, vec3 X, vec3 N)
{
  vec4 s = frame.light_shadow[i];
  if (int(s.y + 0.5) == EL_SHADOW_NONE) {
    return 1.0;
  }
  int layer = el_shadow_layer(i, X, s);
  if (layer < 0) {
    return 1.0;
  }
  mat4 m = frame.shadow_matrix[layer];
  bool ortho = el_shadow_ortho(m);
  float size = frame.shadow_map.x;
  /* A texel's width in world units at X (clip w is 1 for an orthographic layer). */
  float w = (m * vec4(X, 1.0)).w;
  float texel = 2.0 * w / (size * max(length(vec3(m[0][0], m[1][0], m[2][0])), 1e-30));
  /* Normal offset: the lookup moves off the surface by two texels, so that a surface does not
   * shadow itself where the map samples it coarsely (acne), with a texel's slack on the depth. */
  vec3 Xo = X + N * (2.0 * texel + el_shadow_lift);
  /* The layer of the point looked up: the offset may cross a cube face's or a cascade's border. */
  int moved = el_shadow_layer(i, Xo, s);
  if (moved < 0) {
    return 1.0;
  }
  if (moved != layer) {
    layer = moved;
    m = frame.shadow_matrix[layer];
  }
  vec4 clip = m * vec4(Xo, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || clip.w <= 0.0) {
    return 1.0; /* outside what the layer sees: nothing there casts */
  }
  /* Depths in the layer's units: world units along its axis, or clip z (scale `unit`). */
  float unit = ortho ? length(vec3(m[0][2], m[1][2], m[2][2])) : 1.0;
  float v = (ortho ? clip.z : clip.w) - texel * unit;
  vec2 p = uv * size;
  float radius = s.w; /* the light's radius, or tan of a sun's angular radius */
  if (frame.shadow_map.y < 0.5 || radius <= 0.0) {
    return el_shadow_bilinear(p, layer, v);
  }
  /* Soft (PCSS, docs/shadows.md): the mean depth of the blockers near X's texel gives the
   * penumbra's width there, for a light of that size; the comparisons are then averaged over a
   * disk that wide, turned per pixel and per sample so that the samples fill it in. */
  vec2 pixel = floor(gl_FragCoord.xy) + frame.frame_pixel.xy; /* the whole frame's, in a region too */
  float turn = 6.28318531 * fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715)))) +
               frame.shadow_map.z * 2.39996323;
  /* Blockers are searched within the light's radius of X (a sun: the width its disk spans over a
   * quarter of the cascade's depth range, 2 / unit), at most 32 texels. */
  float reach = ortho ? radius * 0.5 / unit : radius;
  float search = clamp(reach / texel, 1.0, 32.0);
  float blocker = 0.0, found = 0.0;
  for (int k = 0; k < EL_BLOCKER_TAPS; k++) {
    float d = el_shadow_depth(ivec2(floor(p + search * el_vogel(k, EL_BLOCKER_TAPS, turn))), layer);
    if (d < v) {
      blocker += d;
      found += 1.0;
    }
  }
  if (found == 0.0) {
    return el_shadow_bilinear(p, layer, v); /* no blocker in reach: at most a hard edge's texel */
  }
  blocker /= found;
  float receiver = ortho ? clip.z : clip.w;
  /* The penumbra's half width at X in world units: a sphere or disk of radius R at the
   * blocker's distance b casts R (z - b) / b at the receiver's z; a sun of angular radius a casts
   * (z - b) tan a. */
  float gap = max(receiver - blocker, 0.0) / unit;
  float penumbra = ortho ? gap * radius : radius * gap / max(blocker, 1e-6);
  /* At least a texel and a half: a map's texels would otherwise show as steps along the edge. */
  float filter_px = clamp(penumbra / texel, 1.5, 32.0);
  /* One texel per tap: the taps turn per pixel and per sample, so the samples blend them. */
  float lit = 0.0;
  for (int k = 0; k < EL_SHADOW_TAPS; k++) {
    lit += el_shadow_texel(ivec2(floor(p + filter_px * el_vogel(k, EL_SHADOW_TAPS, turn + 1.0))), layer, v);
  }
  return lit / float(EL_SHADOW_TAPS);
}
#else
float el_light_shadow(int i, vec3 X, vec3 N)
{
  return 1.0;
}
#endif
