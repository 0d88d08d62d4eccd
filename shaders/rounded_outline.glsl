/* Where a rounded silhouette pulls the part's outline in (docs/highlight_math.md, "The fillet's
 * outline"). A convex fillet of radius r between faces with unit normals Na, Nb has its axis r
 * inside both, and the sharp edge lies r C from the axis, C = (Na + Nb) / (1 + Na.Nb). Where one
 * face faces the eye and the other does not, the fillet's outline is the circle's extreme point
 * across the view, r from the axis along P = (Na x Nb) x V / |...|, and the sharp edge's image
 * lies r |P.C| from it: the outline moves in by r (|P.C| - 1). The strip between shows what lies
 * behind the part. Where two silhouettes meet at a corner patch, the fillets meet on its ball, and
 * past the feet of the ball's centre on both lines the outline is the ball's circle. Needs the
 * samplers outline_edges, outline_corners and outline_triangles, and their layouts as defines
 * (EL_OUTLINE_*: rounded_outline.py's constants, passes/surface_pass.py). */
#ifdef EL_ROUNDED_OUTLINE
/* A convex fillet of radius 1 between faces of unit normals na, nb, seen along V (unit, towards
 * the eye): xyz, the unit direction P from its axis to its outline point, turned towards the sharp
 * edge, which lies C from the axis; w, 1 where one face faces the eye and the other does not (a
 * silhouette), else 0 (and P = 0). outline_lines.fillet_outline is its numpy copy (the ink's move
 * onto the outline), pinned to this text by tests/blender/test_fillet_outline.py. */
vec4 el_fillet_outline(vec3 na, vec3 nb, vec3 V, out vec3 C)
{
  C = (na + nb) / max(1.0 + dot(na, nb), 1e-3);
  vec3 P = cross(cross(na, nb), V);
  float len = length(P);
  if (!(dot(na, V) * dot(nb, V) < 0.0) || !(len > 1e-6)) {
    return vec4(0.0);
  }
  P /= len;
  return vec4(dot(P, C) < 0.0 ? -P : P, 1.0);
}

/* Rounded edge `e`'s strip seen from pixel position `s` (pixels): returns its width in pixels at
 * the edge's end p0 (0 where the edge is no silhouette there; -1 where it has no strip at all),
 * and `strip1` at p1; `dist`, the signed distance in pixels of s from the edge's image line
 * (positive on its faces' side), `along`, where its foot lies on the edge's image (0 and 1: the
 * ends), `length_px`, the edge's image length in pixels; per end, where a concave fillet meets
 * the edge and fills the corner, `cut`, the fraction of the edge from that end the fillet
 * reaches along it (rounded_outline.py's records), and `arc`, how far out over the line its end
 * arc reaches at the vertex in pixels, negative where a concave edge meets the end
 * (el_end_arc_px). dist and along are affine on screen: interpolated without perspective from
 * a triangle's vertices, they are exact at every pixel. A pixel takes the strip's width at its foot; past an end the strip ends in a half disc
 * of its width there, or of the edge's image length where that is shorter (el_strip_part): where
 * the outline turns away from the part's inside between two strips (a rim seen from above),
 * their ends leave a wedge that the moved outline, round there as the fillets' is, still passes
 * inside. Judged at the edge's own ends, the strip is the same on both its faces and at every
 * vertex of a triangle. A polygon's other triangles meet the line beyond the edge too (a gear's
 * face round its teeth): the strip runs along the edge alone, and its ends' half discs reach no
 * farther than its width. `nm`: el_normal_matrix(model). */
