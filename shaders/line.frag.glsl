/* Ink line pass: a round-capped stroke around the node (a segment, or a chord standing for up to
 * 8 segments: line.vert.glsl), box-filtered across its width, so strokes that share an end
 * overlap at the join with no gap at any angle. Visibility is decided on the centre line (so the
 * whole width of a stroke agrees) against the surface pass's ids and depth; a node's own faces
 * (line_faces0..3, 0 = none) are those of every segment it stands for.
 * The output depth is 1 - alpha: with a LESS depth test each pixel keeps its most opaque stroke
 * instead of stacking the overlapping caps of a chain, which would darken its joins. */

/* Fraction of the pixel [-0.5, 0.5] covered by the band [d - r, d + r]. */
float el_band_coverage(float d, float r)
{
  return max(min(d + r, 0.5) - max(d - r, -0.5), 0.0);
}

/* Whether id (instance, face) is one of the node's own faces, of this instance. */
bool el_own_face(vec2 id)
{
  vec4 y = vec4(id.y);
  return id.x == line_vis.z && id.y > 0.0 &&
         (any(equal(y, line_faces0)) || any(equal(y, line_faces1)) || any(equal(y, line_faces2)) ||
          any(equal(y, line_faces3)));
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
  /* The camera's clip range cuts the line where it cuts the surface (the quad's own depth is not
   * the line's: line.vert.glsl draws it at 0). */
  vec4 clip_c = frame.projection * vec4(0.0, 0.0, -z, 1.0);
  if (abs(clip_c.z) > clip_c.w) {
    discard;
  }
  /* Visibility from the surface pass's ids (docs/lines.md, "Visibility"): visible where one of
   * the node's own faces (line_faces0..3, of this instance: line_vis.z) shows in the 3x3 pixels
   * around the centre point, or else where what shows is no nearer than the line within half a
   * pixel's footprint. What shows is the centre pixel's surface; for a line that can lie on an
   * outline (line_vis.w: silhouettes, borders, contours) it is the farthest of the 3x3 pixels
   * that lie beyond an outline of the centre pixel's face: that show something else, and not
   * the continuation of its plane (a seam between faces of one flat surface, such as the
   * diagonal of a quad, is no outline). So an outline stays visible while a line under a
   * surface seen at a grazing angle stays hidden, even where the surface's triangles meet.
   * Unlike a depth bias that follows the faces' slope, the tolerance is fixed: a wall thicker
   * than half a pixel's footprint, plus its depth change over the half pixel between the line's
   * point and the pixel's centre, hides what lies behind it at any angle. A line more
   * than a footprint under the centre face at its own point (the face continued along its plane
   * from the pixel's centre) is judged by that face alone unless empty space shows beyond: a part
   * passing through the surface next to the line is no outline of it. */
  ivec2 q = ivec2(floor(c));
  ivec2 size = textureSize(surface_depth, 0) - 1;
  ivec2 qc = clamp(q, ivec2(0), size);
  vec2 id_c = texelFetch(surface_id, qc, 0).rg;
  float inv_c = texelFetch(surface_depth, qc, 0).r;
  float inv_at = inv_c; /* the centre face's 1/z at the line's point c */
  bool under = false;   /* the line lies more than a footprint under the centre face at c, and
                         * nothing beyond it in the 3x3 is empty space */
  float inv_other = inv_c;
  float world_per_px = (persp ? z : 1.0) / frame.camera.x;
  float bias = 0.5 * world_per_px + line_vis.y * abs(z);
  /* Where the highlights draw fillets (line_vis.w < 0, a type that lies between faces: a crease),
   * the surface pass moved a rounded silhouette's outline in (rounded_outline.glsl) and the
   * silhouette line with it (outline_lines.py), but a crease along that edge still runs on the
   * sharp edge. Its ink over a pixel that shows none of its faces and nothing in front of it
   * (empty space, or a surface behind it) lies past the part's outline: not drawn, not dimmed
   * either. Judged per pixel, not on the centre line: the crease's half over the part stays
   * within the moved silhouette's stroke, and a crease away from any outline has its faces
   * under every pixel. */
  if (line_vis.w < -0.5) {
    ivec2 pp = clamp(ivec2(p), ivec2(0), size);
    float inv_p = texelFetch(surface_depth, pp, 0).r;
    if (!el_own_face(texelFetch(surface_id, pp, 0).rg) && !(inv_p > 0.0 && 1.0 / inv_p <= z + bias)) {
      discard;
    }
  }
  /* Most ink lies on one of its own faces at the centre pixel: then the 3x3 walk is skipped
   * (whole 4x4 blocks of a stroke usually agree, so llvmpipe skips it too). */
  bool own = el_own_face(id_c);
  if (!own) {
    /* The 3x3 window, k = 3 * (dy + 1) + (dx + 1), filled at constant indices: softpipe's
     * interpreter (tgsi_exec) stores through a variable array index at the index of the first
     * pixel of its 2x2 quad for all four, even when that pixel was discarded or took the other
     * branch (a stale index: a wrong element written), and a loop with a discard in the shader is
     * not unrolled there. Reads through a variable index are per pixel. */
    ivec2 lo = clamp(q - 1, ivec2(0), size), hi = clamp(q + 1, ivec2(0), size);
    vec2 nid[9] = vec2[9](texelFetch(surface_id, ivec2(lo.x, lo.y), 0).rg, texelFetch(surface_id, ivec2(qc.x, lo.y), 0).rg,
                          texelFetch(surface_id, ivec2(hi.x, lo.y), 0).rg, texelFetch(surface_id, ivec2(lo.x, qc.y), 0).rg,
                          id_c, texelFetch(surface_id, ivec2(hi.x, qc.y), 0).rg,
                          texelFetch(surface_id, ivec2(lo.x, hi.y), 0).rg, texelFetch(surface_id, ivec2(qc.x, hi.y), 0).rg,
                          texelFetch(surface_id, ivec2(hi.x, hi.y), 0).rg);
    float ninv[9] = float[9](texelFetch(surface_depth, ivec2(lo.x, lo.y), 0).r, texelFetch(surface_depth, ivec2(qc.x, lo.y), 0).r,
                             texelFetch(surface_depth, ivec2(hi.x, lo.y), 0).r, texelFetch(surface_depth, ivec2(lo.x, qc.y), 0).r,
                             inv_c, texelFetch(surface_depth, ivec2(hi.x, qc.y), 0).r,
                             texelFetch(surface_depth, ivec2(lo.x, hi.y), 0).r, texelFetch(surface_depth, ivec2(qc.x, hi.y), 0).r,
                             texelFetch(surface_depth, ivec2(hi.x, hi.y), 0).r);
    for (int k = 0; k < 9; k++) {
      own = own || el_own_face(nid[k]);
    }
    /* The centre face's step of 1/z per pixel in x and y (1/z is affine in screen space across
     * a plane), from a pixel beside the centre that shows the same face; none: unknown. */
    bool in_r = q.x<size.x, in_l = q.x> 0, in_u = q.y<size.y, in_d = q.y> 0;
    bool has_gx = (in_r && nid[5] == id_c) || (in_l && nid[3] == id_c);
    bool has_gy = (in_u && nid[7] == id_c) || (in_d && nid[1] == id_c);
    float gx = (in_r && nid[5] == id_c) ? ninv[5] - inv_c : inv_c - ninv[3];
    float gy = (in_u && nid[7] == id_c) ? ninv[7] - inv_c : inv_c - ninv[1];
    /* The centre face continued along its plane to the line's own point c (up to 0.7 px from
     * the pixel's centre): a line more than a footprint under it there lies under that face. */
    if (inv_c > 0.0 && has_gx && has_gy) {
      vec2 off = c - (vec2(q) + 0.5);
      inv_at = inv_c + off.x * gx + off.y * gy;
      under = inv_at > 0.0 && z > 1.0 / inv_at + world_per_px + bias;
    }
    for (int k = 0; k < 9; k++) {
      if (nid[k] == id_c) {
        continue;
      }
      int dx = k % 3 - 1, dy = k / 3 - 1;
      bool seam = false;
      if (inv_c > 0.0 && ninv[k] > 0.0 && (dx == 0 || has_gx) && (dy == 0 || has_gy)) {
        float plane = inv_c + (dx != 0 ? float(dx) * gx : 0.0) + (dy != 0 ? float(dy) * gy : 0.0);
        seam = plane > 0.0 && abs(1.0 / ninv[k] - 1.0 / plane) <= bias;
      }
      if (!seam) {
        inv_other = min(inv_other, ninv[k]);
      }
    }
    /* Empty space beyond: an outline against the background, whatever the centre face's plane
     * says (near a convex outline, a facet's plane continued lies in front of the outline). */
    under = under && inv_other > 0.0;
  }
  float inv_shown = line_vis.w > 0.5 && !under ? inv_other : inv_c;
  bool visible = own || inv_shown <= 0.0 || z <= 1.0 / inv_shown + bias;
  float alpha = cov * line_color.a * (visible ? 1.0 : line_vis.x);
  if (alpha <= 0.0) {
    discard;
  }
  out_color = vec4(line_color.rgb, alpha);
  gl_FragDepth = 1.0 - alpha;
}
