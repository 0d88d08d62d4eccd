/* The outline's fringe (docs/highlight_math.md, "Band ends"): a fillet lies within its part's
 * outline, so over the background a band or a corner patch shows only in the pixels the part's
 * own outline partly covers: one of the 3x3 around pixel px shows this object in the surface
 * pass's ids. Needs the sampler surface_id and the push constant instance_id. */
bool el_outline_fringe(ivec2 px)
{
  ivec2 size = textureSize(surface_id, 0) - 1;
  bool fringe = false;
  for (int dy = -1; dy <= 1; dy++) {
    for (int dx = -1; dx <= 1; dx++) {
      vec2 n = texelFetch(surface_id, clamp(px + ivec2(dx, dy), ivec2(0), size), 0).rg;
      fringe = fringe || (n.x == instance_id && n.y > 0.0);
    }
  }
  return fringe;
}