float el_outline_strip(int e, vec2 s, mat3 nm, out float dist, out float along_t, out float strip1, out float length_px,
                       out vec2 cut, out vec2 arc)
{
  cut = vec2(0.0);
  arc = vec2(0.0);
  dist = 0.0;
  along_t = 0.0;
  strip1 = 0.0;
  length_px = 0.0;
  bool persp = frame.eye.w > 0.5;
  ivec2 at = ivec2((e % EL_OUTLINE_EDGES_PER_ROW) * EL_OUTLINE_EDGE_TEXELS, e / EL_OUTLINE_EDGES_PER_ROW);
  vec4 t0 = texelFetch(outline_edges, at, 0);
  vec3 ma = t0.xyz, mb = texelFetch(outline_edges, at + ivec2(1, 0), 0).xyz;
  vec4 e0 = texelFetch(outline_edges, at + ivec2(2, 0), 0), e1 = texelFetch(outline_edges, at + ivec2(3, 0), 0);
  vec3 o0 = e0.xyz, o1 = e1.xyz;
  float scale = el_radius_scale(model, ma, mb, o1 - o0); /* as the edge pass scales its radius */
  vec3 na = normalize(nm * ma), nb = normalize(nm * mb);
  vec3 w0 = (model * vec4(o0, 1.0)).xyz, w1 = (model * vec4(o1, 1.0)).xyz;
  vec4 t4 = texelFetch(outline_edges, at + ivec2(4, 0), 0), t5 = texelFetch(outline_edges, at + ivec2(5, 0), 0);
  vec3 ta = t4.xyz, tb = t5.xyz;
  vec2 width = vec2(0.0);
  for (int end = 0; end < 2; end++) {
    /* Each end with the normals its faces are shaded with there, the vertex's own: the edges
     * that meet at a vertex agree on whether it lies on a silhouette, so a strip narrows to
     * nothing where its neighbour's does, and its end's half disc reaches no farther. */
    float half_turn = end == 0 ? -0.5 : 0.5;
    vec3 ea = normalize(nm * (ma + half_turn * ta)), eb = normalize(nm * (mb + half_turn * tb));
    vec3 to_eye = persp ? frame.eye.xyz - (end == 0 ? w0 : w1) : -frame.view_dir.xyz;
    vec3 C;
    vec4 P = el_fillet_outline(ea, eb, normalize(to_eye), C);
    if (P.w > 0.0) {
      float px_per_world = frame.camera.x / (persp ? max(length(to_eye), 1e-30) : 1.0);
      width[end] = t0.w * scale * max(dot(P.xyz, C) - 1.0, 0.0) * px_per_world;
    }
  }
  if (!(max(width.x, width.y) > 0.0)) {
    return -1.0; /* both faces on one side of the eye at both ends: no silhouette */
  }
  vec4 c0 = frame.projection * (frame.view * vec4(w0, 1.0));
  vec4 c1 = frame.projection * (frame.view * vec4(w1, 1.0));
  vec2 s0 = (c0.xy / c0.w * 0.5 + 0.5) * frame.viewport.xy;
  vec2 along = (c1.xy / c1.w * 0.5 + 0.5) * frame.viewport.xy - s0;
  float l = length(along);
  if (!(c0.w > 0.0) || !(c1.w > 0.0) || !(l > 1e-6)) {
    return -1.0; /* behind the eye, or seen end-on: its strip is a point */
  }
  /* Signed towards where the faces lie: at a silhouette both lie on one side of the line, and
   * the strip lies there; on the other side, another face may show (a bore's wall turning
   * towards the eye past the end of its rim's silhouette). Judged at the wider end, from a
   * step into face a square to the edge. */
  vec3 wide_end = width.x >= width.y ? w0 : w1;
  vec3 into_a = -(nb - dot(nb, na) * na);
  vec4 cs = frame.projection * (frame.view * vec4(wide_end, 1.0));
  vec4 ca = frame.projection * (frame.view * vec4(wide_end + into_a * (0.1 * length(w1 - w0) / max(length(into_a), 1e-30)), 1.0));
  vec2 step_a = (ca.xy / ca.w - cs.xy / cs.w) * 0.5 * frame.viewport.xy;
  float faces_side = along.x * step_a.y - along.y * step_a.x < 0.0 ? -1.0 : 1.0;
  dist = faces_side * (along.x * (s.y - s0.y) - along.y * (s.x - s0.x)) / l;
  along_t = dot(s - s0, along) / (l * l);
  length_px = l;
  strip1 = width.y;
  /* A concave fillet meeting the edge at an end: its end arc lies in the edge's other face,
   * from the edge, `cut` of it from the vertex, round the inside corner (taken as a quarter
   * circle of that radius); out of that face's side of the line, over the part's outline. How
   * far out the arc's far end lies in pixels, across the line (el_strip_part), negative where
   * a concave edge meets the end (el_end_arc_px). */
  for (int end = 0; end < 2; end++) {
    float c = end == 0 ? e0.w : e1.w, h = 0.0;
    if (c != 0.0) {
      float half_turn = end == 0 ? -0.5 : 0.5;
      vec3 ea = normalize(nm * (ma + half_turn * ta)), eb = normalize(nm * (mb + half_turn * tb));
      vec3 arc_face = c > 0.0 ? eb : ea, fillet_face = c > 0.0 ? ea : eb;
      vec3 out_of_face = fillet_face - dot(fillet_face, arc_face) * arc_face;
      vec3 at_end = end == 0 ? w0 : w1;
      vec4 ce = frame.projection * (frame.view * vec4(at_end, 1.0));
      vec4 co = frame.projection * (frame.view * vec4(at_end + out_of_face * (abs(c) * length(w1 - w0) / max(length(out_of_face), 1e-30)), 1.0));
      vec2 q = (co.xy / co.w - ce.xy / ce.w) * 0.5 * frame.viewport.xy;
      /* The cut, a fraction of the edge from this end, as a fraction of its image (el_strip_part
       * takes the pixel's foot on the image): perspective divides by the clip w. */
      float w_here = end == 0 ? c0.w : c1.w, w_there = end == 0 ? c1.w : c0.w;
      cut[end] = abs(c) * w_there / max((1.0 - abs(c)) * w_here + abs(c) * w_there, 1e-30);
      h = co.w > 0.0 ? max(-faces_side * (along.x * q.y - along.y * q.x) / l, 0.0) : 0.0;
    }
    arc[end] = (end == 0 ? t4.w : t5.w) > 0.0 ? -1.0 - h : h;
  }
  return width.x;
}

