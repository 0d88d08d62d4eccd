/* I = W Is + (1 - W) I_origin, with the highlight buffer premultiplied (W Is, W) (a band at
 * the outline: a change of colour, alpha 0, edge_band_pixel.glsl); ink lines (straight alpha)
 * over that; then the world colour behind whatever is not opaque
 * (background.w = 0 for a transparent film), except where a holdout shows (surface alpha -1,
 * surface.frag.glsl): a hole, transparent on any film, as Cycles and EEVEE cut it. Samples add
 * up in the result with additive blending, each scaled by weight = 1 / samples. */
void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 surf = texelFetch(surface_color, p, 0);
  float world = surf.a < 0.0 ? 0.0 : background.w;
  surf = max(surf, vec4(0.0));
  vec4 hl = texelFetch(highlight_color, p, 0);
#ifdef EL_NO_INK
  vec4 ln = vec4(0.0); /* the ink is a render pass of its own (Lines as Render Pass) */
#else
  vec4 ln = texelFetch(line_color, p, 0);
#endif
  vec3 rgb = hl.rgb + (1.0 - hl.a) * surf.rgb;
  float a = hl.a + (1.0 - hl.a) * surf.a;
  rgb = ln.a * ln.rgb + (1.0 - ln.a) * rgb;
  a = ln.a + (1.0 - ln.a) * a;
  vec3 behind = background.rgb;
#ifdef EL_ENVIRONMENT
  /* The Environment Texture along the pixel's ray: between its points on the near and far
   * planes, so orthographic views read it too. */
  vec2 ndc = gl_FragCoord.xy * frame.viewport.zw * 2.0 - 1.0;
  vec4 near = frame.clip_to_world * vec4(ndc, -1.0, 1.0), far = frame.clip_to_world * vec4(ndc, 1.0, 1.0);
  behind = el_world_background(normalize(far.xyz / far.w - near.xyz / near.w));
#endif
  out_color = vec4(rgb + (1.0 - a) * world * behind, mix(a, 1.0, world)) * weight;
#ifdef EL_SURFACE_PASS
  out_surface = surf * weight; /* the Surface render pass: the sample mean of the surface alone */
#endif
}
