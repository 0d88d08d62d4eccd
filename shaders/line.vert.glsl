/* Ink line pass: one screen-space quad per line segment (no wide GL lines, no geometry shader),
 * reaching one pixel past the segment's round-capped stroke on every side. corner.x picks the
 * end (0: p0, 1: p1), corner.y the side (-1, +1). Widths are pixels, or scene units with a pixel
 * floor (line_style.y = 1); taper.x/y is the distance from each end to the chain's nearest free
 * end as a fraction of the chain's length (large: no free end), and line_style.w the fraction
 * over which the stroke tapers to nothing. */
float el_line_half_width(float depth, float taper_t)
{
  float w = line_style.x;
  if (line_style.y > 0.5) {
    float px_per_unit = frame.eye.w > 0.5 ? frame.camera.x / max(depth, 1e-20) : frame.camera.x;
    w = max(w * px_per_unit, line_style.z);
  }
  float f = line_style.w > 0.0 ? clamp(taper_t / line_style.w, 0.0, 1.0) : 1.0;
  return 0.5 * w * f;
}

void main()
{
  vec3 w0 = (model * vec4(p0, 1.0)).xyz;
  vec3 w1 = (model * vec4(p1, 1.0)).xyz;
  vec4 v0 = frame.view * vec4(w0, 1.0);
  vec4 v1 = frame.view * vec4(w1, 1.0);
  vec4 c0 = frame.projection * v0;
  vec4 c1 = frame.projection * v1;
  float z0 = -v0.z, z1 = -v1.z;
  /* Clip the segment to the part in front of the eye (perspective w > 0). */
  const float eps = 1e-6;
  if (c0.w < eps && c1.w < eps) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  float t0 = 0.0, t1 = 1.0;
  if (c0.w < eps) {
    t0 = (eps - c0.w) / (c1.w - c0.w);
  }
  else if (c1.w < eps) {
    t1 = (eps - c0.w) / (c1.w - c0.w);
  }
  vec4 a = mix(c0, c1, t0), b = mix(c0, c1, t1);
  float za = mix(z0, z1, t0), zb = mix(z0, z1, t1);
  float taper_a = mix(taper.x, taper.y, t0), taper_b = mix(taper.x, taper.y, t1);

  vec2 sa = (a.xy / a.w * 0.5 + 0.5) * frame.viewport.xy;
  vec2 sb = (b.xy / b.w * 0.5 + 0.5) * frame.viewport.xy;
  float ra = el_line_half_width(za, taper_a), rb = el_line_half_width(zb, taper_b);
  line_ends = vec4(sa, sb);
  line_radius = vec2(ra, rb);
  line_depth = vec2(za, zb);
  line_world_a = mix(w0, w1, t0);
  line_world_b = mix(w0, w1, t1);
  line_faces = faces;
  line_n1 = el_transform_normal(model, n1);
  line_n2 = el_transform_normal(model, n2);

  vec2 along = sb - sa;
  float len = length(along);
  vec2 dir = len > 1e-6 ? along / len : vec2(1.0, 0.0);
  vec2 across = vec2(-dir.y, dir.x);
  float reach = max(ra, rb) + 1.0;
  vec2 s = (corner.x < 0.5 ? sa - dir * reach : sb + dir * reach) + across * corner.y * reach;
  gl_Position = vec4(s / frame.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
}
