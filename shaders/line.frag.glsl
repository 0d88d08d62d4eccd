/* Ink line pass: a round-capped stroke around the segment, box-filtered across its width, so
 * strokes that share an end overlap at the join with no gap at any angle. Visibility is decided
 * on the centre line (so the whole width of a stroke agrees) against the surface pass's depth.
 * The output depth is 1 - alpha: with a LESS depth test each pixel keeps its most opaque stroke
 * instead of stacking the overlapping caps of a chain, which would darken its joins. */

/* Fraction of the pixel [-0.5, 0.5] covered by the band [d - r, d + r]. */
float el_band_coverage(float d, float r)
{
  return max(min(d + r, 0.5) - max(d - r, -0.5), 0.0);
}

void main()
{
  vec2 p = gl_FragCoord.xy;
  vec2 a = line_ends.xy, b = line_ends.zw;
  vec2 ab = b - a;
  float l2 = dot(ab, ab);
  float t = l2 > 1e-12 ? clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  vec2 c = a + t * ab;
  float r = mix(line_radius.x, line_radius.y, t);
  float cov = min(el_band_coverage(length(p - c), r), 1.0);
  if (cov <= 0.0) {
    discard;
  }

  /* View depth of the centre point (1/z is affine in screen space under perspective). */
  bool persp = frame.eye.w > 0.5;
  float z = persp ? 1.0 / mix(1.0 / line_depth.x, 1.0 / line_depth.y, t) : mix(line_depth.x, line_depth.y, t);
  /* The farthest surface in the 3x3 pixels around the centre point: a line on an outline sees
   * the background (or what lies behind) on its outer side and stays visible. */
  ivec2 q = ivec2(floor(c));
  ivec2 size = textureSize(surface_depth, 0) - 1;
  float inv_far = 3.0e38;
  for (int dy = -1; dy <= 1; dy++) {
    for (int dx = -1; dx <= 1; dx++) {
      inv_far = min(inv_far, texelFetch(surface_depth, clamp(q + ivec2(dx, dy), ivec2(0), size), 0).r);
    }
  }
  /* View-space bias: the faces next to the edge differ in depth from its centre line by up to
   * 1.5 pixels times their depth slope; plus a relative part against rounding. */
  float dz = line_depth.y - line_depth.x;
  float u = abs(dz) > 1e-6 * abs(z) ? clamp((z - line_depth.x) / dz, 0.0, 1.0) : t;
  vec3 X = mix(line_world_a, line_world_b, u);
  float world_per_px = (persp ? z : 1.0) / frame.camera.x;
  vec3 V = persp ? normalize(frame.eye.xyz - X) : -frame.view_dir.xyz;
  float c1 = abs(dot(normalize(line_n1), V)), c2 = abs(dot(normalize(line_n2), V));
  float cmin = max(min(c1, c2), 1.0 / 16.0);
  float slope = sqrt(max(1.0 - cmin * cmin, 0.0)) / cmin;
  float bias = 1.5 * world_per_px * (slope + 0.05) + line_vis.y * abs(z);
  bool visible = inv_far <= 0.0 || z <= 1.0 / inv_far + bias;
  float alpha = cov * line_color.a * (visible ? 1.0 : line_vis.x);
  if (alpha <= 0.0) {
    discard;
  }
  out_color = vec4(line_color.rgb, alpha);
  gl_FragDepth = 1.0 - alpha;
}