/* Which part of its strip a pixel with these values of el_outline_strip lies in: EL_STRIP_BODY
 * along the edge; past one of its ends, in the half disc of the strip's width there (of no more
 * than the edge's image length: where a rim's image turns tightly its edges are shorter than
 * the strip is wide, and a wider disc reaches past the next edges, whose strips narrow),
 * EL_STRIP_LONE_DISC where no concave edge meets that end, else EL_STRIP_DISC; EL_STRIP_NEAR
 * past an end within the strip's width there but not in that disc; else EL_STRIP_NONE.
 * A disc fills the wedge where the outline turns away from the part between two strips (a rim
 * seen from above), and a pixel there lies past the ends of both. Where the outline runs on
 * from the strip into an edge the fillets do not move, the disc rounds the turn; but where a
 * concave edge meets the end, the silhouette may run on into it, behind the face, and past the
 * end lies face that the fillets keep (a step's riser seen from behind, ending at the floor):
 * there the disc needs another strip's end at the vertex (el_past_outline). Where a concave fillet
 * meets the edge at an end, the strip is narrower by how far the fillet's end arc lies out over
 * the line (el_end_arc, over the `cut` fraction of the edge from that end). */
const int EL_STRIP_NONE = 0, EL_STRIP_NEAR = 1, EL_STRIP_DISC = 2, EL_STRIP_BODY = 3, EL_STRIP_LONE_DISC = 4;

