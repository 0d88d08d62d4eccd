/* Surface pass: Blinn-Phong from the material, ambient from the world, or toon shading
 * (toon.glsl), or unlit white (whiteout); writes colour and the inverse view-space depth the edge
 * and line passes test against. The mode is fixed when the program is built (EL_SURFACE_MODE,
 * one of the EL_SURFACE_MODE_* of shaders/surface_modes.json; passes/frame.py builds one per mode
 * in use), so the other modes' code is not in it. */
#ifndef EL_SURFACE_MODE
#define EL_SURFACE_MODE EL_SURFACE_MODE_PHONG
#endif
void main()
{
  /* The triangle's plane, from the pixel's footprint (before any discard: derivatives are
   * undefined after one), turned to face the eye: which side of it is seen is then geometry,
   * not gl_FrontFacing, whose sense under Blender's offscreen targets differs between drivers
   * (Mesa's softpipe reports every face of a cube the other way round from llvmpipe), nor the
   * sign of a derivative (GLSL leaves it to the implementation: Blender's DFDX_SIGN). */
  vec3 plane = cross(dFdx(world_pos), dFdy(world_pos));
  vec3 to_eye = frame.eye.w > 0.5 ? frame.eye.xyz - world_pos : -frame.view_dir.xyz;
  plane = dot(plane, to_eye) < 0.0 ? -plane : plane;
#ifdef EL_ROUNDED_OUTLINE
  /* The strips a rounded silhouette leaves out, and past a corner the ball's circle
   * (rounded_outline.glsl). */
  ivec2 tally = ivec2(0);
  vec4 ends = vec4(0.0);
  for (int k = 0; k < 4; k++) {
    float end_px;
    vec2 e0 = el_unpack_half2(outline_end0[k]), e1 = el_unpack_half2(outline_end1[k]);
    int part = el_strip_part(outline_strip0[k], outline_strip1[k], outline_along[k], outline_length[k], outline_dist[k],
                             vec2(e0.x, e1.x), vec2(e0.y, e1.y), end_px);
    el_tally_strip(part, end_px, tally, ends);
  }
#ifdef EL_OUTLINE_MORE
  /* Only the triangles that list more than four edges are drawn by this variant: on llvmpipe
   * the check's code costs every fragment of the program, taken or not. */
  el_tally_more_strips(int(surface_tri + 0.5), gl_FragCoord.xy, tally, ends);
#endif
  if (el_past_outline(tally)) {
    discard;
  }
  for (int q = 0; q < 4; q++) {
    vec4 z = q == 0 ? outline_corner0 : (q == 1 ? outline_corner1 : (q == 2 ? outline_corner2 : outline_corner3));
    if (outline_ball[q] > 0.0 && z.z > 0.0 && z.w > 0.0 && dot(z.xy, z.xy) > outline_ball[q] * outline_ball[q]) {
      discard;
    }
  }
#endif
#ifdef EL_BASE_TEXTURE
#if EL_TEX_ALPHA != EL_ALPHA_NONE
  /* The image's alpha into the material's Alpha: Alpha Clip cuts below the threshold, Alpha
   * Hashed (EEVEE Next's Dithered) against el_alpha_hash, which the samples average. */
  float coverage = el_base_texel(surface_uv).a;
  if (EL_TEX_ALPHA == EL_ALPHA_CLIP ? coverage < material.alpha_clip.x : coverage <= el_alpha_hash()) {
    discard;
  }
#endif
#endif
  out_depth = 1.0 / max(view_depth, 1e-30); /* 0 where nothing was drawn: infinitely far */
  /* Seen from its front: the side world_nor points to (outward, a mirrored object's too:
   * el_transform_normal) faces the eye. */
  bool front = dot(world_nor, plane) >= 0.0;
#ifdef EL_SURFACE_IDS
  /* Which instance and face covers the pixel, for the line pass's visibility (docs/lines.md):
   * surface_ids.y is the id of the batch's first triangle; 0 where nothing was drawn. The
   * triangle's number comes from its vertices (surface_tri), since a slot's triangles may be
   * drawn as two indexed subsets. */
  out_id = vec2(surface_ids.x, surface_ids.y + surface_tri);
#endif
#ifdef EL_NORMAL_PASS
  /* The Normal render pass: world space, facing the camera, as Cycles writes it. Only the
   * program variant built for a render that asks for the pass has this output. */
  out_normal = vec4(front ? normalize(world_nor) : -normalize(world_nor), 1.0);
#endif
  const int mode = EL_SURFACE_MODE;
  if (mode == EL_SURFACE_MODE_HOLDOUT) {
    out_color = vec4(0.0, 0.0, 0.0, -1.0); /* a hole: the composite leaves out the world too */
    return;
  }
  if (mode == EL_SURFACE_MODE_WHITEOUT) {
    out_color = vec4(1.0, 1.0, 1.0, base_color.a); /* a transparent material stays transparent */
    return;
  }
  vec3 N = normalize(world_nor);
  vec3 V = frame.eye.w > 0.5 ? normalize(frame.eye.xyz - world_pos) : -frame.view_dir.xyz;
  if (!front) {
    N = -N; /* back faces are shaded as seen (Blender shows both sides) */
  }
  if (mode == EL_SURFACE_MODE_RAMP || mode == EL_SURFACE_MODE_XTOON) {
    float x = el_toon_light(N, world_pos);
    vec3 toon_col = mode == EL_SURFACE_MODE_RAMP ? el_toon_ramp(x) : el_xtoon(x, view_depth, N, V);
    out_color = vec4(toon_col + material.emission.rgb, base_color.a); /* emission on top, as EEVEE adds it */
    return;
  }
  vec3 albedo = base_color.rgb;
  vec3 spec = spec_color.rgb;
  float n = spec_color.w;
#ifdef EL_BASE_TEXTURE
  /* An image in the material's node chains (materials.BaseTexture): its node program gives the
   * albedo, F0 and exponent here (material_program.glsl). */
  ElMaterial m = el_material_at(surface_uv, surface_col);
  albedo = m.albedo;
  spec = m.f0;
  n = m.n;
  if (m.normal_map.a >= 0.0) {
    N = el_normal_map(N, front, surface_tan, m.normal_map);
  }
#endif
  /* The world: its irradiance on the albedo, its prefiltered radiance around the reflection
   * times the lobe's directional albedo (the split sum; environment.glsl). */
  vec3 col = material.emission.rgb + albedo * el_world_diffuse(N) +
             el_world_specular(reflect(-V, N), n) * el_env_specular(spec, n, dot(N, V));
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    col += el_blinn_phong(i, world_pos, N, V, albedo, spec, n);
  }
  out_color = vec4(col, base_color.a);
}
