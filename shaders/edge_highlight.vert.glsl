/* Hidden pixels are rejected by the depth test against the surface pass before the fragment
 * shader runs (llvmpipe then skips whole blocks; a discard does not end its fragments). The
 * quad's depth at an end is that end pulled toward the eye by more than the fragment shader's
 * own visibility bias at any pixel of the quad there, so that exact test still decides every
 * pixel it could keep: the bias (edge_highlight.frag) with |across| at its largest (half_px),
 * the faces' cosines halved (the view ray turns along the edge) and a factor 2. Returns the NDC
 * depth, or -1 (the near plane: nothing is rejected) when the pulled point would reach the near
 * plane. */
float el_pulled_depth(vec3 at, float half_px)
{
  bool persp = frame.eye.w > 0.5;
  vec3 V = el_safe_normalize(persp ? frame.eye.xyz - at : -frame.view_dir.xyz);
  float dist = persp ? length(frame.eye.xyz - at) : 1.0;
  float c_min = max(0.5 * min(abs(dot(normalize(edge_n1), V)), abs(dot(normalize(edge_n2), V))), 1.0 / 16.0);
  float slope = sqrt(max(1.0 - c_min * c_min, 0.0)) / c_min;
  float pull = 2.0 * ((half_px + 1.0) * (dist / frame.camera.x) * (slope + 0.05) + 1e-5 * dist);
  if (persp && !(pull < 0.5 * dist)) {
    return -1.0;
  }
  vec4 cp = frame.projection * (frame.view * vec4(at + V * pull, 1.0));
  float z = cp.z / cp.w;
  return cp.w > 0.0 && z > -1.0 ? z : -1.0;
}

/* A band's cut at an end vertex (band_ends.py), as the unit screen normal of its line pointing to
 * the band's body. u: along the edge from this end, inside: the face's inside across the edge
 * (object space), phi: the cut's angle from the edge towards the inside. A cut seen end-on
 * (along the view ray) is square to the edge's image. */
vec2 el_cut_normal(vec3 u, vec3 inside, float phi, vec4 c, vec2 along_px)
{
  vec3 un = el_safe_normalize(u);
  vec3 n = el_safe_normalize(inside - dot(inside, un) * un);
  vec2 line = el_screen_dir(mat3(model) * (cos(phi) * un + sin(phi) * n), c);
  vec2 body = el_screen_dir(mat3(model) * (sin(phi) * un - cos(phi) * n), c);
  float len = length(line);
  if (!(len > 1e-6 * length(body))) {
    return along_px;
  }
  vec2 nrm = vec2(-line.y, line.x) / len;
  return dot(nrm, body) < 0.0 ? -nrm : nrm;
}

/* How far past its end vertex (pixels along the edge's image, outwards) the quad must reach for
 * the cuts of both faces there (unit normals a, b pointing to the band's body): a cut square to
 * the edge in its face's plane may lean outwards on screen. `half_px`: the band's reach across,
 * `cap`: the most it may reach. */
float el_reach_past(vec2 a, vec2 b, vec2 outward, vec2 across, float half_px, float cap)
{
  float r = 1.0 / 64.0;
  for (int k = 0; k < 2; k++) {
    vec2 nrm = k == 0 ? a : b;
    float o = dot(outward, nrm);
    float need = o < -1e-3 ? half_px * abs(dot(across, nrm)) / -o : cap;
    r = max(r, min(need, cap));
  }
  return r;
}

/* The world point of the edge's line whose image is at lambda along s0 -> s1 (0 and 1: the
 * ends), perspective-correct; at most a few edge lengths past either end (the quad's reach past
 * an end is bounded on screen, el_reach_past's cap), and well in front of the eye: clip w is
 * affine along the line, so it is kept above half the nearer end's. */
vec3 el_line_point(vec3 w0, vec3 w1, float iw0, float iw1, float lambda)
{
  float den = (1.0 - lambda) * iw0 + lambda * iw1;
  float t = clamp(den > 0.0 ? lambda * iw1 / den : lambda, -4.0, 5.0);
  float cw0 = 1.0 / iw0, cw1 = 1.0 / iw1, least = 0.5 * min(cw0, cw1);
  if (mix(cw0, cw1, t) < least) {
    t = (least - cw0) / (cw1 - cw0);
  }
  return w0 + t * (w1 - w0);
}

