/* What one pixel shows of a rounded edge's band (edge_highlight.frag.glsl): EdgeLight's method
 * (docs/highlight_math.md, section 15), at every width. The band lies where the fillet's image
 * really lies, and the pixel is shaded with the part of the arc whose image it covers. Needs
 * highlight_arc.glsl, edge_shading.glsl and edge_band.glsl. */

/* The band's arc at line parameter t (el_edge_frame_at) seen along V from edge point X: E, |E x V|
 * and the band's ends across the line in pixels. */
ElArc el_band_at(float t, vec3 X, vec3 V, float world_per_px, out vec3 E, out float s, out vec2 ends)
{
  vec3 n1, n2;
  el_edge_frame_at(t, E, n1, n2);
  ElArc g = el_arc(E, n1, n2, V);
  s = sqrt(dot(g.view, g.view)); /* |E x V| */
  vec3 P = el_safe_normalize(cross(el_safe_normalize(E), V));
  /* Which way P points on screen (the sign of its image along edge_screen's normal). */
  vec4 q0 = frame.projection * (frame.view * vec4(X, 1.0));
  vec4 q1 = frame.projection * (frame.view * vec4(X + P * world_per_px, 1.0));
  float side = dot((q1.xy / q1.w - q0.xy / q0.w) * frame.viewport.xy, edge_screen.zw) < 0.0 ? -1.0 : 1.0;
  ends = el_band_ends(g, P, edge_fold) * (side * edge_radius / world_per_px);
  return g;
}

/* Premultiplied (W Is, W) of the pixel whose centre is `pc`, at edge point X seen along unit V;
 * `across`: the pixel centre's distance from the edge line in pixels (along edge_screen.zw).
 * Zero where the pixel shows none of the band. The pixel is a square: its footprint across the
 * line is one to four boxes (el_footprint), each shaded with the part of the arc whose image it
 * covers. share1: the share of the band's part in the pixel that lies on N1's face's side of the
 * line (at 0; edge_far.z: the side N1's face lies on in the image), pixel1 the pixel's own share
 * there (el_faces_under_band). */
vec4 el_band_pixel(vec2 pc, vec3 X, vec3 V, float world_per_px, float across, out float share1, out float pixel1)
{
  share1 = 0.5;
  pixel1 = 0.5;
  vec3 E;
  float s;
  vec2 ends;
  ElArc g = el_band_at(clamp(edge_t, 0.0, 1.0), X, V, world_per_px, E, s, ends);
  if (!(g.width > 0.0) || !(s > 0.0)) {
    return vec4(0.0);
  }
  float ramp = el_axial_ramp(s);
  /* Along the line (docs/highlight_math.md, "Along the line"): the fillet's point of normal N
   * lies Y = fold r (N - C) from the edge point whose cross-section it is, and where the edge is
   * seen obliquely Y's image runs along the line too. The pixel's foot is on the line of the
   * edge D (length L), so the point it sees is that of the cross-section at
   * t' = t + ((Y.V)(D.V) - Y.D) / (L |D x V|^2), N the normal of the arc's point its centre
   * sees (Y.D: the frame turns off D where the normals turn). That matters where the normals
   * turn along the edge (a ring seen nearly along its edges, where its image turns): there the
   * band takes the frame at t', the normals turned on past the edge's ends as they turn along
   * it, to half an edge (the next edges' own bands take over). Not at a silhouette, whose band's
   * horizon is the outline. */
  if ((edge_turn1 != vec3(0.0) || edge_turn2 != vec3(0.0)) && edge_far.w > 0.5) {
    float f = clamp((across - ends.x) / (ends.y - ends.x), 0.0, 1.0);
    ElArc seen = el_sub_arc(g, f, f);
    vec3 C = (g.a1 + el_arc_normal(g, g.alpha)) / max(1.0 + cos(g.alpha), 1e-3);
    vec3 Y = edge_fold * edge_radius * (el_arc_normal(seen, seen.vis.lo) - C);
    float L = length(edge_dir);
    vec3 D = edge_dir / max(L, 1e-30);
    float dv = dot(D, V), sd2 = max(1.0 - dv * dv, 1e-6);
    float t = clamp(edge_t + (dot(Y, V) * dv - dot(Y, D)) / (max(L, 1e-30) * sd2), -0.5, 1.5);
    if (abs(t - edge_t) > 1e-4) {
      X += (t - edge_t) * edge_dir;
      g = el_band_at(t, X, V, world_per_px, E, s, ends);
      if (!(g.width > 0.0) || !(s > 0.0)) {
        return vec4(0.0);
      }
    }
  }
  float b0 = min(ends.x, ends.y), b1 = max(ends.x, ends.y);
  /* The band's ends on the face this pixel lies over (band_ends.py): the pixel's centre on the
   * body's side of each cut. Two bands meeting on a cut then split its pixels exactly (a
   * filtered cut would leave a seam: bands blend over each other, they do not add); the
   * jittered samples antialias the cut as they do the outline. */
  bool on_f1 = across * edge_far.z >= 0.0;
  vec2 cut0 = on_f1 ? edge_cut0.xy : edge_cut0.zw, cut1 = on_f1 ? edge_cut1.xy : edge_cut1.zw;
  if (dot(pc - edge_screen.xy, cut0) < 0.0 || dot(pc - edge_far.xy, cut1) < 0.0 || !(b1 > b0)) {
    return vec4(0.0);
  }
  /* Per box: its own share on N1's side, its covered part [pa, pb] of the band as a share of
   * the box, and that part's arc (fractions of the band from vis.lo's end). */
  vec3 fp = el_footprint(edge_screen.zw);
  int boxes = clamp(int(fp.z), 1, 4); /* bounded even for a NaN normal */
  float cover = 0.0, on1 = 0.0, box1 = 0.0;
  vec3 col = vec3(0.0);
  for (int k = 0; k < boxes; k++) {
    float c = across + el_footprint_box(fp, k);
    box1 += clamp(0.5 + c * edge_far.z / fp.x, 0.0, 1.0);
    float pa = max(c - 0.5 * fp.x, b0), pb = min(c + 0.5 * fp.x, b1);
    if (pb > pa) {
      float part = (pb - pa) / fp.x;
      cover += part;
      on1 += max(edge_far.z >= 0.0 ? pb - max(pa, 0.0) : min(pb, 0.0) - pa, 0.0) / fp.x;
      float fa = (pa - ends.x) / (ends.y - ends.x), fb = (pb - ends.x) / (ends.y - ends.x);
      ElArc sub = el_sub_arc(g, clamp(min(fa, fb), 0.0, 1.0), clamp(max(fa, fb), 0.0, 1.0));
      col += part * el_edge_colour(sub, X, V, E);
    }
  }
  float W = clamp(tint.w * cover / float(boxes), 0.0, 1.0) * ramp;
  if (!(W > 0.0)) {
    return vec4(0.0);
  }
  share1 = clamp(on1 / cover, 0.0, 1.0);
  pixel1 = box1 / float(boxes);
  return vec4(col / cover * W, W);
}

