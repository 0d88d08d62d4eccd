/* The world's light (addon/extract/world_light.py): a uniform colour, frame.ambient, or with
 * EL_ENVIRONMENT an Environment Texture filtered into the `env_map` atlas
 * (addon/extract/environment_filter.py): equirectangular tiles of the radiance prefiltered by GGX
 * roughness (the split sum's first factor, docs/highlight_math.md) and of the irradiance E / pi.
 * Texels are fetched and blended here, not by a sampler's state: u wraps around the sphere,
 * v stops at the poles. Without EL_ENVIRONMENT every lookup is frame.ambient, as before. */
#ifdef EL_ENVIRONMENT
/* Blender's equirectangular mapping of the image's direction d: u = 1/2 - atan2(y, x) / 2pi,
 * v = 1/2 + asin(z) / pi (atan2 of the horizontal length: no asin past 1). atan(0, 0) is
 * undefined in GLSL, and a floor's normal points exactly at the pole: there every u is the
 * same texel row, so u = 1/2. */
vec2 el_env_uv(vec3 world_dir)
{
  vec3 d = mat3(frame.env_rotation) * world_dir;
  float r = length(d.xy);
  float az = r > 0.0 ? atan(d.y, d.x) : 0.0;
  float el = (r > 0.0 || d.z != 0.0) ? atan(d.z, r) : 0.0;
  return vec2(0.5 - az * (0.5 / 3.14159265), 0.5 + el * (1.0 / 3.14159265));
}

/* Bilinear radiance of tile r (x, y, w, h) at uv. Level 0's rows are the image's, at their
 * centres; a filtered tile's (`poles`) run from pole to pole, both included
 * (environment_filter.tile_directions). */
vec3 el_env_tile(vec4 r, vec2 uv, bool poles)
{
  ivec2 size = ivec2(r.zw + 0.5), o = ivec2(r.xy + 0.5);
  vec2 p = vec2(uv.x * r.z - 0.5, poles ? uv.y * (r.w - 1.0) : uv.y * r.w - 0.5);
  ivec2 b = ivec2(floor(p));
  vec2 f = p - floor(p);
  int x0 = b.x - size.x * int(floor(float(b.x) / float(size.x)));
  int x1 = x0 + 1 == size.x ? 0 : x0 + 1;
  int y0 = clamp(b.y, 0, size.y - 1), y1 = clamp(b.y + 1, 0, size.y - 1);
  vec3 lo = mix(texelFetch(env_map, o + ivec2(x0, y0), 0).rgb, texelFetch(env_map, o + ivec2(x1, y0), 0).rgb, f.x);
  vec3 hi = mix(texelFetch(env_map, o + ivec2(x0, y1), 0).rgb, texelFetch(env_map, o + ivec2(x1, y1), 0).rgb, f.x);
  return mix(lo, hi, f.y) * frame.env.y;
}
#endif

/* GGX roughness of the Blinn exponent n (materials.shininess_from_roughness inverted): the
 * level a lookup takes, and lighting.glsl's el_env_specular's lobe. */
float el_env_roughness(float n)
{
  return pow(2.0 / (max(n, 0.0) + 2.0), 0.25);
}

/* The world's radiance along a view ray that meets nothing: the background. */
vec3 el_world_background(vec3 dir)
{
#ifdef EL_ENVIRONMENT
  return el_env_tile(frame.env_level[0], el_env_uv(dir), false);
#else
  return frame.ambient.rgb;
#endif
}

/* What a Lambertian albedo of 1 with unit normal N gives back of the world: E(N) / pi. */
vec3 el_world_diffuse(vec3 N)
{
#ifdef EL_ENVIRONMENT
  return el_env_tile(frame.env_irradiance, el_env_uv(N), true);
#else
  return frame.ambient.rgb;
#endif
}

/* The world's radiance prefiltered by the lobe of Blinn exponent n around the reflected
 * direction R: blended between the two levels whose roughness brackets the lobe's. */
vec3 el_world_specular(vec3 R, float n)
{
#ifdef EL_ENVIRONMENT
  float last = frame.env.x - 1.0;
  float at = clamp(el_env_roughness(n), 0.0, 1.0) * last;
  int k = int(min(floor(at), last - 1.0));
  vec2 uv = el_env_uv(R);
  return mix(el_env_tile(frame.env_level[k], uv, k > 0), el_env_tile(frame.env_level[k + 1], uv, true), at - float(k));
#else
  return frame.ambient.rgb;
#endif
}
