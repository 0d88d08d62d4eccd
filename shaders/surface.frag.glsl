/* Surface pass: Blinn-Phong from the material, ambient from the world; writes colour and the
 * inverse view-space depth the edge passes test against. */
void main()
{
  vec3 N = normalize(world_nor);
  vec3 V = frame.eye.w > 0.5 ? normalize(frame.eye.xyz - world_pos) : -frame.view_dir.xyz;
  if (!gl_FrontFacing) {
    N = -N; /* back faces are shaded as seen (Blender shows both sides) */
  }
  vec3 albedo = base_color.rgb;
  vec3 spec = spec_color.rgb;
  float n = spec_color.w;
  vec3 col = frame.ambient.rgb * albedo;
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    vec3 L, E;
    light_at(i, world_pos, L, E);
    float nl = dot(N, L);
    if (nl <= 0.0) {
      continue;
    }
    vec3 H = normalize(L + V);
    col += E * (albedo * (nl / 3.14159265) + spec * blinn_norm(n) * pow(max(dot(N, H), 0.0), n));
  }
  out_color = vec4(col, base_color.a);
  out_depth = 1.0 / max(view_depth, 1e-30); /* 0 where nothing was drawn: infinitely far */
}
