/* Ink line pass: a round-capped stroke around the segment, box-filtered across its width, so
 * strokes that share an end overlap at the join with no gap at any angle. Visibility is decided
 * on the centre line (so the whole width of a stroke agrees) against the surface pass's ids and
 * depth.
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
  /* Visibility from the surface pass's ids (docs/lines.md, "Visibility"): visible where one of
   * the segment's own faces (line_faces, of this instance: line_vis.z) shows in the 3x3 pixels
   * around the centre point, or else where what shows is no nearer than the line within a tight
   * tolerance. For a line that can lie on an outline (line_vis.w: silhouettes, borders,
   * contours) what shows is the farthest of the 3x3 pixels, so the background or what lies
   * behind on its outer side keeps it; for any other line it is the centre pixel, so a crease
   * near an outline is still hidden by what covers it. Unlike a depth bias that follows the
   * faces' slope, the tolerance is half a pixel's footprint, so a wall thicker than that hides
   * what lies behind it at any angle. */
  ivec2 q = ivec2(floor(c));
  ivec2 size = textureSize(surface_depth, 0) - 1;
  float inv_far = 3.0e38;
  bool own = false;
  for (int dy = -1; dy <= 1; dy++) {
    for (int dx = -1; dx <= 1; dx++) {
      ivec2 at = clamp(q + ivec2(dx, dy), ivec2(0), size);
      inv_far = min(inv_far, texelFetch(surface_depth, at, 0).r);
      vec2 id = texelFetch(surface_id, at, 0).rg;
      own = own || (id.x == line_vis.z && id.y > 0.0 && (id.y == line_faces.x || id.y == line_faces.y));
    }
  }
  float inv_shown = line_vis.w > 0.5 ? inv_far : texelFetch(surface_depth, clamp(q, ivec2(0), size), 0).r;
  float world_per_px = (persp ? z : 1.0) / frame.camera.x;
  float bias = 0.5 * world_per_px + line_vis.y * abs(z);
  bool visible = own || inv_shown <= 0.0 || z <= 1.0 / inv_shown + bias;
  float alpha = cov * line_color.a * (visible ? 1.0 : line_vis.x);
  if (alpha <= 0.0) {
    discard;
  }
  out_color = vec4(line_color.rgb, alpha);
  gl_FragDepth = 1.0 - alpha;
}
