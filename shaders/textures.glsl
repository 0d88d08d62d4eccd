/* An Image Texture drawn into Base Color (materials.BaseTexture; EL_BASE_TEXTURE): `base_tex`
 * is Blender's own GPU texture of the image, whose colour space it decodes as EEVEE's. Texels
 * are fetched and filtered here rather than by the sampler's state, which the gpu module does
 * not set alike on every version: Closest takes the texel under the UV (EL_TEX_CLOSEST), Linear
 * blends the four around it; EL_TEX_EXTEND is how the image continues past [0, 1]
 * (EL_EXTEND_*, shaders/surface_modes.json). No mipmaps: a minified image aliases, which the
 * jittered samples average. A UV of (0, 0) is the image's first pixel, bottom left. */
#ifdef EL_BASE_TEXTURE
#ifndef EL_TEX_ALPHA
#define EL_TEX_ALPHA EL_ALPHA_NONE
#endif
/* An Alpha Hashed surface's threshold at this pixel and sample: interleaved gradient noise over
 * the whole frame's pixels (a render region's too), moved each sample, so that the jittered
 * samples average the cut into the alpha's coverage. The first sample cuts at 1/2: its depth and
 * ids are what the bands and the ink are hidden by, for every sample, so a hashed pattern there
 * would stay in them as dots. */
#ifndef EL_SHADOW_CUT /* the shadow pass has no frame: it cuts at 1/2 */
float el_alpha_hash()
{
  if (frame.camera.z < 0.5) {
    return 0.5;
  }
  vec2 p = floor(gl_FragCoord.xy) + frame.frame_pixel.xy + 5.588238 * frame.camera.z;
  return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}
#endif

vec4 el_base_fetch(ivec2 p, ivec2 size)
{
  if (EL_TEX_EXTEND == EL_EXTEND_REPEAT) {
    p -= size * ivec2(floor(vec2(p) / vec2(size))); /* floor, not %: negative texels wrap too */
  }
  return texelFetch(base_tex, clamp(p, ivec2(0), size - 1), 0);
}

vec4 el_base_texel(vec2 uv)
{
  if (EL_TEX_EXTEND == EL_EXTEND_CLIP && (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))) {
    return vec4(0.0); /* Clip: transparent black outside the image */
  }
  ivec2 size = textureSize(base_tex, 0);
  vec2 p = uv * vec2(size);
#if EL_TEX_CLOSEST
  return el_base_fetch(ivec2(floor(p)), size);
#else
  p -= 0.5;
  ivec2 b = ivec2(floor(p));
  vec2 f = p - floor(p);
  vec4 lo = mix(el_base_fetch(b, size), el_base_fetch(b + ivec2(1, 0), size), f.x);
  vec4 hi = mix(el_base_fetch(b + ivec2(0, 1), size), el_base_fetch(b + ivec2(1, 1), size), f.x);
  return mix(lo, hi, f.y);
#endif
}
#endif