/* Edge highlight pass: one screen-space quad per rounded edge (no wide GL lines, no geometry
 * shader). corner.x picks the end (0: p0, 1: p1), corner.y the side (-1, +1), corner.z is the
 * radius. The quad reaches the pixel's footprint past the rounded edge's projected band on each
 * side: the support of the fragment shader's filtered coverage, so every pixel the band touches
 * runs it and no other does. */
void main()
{
  vec3 w0 = (model * vec4(p0, 1.0)).xyz;
  vec3 w1 = (model * vec4(p1, 1.0)).xyz;
  edge_faces = faces;
  edge_uv = uv;     /* the image's UV at p0 and at p1 on the edge's face (batches.edge_uv), zero without one */
  edge_col0 = col0; /* and the colour attribute there (batches._edge_attribute_colors) */
  edge_col1 = col1;
  /* Each end's normals transformed as the surface pass transforms its corner normals (each
   * normalized before the blend along the edge), then the world mean and turn from them as
   * edge_data.mean_and_turn takes them in object space. */
  el_mean_and_turn(el_transform_normal(model, n1 - 0.5 * turn1), el_transform_normal(model, n1 + 0.5 * turn1),
                   edge_n1, edge_turn1);
  el_mean_and_turn(el_transform_normal(model, n2 - 0.5 * turn2), el_transform_normal(model, n2 + 0.5 * turn2),
                   edge_n2, edge_turn2);
  edge_dir = w1 - w0;
  edge_radius = corner.z * el_radius_scale(model, n1, n2, p1 - p0);
  /* Convex or concave, in object space where a mirroring model cannot turn it: N1's face runs
   * p0 -> p1, so the surface turns away from its outside where N1 x N2 points along p0 -> p1
   * (the library's EL_EDGE_CONVEX rule, classify.cpp). */
  edge_fold = dot(cross(n1, n2), p1 - p0) < 0.0 ? -1.0 : 1.0;

  vec4 c0 = frame.projection * (frame.view * vec4(w0, 1.0));
  vec4 c1 = frame.projection * (frame.view * vec4(w1, 1.0));
  vec3 world = corner.x < 0.5 ? w0 : w1;
  vec4 c = corner.x < 0.5 ? c0 : c1;
  /* An end behind the eye: skip the edge (its other end is clipped anyway). */
  if (c0.w <= 0.0 || c1.w <= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  vec2 s0 = (c0.xy / c0.w * 0.5 + 0.5) * frame.viewport.xy;
  vec2 s1 = (c1.xy / c1.w * 0.5 + 0.5) * frame.viewport.xy;
  vec2 along = s1 - s0;
  float len = length(along);
  vec2 dir = len > 1e-6 ? along / len : vec2(1.0, 0.0);
  vec2 across = vec2(-dir.y, dir.x);
  edge_screen = vec4(s0, across);
  /* Where the band ends on each face: a cut through each end vertex in the face's plane
   * (band_ends.py). N1's face runs p0 -> p1, so its inside is N1 x (p1 - p0); N2's is the other
   * way round. edge_far.z: which side of the line N1's face lies on, in the image. */
  vec3 e_obj = p1 - p0;
  vec3 in1 = cross(n1, e_obj), in2 = cross(e_obj, n2);
  edge_cut0 = vec4(el_cut_normal(e_obj, in1, ends.x, c0, dir), el_cut_normal(e_obj, in2, ends.y, c0, dir));
  edge_cut1 = vec4(el_cut_normal(-e_obj, in1, ends.z, c1, -dir), el_cut_normal(-e_obj, in2, ends.w, c1, -dir));
  float side1 = dot(el_screen_dir(mat3(model) * in1, c0), across) < 0.0 ? -1.0 : 1.0;
  float side2 = dot(el_screen_dir(mat3(model) * in2, c0), across) < 0.0 ? -1.0 : 1.0;
  vec3 Vm0 = el_safe_normalize(frame.eye.w > 0.5 ? frame.eye.xyz - 0.5 * (w0 + w1) : -frame.view_dir.xyz);
  float f1 = dot(el_safe_normalize(edge_n1), Vm0), f2 = dot(el_safe_normalize(edge_n2), Vm0);
  if (side1 == side2 || min(f1, f2) < 0.1) {
    /* A silhouette (both faces lie on one side of the line, nothing on the other), or a face
     * seen edge-on (its cut's image is a guess): the band is cut as on the face that faces the
     * eye, on both sides. */
    bool front1 = f1 >= f2;
    edge_cut0 = front1 ? edge_cut0.xyxy : edge_cut0.zwzw;
    edge_cut1 = front1 ? edge_cut1.xyxy : edge_cut1.zwzw;
  }
  /* edge_far.w: 1 where both faces face the eye, one each side of the line (el_faces_under_band;
   * a face seen at a grazing angle still covers its side of the pixels next to the line); -1 at
   * a silhouette, both faces on one side (el_silhouette_band); 0 otherwise. */
  edge_far = vec4(s1, side1, side1 != side2 && min(f1, f2) > 0.0 ? 1.0 : (side1 == side2 ? -1.0 : 0.0));

  /* Cull before any fragment runs (viewport.visible_edges counts the same tests): both faces
   * turned away (judged at the edge's midpoint, the same for all four corners), or a weight
   * that cannot reach one 8-bit step. */
  vec3 mid = 0.5 * (w0 + w1);
  vec3 Vm = frame.eye.w > 0.5 ? frame.eye.xyz - mid : -frame.view_dir.xyz;
  float dist_m = frame.eye.w > 0.5 ? length(Vm) : 1.0;
  float width_m = edge_radius * length(edge_n1 - edge_n2) * frame.camera.x / max(dist_m, 1e-20);
  if ((dot(edge_n1, Vm) <= 0.0 && dot(edge_n2, Vm) <= 0.0) || tint.w * min(width_m, 1.0) < 1.0 / 255.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }

  /* The quad's sides, the same offsets from the line at both ends: a parallelogram, so that
   * edge_point interpolates to the foot of each pixel's perpendicular on the line (a trapezoid
   * would skew it). The pixel's footprint past where the band lies (edge_band_extent.glsl),
   * within its reach (the larger of the two ends'). Fewer pixels run the fragment shader; none it
   * would light is left out (tests/native/render/test_edge_culling.cpp). */
  float half_px = max(el_half_width_px(w0), el_half_width_px(w1));
  vec2 sides = el_quad_sides(w0, w1, c0, c1, across, half_px - 0.5 - 1.0 / 64.0);
  float lo = sides.x, hi = sides.y;
  float pad = el_footprint_reach(across) + 1.0 / 64.0; /* the pixel's footprint (edge_band.glsl) */
  float offset = corner.y < 0.0 ? lo - pad : hi + pad;

  /* Past each end as far as a cut there leans outwards on screen (up to twice the band's widest
   * reach, whichever sides the quad was fitted to; an edge seen end-on, under a pixel long, has
   * no direction to reach along, so at most its own image length there), along the edge's line:
   * still a parallelogram, so edge_point still interpolates to each pixel's foot on the line. A
   * band wider than its edge is long (a short piece of a rim) leans past it by more than the
   * edge's length. */
  float side_px = max(abs(lo), abs(hi)) + pad;
  float most = 2.0 * (half_px + 0.5);
  float cap = max(len >= 1.0 ? most : min(most, len), 1.0 / 64.0);
  float past0 = el_reach_past(edge_cut0.xy, edge_cut0.zw, -dir, across, side_px, cap) / max(len, 1e-6);
  float past1 = el_reach_past(edge_cut1.xy, edge_cut1.zw, dir, across, side_px, cap) / max(len, 1e-6);
  world = el_line_point(w0, w1, 1.0 / c0.w, 1.0 / c1.w, corner.x < 0.5 ? -past0 : 1.0 + past1);
  c = frame.projection * (frame.view * vec4(world, 1.0));
  vec3 x0 = el_line_point(w0, w1, 1.0 / c0.w, 1.0 / c1.w, -past0);
  vec3 x1 = el_line_point(w0, w1, 1.0 / c0.w, 1.0 / c1.w, 1.0 + past1);
  if (c.w <= 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }

  /* Both ends' pulled depths, so that all four corners agree on whether the edge is tested. */
  float z0 = el_pulled_depth(x0, half_px), z1 = el_pulled_depth(x1, half_px);
  float z = (z0 > -1.0 && z1 > -1.0) ? (corner.x < 0.5 ? z0 : z1) : -1.0;

  vec2 s = (c.xy / c.w * 0.5 + 0.5) * frame.viewport.xy + across * offset;
  edge_point = world;
  vec3 span = w1 - w0;
  edge_t = dot(span, span) > 0.0 ? dot(world - w0, span) / dot(span, span) : 0.5;
  gl_Position = vec4((s / frame.viewport.xy * 2.0 - 1.0) * c.w, z * c.w, c.w);
}
