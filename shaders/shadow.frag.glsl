/* Shadow pass: the depth the vertex stage gave; the depth test keeps the nearest surface. An
 * alpha-cut surface (EL_SHADOW_CUT) casts only where the surface pass draws it: Alpha Clip
 * below its threshold, Alpha Hashed as the first sample cuts it, at 1/2 (the maps are drawn once
 * a frame, not per sample). */
void main()
{
#ifdef EL_SHADOW_CUT
  float coverage = el_base_texel(shadow_uv).a;
  if (EL_TEX_ALPHA == EL_ALPHA_CLIP ? coverage < material.alpha_clip.x : coverage <= 0.5) {
    discard;
  }
#endif
  out_depth = light_depth;
}