/* What the band's blend over the pixel gets wrong about the sharp faces it replaces, to add to
 * its premultiplied colour (docs/highlight_math.md, "The faces under the band"). The composite
 * is W Is + (1 - W) S, S the pixel's mean of the sharp mesh; a fillet replaces only the faces
 * under the band: S - W (s1 I1 + (1 - s1) I2) + W Is, with s1 the band's share on N1's side and
 * I1, I2 the faces' colours along the edge. With S = f1 I1 + (1 - f1) I2 (f1: the pixel's share
 * on N1's side) the difference is W (f1 - s1) (I1 - I2): zero where the band splits as the
 * pixel does, large where it lies on a face lit past white and the pixel straddles a dim one.
 * Only where both faces face the eye, one on each side of the line (edge_far.w); a
 * silhouette's far side is whatever lies behind it. I1 and I2 are the faces' colours with the
 * normals they are shaded with at the pixel's place along the edge (el_edge_frame). Where the
 * line crosses the pixel, `far` is the colour along the edge of the face on the other side of
 * the line from the pixel's centre and `near_share` the pixel's share on the centre's side;
 * elsewhere near_share is 1. */
vec3 el_faces_under_band(vec3 X, vec3 V, float f1, float share1, float W, out vec3 far, out float near_share)
{
  far = vec3(0.0);
  near_share = 1.0;
  if (!(edge_far.w > 0.5) || f1 == share1) {
    return vec3(0.0);
  }
  vec3 E, n1, n2;
  el_edge_frame(edge_t, E, n1, n2);
  vec3 I1 = el_face_colour(normalize(n1), X, V), I2 = el_face_colour(normalize(n2), X, V);
  if (f1 > 0.0 && f1 < 1.0) {
    bool centre_on_1 = f1 >= 0.5;
    far = centre_on_1 ? I2 : I1;
    near_share = centre_on_1 ? f1 : 1.0 - f1;
  }
  return W * (f1 - share1) * (I1 - I2);
}

/* A silhouette's band as a change to the pixel, premultiplied with no alpha of its own: W (Is -
 * I_front) (docs/highlight_math.md, "The band at the outline"). Laid over each sample's surface
 * as a layer, the band hides W of whatever that sample shows, the background too where the
 * sample lies past the outline; the fillet lies on the front face and takes W out of that face
 * alone. W is at most the pixel's share on the faces' side of the line (`faces_share`), the
 * front face's coverage, so that the samples' mean stays a blend of the face and the band. */
vec4 el_silhouette_band(vec4 band, vec3 X, vec3 V, float faces_share)
{
  vec3 E, n1, n2;
  el_edge_frame(edge_t, E, n1, n2);
  vec3 front = dot(n1, V) >= dot(n2, V) ? n1 : n2;
  float W = min(band.w, clamp(faces_share, 0.0, 1.0));
  return vec4(W * (band.rgb / band.w - el_face_colour(normalize(front), X, V)), 0.0);
}
