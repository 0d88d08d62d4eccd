/* Toon shading (a shade ramp, or X-Toon). toon.x: the mode (surface.frag.glsl's
 * EL_SURFACE_MODE, for reference); toon.yz:
 * X-Toon near and far distances; toon.w: 1 if the ramp interpolates (else stepped) + 2 if
 * X-Toon's y is orientation N.V (else depth). */

/* The ramp's input: N.L of each light weighted by the irradiance it delivers here, over that of
 * the strongest light, clamped to [0, 1]. One light of any strength gives plain max(N.L, 0), so
 * a ramp's bands sit where an artist expects; more light only makes a point brighter. */
float el_toon_light(vec3 N, vec3 X)
{
  int count = int(frame.camera.y + 0.5);
  float sum = 0.0, strongest = 0.0;
  for (int i = 0; i < count; i++) {
    vec3 L, E;
    light_at(i, X, L, E);
    float e = dot(E, vec3(0.2126, 0.7152, 0.0722));
    /* A cast shadow lowers the ramp's input like turning away from the light: a cel shadow. */
    sum += e * max(dot(N, L), 0.0) * el_light_shadow(i, X, N);
    strongest = max(strongest, e);
  }
  return strongest > 0.0 ? clamp(sum / strongest, 0.0, 1.0) : 0.0;
}

/* The ramp is a 256 x 1 texture made from the material's stops: stepped ramps read the nearest
 * texel (so they give exactly their stop colours), smooth ones interpolate. */
vec3 el_toon_ramp(float x)
{
  int w = textureSize(toon_ramp, 0).x;
  float f = clamp(x, 0.0, 1.0) * float(w - 1);
  bool smooth_ramp = mod(toon.w, 2.0) > 0.5;
  if (!smooth_ramp) {
    return texelFetch(toon_ramp, ivec2(int(f + 0.5), 0), 0).rgb;
  }
  int i = min(int(f), w - 2);
  return mix(texelFetch(toon_ramp, ivec2(i, 0), 0).rgb, texelFetch(toon_ramp, ivec2(i + 1, 0), 0).rgb, f - float(i));
}

/* X-Toon: x from the lighting, y from depth between near and far (0 at near) or from the
 * orientation N.V (0 facing the eye, 1 at the outline). Bilinear between texel centres. */
vec3 el_xtoon(float x, float depth, vec3 N, vec3 V)
{
  float y = toon.w >= 2.0 ? 1.0 - clamp(dot(N, V), 0.0, 1.0)
                          : clamp((depth - toon.y) / max(toon.z - toon.y, 1e-6), 0.0, 1.0);
  vec2 size = vec2(textureSize(toon_map, 0));
  vec2 f = vec2(clamp(x, 0.0, 1.0), y) * (size - 1.0);
  ivec2 i = min(ivec2(f), ivec2(size) - 2);
  i = max(i, ivec2(0));
  vec2 w = f - vec2(i);
  vec3 a = mix(texelFetch(toon_map, i, 0).rgb, texelFetch(toon_map, i + ivec2(1, 0), 0).rgb, w.x);
  vec3 b = mix(texelFetch(toon_map, i + ivec2(0, 1), 0).rgb, texelFetch(toon_map, i + ivec2(1, 1), 0).rgb, w.x);
  return mix(a, b, w.y);
}