/* el_outline_strip's `arc` at an end: the end arc's reach in pixels (>= 0), and whether a
 * concave edge meets the end (the value then -1 - reach). */
float el_end_arc_px(float arc)
{
  return arc >= 0.0 ? arc : -1.0 - arc;
}

/* How far the end arc of reach `arc` lies out over the line x of the edge from its end. */
float el_end_arc(float x, float cut, float arc)
{
  float u = 1.0 - x / max(cut, 1e-6);
  return u > 0.0 ? el_end_arc_px(arc) * (1.0 - sqrt(max(1.0 - u * u, 0.0))) : 0.0;
}

int el_strip_part(float strip0, float strip1, float along_t, float length_px, float dist, vec2 cut, vec2 arc,
                  out float end_px)
{
  end_px = 0.0;
  float a = clamp(along_t, 0.0, 1.0);
  float strip = mix(strip0, strip1, a) - el_end_arc(a, cut.x, arc.x) - el_end_arc(1.0 - a, cut.y, arc.y);
  if (!(strip > 0.0) || !(dist >= 0.0)) {
    return EL_STRIP_NONE;
  }
  float past = max(max(-along_t, along_t - 1.0), 0.0) * length_px; /* past its end */
  if (!(past > 0.0)) {
    return dist < strip ? EL_STRIP_BODY : EL_STRIP_NONE;
  }
  float d2 = dist * dist + past * past, reach = min(strip, length_px);
  end_px = sqrt(d2);
  bool lone = (along_t < 0.0 ? arc.x : arc.y) >= 0.0;
  return d2 < reach * reach ? (lone ? EL_STRIP_LONE_DISC : EL_STRIP_DISC) : (d2 < strip * strip ? EL_STRIP_NEAR : EL_STRIP_NONE);
}

/* Two strips' ends at one vertex lie equally far from a pixel, to float precision (both
 * distances are affine on screen, from the same point: about 1e-4 px apart); the ends of a
 * chain's next edges, at other vertices, do not, but for pixels on a thin band about their
 * bisector. */
const float EL_SAME_END_PX = 1.0 / 512.0;

/* Adds a strip's el_strip_part, and its end_px, to a pixel's tally: x, 1 once the pixel lies
 * past the rounded outline (in a strip's body or a lone disc, or in a disc whose end meets an
 * end tallied before at its vertex, the pixel past both: the wedge between two strips); y, how
 * many ends it lies past within their strip's width, the first four kept in `ends` (their
 * distances, negated where the pixel lies in that end's disc). Where a chain's edges are
 * shorter than their strips are wide (a bolt hole's rim seen obliquely), a pixel past the
 * silhouette's last end also lies past the ends of the edges before it, at other vertices:
 * those do not pair. Each end is compared as it comes, so one past the four kept still pairs
 * with them. */
void el_tally_strip(int part, float end_px, inout ivec2 tally, inout vec4 ends)
{
  if (part == EL_STRIP_BODY || part == EL_STRIP_LONE_DISC) {
    tally.x = 1;
  }
  else if (part == EL_STRIP_DISC || part == EL_STRIP_NEAR) {
    float mine = part == EL_STRIP_DISC ? -end_px : end_px;
    for (int i = 0; i < min(tally.y, 4); i++) {
      if ((mine < 0.0 || ends[i] < 0.0) && abs(end_px - abs(ends[i])) < EL_SAME_END_PX) {
        tally.x = 1;
      }
    }
    if (tally.y < 4) {
      ends[tally.y] = mine;
    }
    tally.y++;
  }
}

/* Whether a pixel lies past the rounded outline, from its tally (el_tally_strip). */
bool el_past_outline(ivec2 tally)
{
  return tally.x > 0;
}

/* The list of rounded edges `texel` (0 .. EL_OUTLINE_EDGES_PER_TRIANGLE / 4 - 1) of triangle
 * `tri`: up to four edge numbers plus one (0: none). */
