/* Where a band's line crosses a pixel (docs/highlight_math.md, "The faces under the band").
 * Needs the samplers surface_id and surface_depth and the push constant instance_id. */

/* Whether the pixel's samples see only the edge's two faces, as far as the first sample's ids
 * and depths around it tell: the 3x3 around pixel px shows this object, its view depth `depth`
 * continued over each neighbour by at most the steeper face's slope (`slope`, view depth per
 * unit across the image) plus half a footprint (`world_per_px`) -- no other part of the object
 * passes in front there. */
bool el_only_edge_faces(ivec2 px, float depth, float slope, float world_per_px)
{
  ivec2 size = textureSize(surface_id, 0) - 1;
  bool only = true;
  for (int dy = -1; dy <= 1; dy++) {
    for (int dx = -1; dx <= 1; dx++) {
      ivec2 q = clamp(px + ivec2(dx, dy), ivec2(0), size);
      vec2 n = texelFetch(surface_id, q, 0).rg;
      float inv = texelFetch(surface_depth, q, 0).r;
      float reach = (length(vec2(dx, dy)) * slope + 0.5) * world_per_px;
      only = only && n.x == instance_id && n.y > 0.0 && inv > 0.0 && abs(1.0 / inv - depth) <= reach;
    }
  }
  return only;
}