vec4 el_outline_edge_list(int tri, int texel)
{
  return texelFetch(outline_triangles, ivec2((tri % EL_OUTLINE_TRIANGLES_PER_ROW) * EL_OUTLINE_TRIANGLE_TEXELS + texel, tri / EL_OUTLINE_TRIANGLES_PER_ROW), 0);
}

/* For the first four of triangle `tri`'s listed edges, at this vertex (clip position `clip`),
 * el_outline_strip's values (the strip at p0 returned), to be interpolated without perspective:
 * a triangle's first four edges (its own sides and the nearest) cost the vertex shader only.
 * Each end's cut and arc are packed as two halves (half_pack.glsl) in end0 and end1: four flat
 * floats an edge would take the surface program past the 60 varying components GL promises. */
vec4 el_outline_strips(int tri, vec4 clip, out vec4 dist, out vec4 along_t, out vec4 strip1, out vec4 length_px,
                       out uvec4 end0, out uvec4 end1)
{
  end0 = uvec4(el_pack_half2(vec2(0.0)));
  end1 = end0;
  dist = vec4(0.0);
  along_t = vec4(0.0);
  strip1 = vec4(0.0);
  length_px = vec4(0.0);
  vec4 strip0 = vec4(0.0);
  if (!(clip.w > 0.0)) {
    return strip0;
  }
  mat3 nm = el_normal_matrix(model);
  vec2 s = (clip.xy / clip.w * 0.5 + 0.5) * frame.viewport.xy;
  vec4 list = el_outline_edge_list(tri, 0);
  for (int k = 0; k < 4; k++) {
    int e = int(list[k] + 0.5) - 1;
    if (e < 0) {
      continue;
    }
    float d, a, w1, l;
    vec2 c, h;
    float w0 = el_outline_strip(e, s, nm, d, a, w1, l, c, h);
    if (w0 < 0.0) {
      continue;
    }
    end0[k] = el_pack_half2(vec2(c.x, h.x));
    end1[k] = el_pack_half2(vec2(c.y, h.y));
    dist[k] = d;
    along_t[k] = a;
    strip1[k] = w1;
    length_px[k] = l;
    strip0[k] = w0;
  }
  return strip0;
}

/* Adds to `tally` and `ends` (el_tally_strip) the strips of triangle `tri`'s listed edges past the first
 * four, each judged in the fragment shader at pixel `s` (pixels): a sliver of an n-gon's fan (a
 * cylinder's cap) lies in the reach of five or six rims' strips, and only such triangles list
 * more. */
void el_tally_more_strips(int tri, vec2 s, inout ivec2 tally, inout vec4 ends)
{
  mat3 nm = el_normal_matrix(model);
  for (int texel = 1; texel < EL_OUTLINE_EDGES_PER_TRIANGLE / 4; texel++) {
    vec4 list = el_outline_edge_list(tri, texel);
    for (int k = 0; k < 4; k++) {
      int e = int(list[k] + 0.5) - 1;
      if (e < 0) {
        return; /* the list is packed: nothing follows */
      }
      float d, a, w1, l;
      vec2 c, h;
      float w0 = el_outline_strip(e, s, nm, d, a, w1, l, c, h);
      if (w0 >= 0.0) {
        float end_px;
        int part = el_strip_part(w0, w1, a, l, d, c, h, end_px);
        el_tally_strip(part, end_px, tally, ends);
      }
    }
  }
}

/* For each of triangle `tri`'s listed corner patches where exactly two of its three edges are
 * silhouettes (judged at the corner's vertex, so the triangle's vertices agree): its `zone` =
 * (this vertex's image less the ball centre's, b, and that difference along each of the two
 * edges' images towards the vertex; all affine on screen), and the ball's image radius in pixels
 * (returned; 0: no such corner). A pixel past both feet (both along-values positive) and outside
 * the circle lies past the rounded outline. */
vec4 el_outline_corners(int tri, vec4 clip, out vec4 zone0, out vec4 zone1, out vec4 zone2, out vec4 zone3)
{
  zone0 = vec4(0.0);
  zone1 = vec4(0.0);
  zone2 = vec4(0.0);
  zone3 = vec4(0.0);
  vec4 ball = vec4(0.0);
  if (!(clip.w > 0.0)) {
    return ball;
  }
  vec2 s = (clip.xy / clip.w * 0.5 + 0.5) * frame.viewport.xy;
  /* The corners' list follows the edges'. */
  vec4 list = el_outline_edge_list(tri, EL_OUTLINE_EDGES_PER_TRIANGLE / 4);
  mat3 nm = el_normal_matrix(model);
  bool persp = frame.eye.w > 0.5;
  for (int q = 0; q < 4; q++) {
    int c = int(list[q] + 0.5) - 1;
    if (c < 0) {
      continue;
    }
    ivec2 at = ivec2((c % EL_OUTLINE_CORNERS_PER_ROW) * EL_OUTLINE_CORNER_TEXELS, c / EL_OUTLINE_CORNERS_PER_ROW);
    vec3 vert = (model * vec4(texelFetch(outline_corners, at + ivec2(1, 0), 0).xyz, 1.0)).xyz;
    vec3 n[3], m[3];
    for (int k = 0; k < 3; k++) {
      m[k] = texelFetch(outline_corners, at + ivec2(2 + k, 0), 0).xyz;
      n[k] = normalize(nm * m[k]);
    }
    float scale = el_ball_scale(model, m[0], m[1], m[2]); /* as the corner pass scales its radius */
    vec3 V = normalize(persp ? frame.eye.xyz - vert : -frame.view_dir.xyz);
    /* Edge A lies between sectors CA and AB, B between AB and BC, C between BC and CA. */
    bvec3 sil;
    for (int k = 0; k < 3; k++) {
      sil[k] = dot(n[(k + 2) % 3], V) * dot(n[k], V) < 0.0;
    }
    if (int(sil.x) + int(sil.y) + int(sil.z) != 2) {
      continue;
    }
    vec4 t0 = texelFetch(outline_corners, at, 0);
    vec3 centre = (model * vec4(t0.xyz, 1.0)).xyz;
    vec4 cb = frame.projection * (frame.view * vec4(centre, 1.0));
    if (!(cb.w > 0.0)) {
      continue;
    }
    vec4 cv = frame.projection * (frame.view * vec4(vert, 1.0));
    vec2 t[2];
    int found = 0;
    for (int k = 0; k < 3; k++) {
      if (sil[k]) {
        vec3 d = cross(n[(k + 2) % 3], n[k]);
        d = dot(d, n[(k + 1) % 3]) > 0.0 ? -d : d; /* away from the vertex, under the third face */
        vec2 img = -el_screen_dir(d, cv);
        /* Constant indices: softpipe's interpreter (tgsi_exec) stores through a variable array
         * index at the first vertex's index for all four vertices it runs together. */
        vec2 tk = length(img) > 0.0 ? normalize(img) : vec2(0.0);
        if (found == 0) {
          t[0] = tk;
        }
        else {
          t[1] = tk;
        }
        found++;
      }
    }
    vec2 b = (cb.xy / cb.w * 0.5 + 0.5) * frame.viewport.xy;
    float dist = persp ? max(length(frame.eye.xyz - centre), 1e-30) : 1.0;
    vec4 z = vec4(s - b, dot(s - b, t[0]), dot(s - b, t[1]));
    if (q == 0) {
      zone0 = z;
    }
    else if (q == 1) {
      zone1 = z;
    }
    else if (q == 2) {
      zone2 = z;
    }
    else {
      zone3 = z;
    }
    ball[q] = t0.w * scale * frame.camera.x / dist;
  }
  return ball;
}
#endif
