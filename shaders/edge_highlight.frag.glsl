/* Edge highlight pass: the rounded edge's shading integrated over the part of its arc this pixel
 * sees (highlight_arc.glsl), weighted by the pixel's coverage of the projected band, depth-tested
 * against the surface pass. Output is premultiplied (W Is, W). */
#ifdef EL_EDGE_FLOOR
/* Benchmark only (passes/frame.py, EDGELIGHT_EDGE_FLOOR): the same quads, vertex shader and
 * depth test, and a fragment shader that does next to nothing: what the pass costs before any
 * shading (BENCHMARKS.md). It reads every input the pass binds, so the same uniforms can be set,
 * and writes an invisible 1e-20 of them. */
void main()
{
  vec4 inputs = vec4(edge_point, edge_radius) + table_params + base_color + spec_color + tint +
                texelFetch(cos_power_table, ivec2(0), 0).r + texelFetch(surface_depth, ivec2(0), 0).r;
#ifdef EL_EDGE_IDS
  inputs += texelFetch(surface_id, ivec2(0), 0).r + edge_faces.x + instance_id;
#endif
  out_color = inputs * 1e-20;
}
#else
void main()
{
  vec2 pc = gl_FragCoord.xy;
  vec3 X = edge_point;
  bool persp = frame.eye.w > 0.5;
  vec3 to_eye = persp ? frame.eye.xyz - X : -frame.view_dir.xyz;
  float dist = persp ? el_safe_length(to_eye) : 1.0;
  vec3 V = el_safe_normalize(to_eye);

  float world_per_px = dist / frame.camera.x;
  float across = dot(pc - edge_screen.xy, edge_screen.zw);
  float inv_surface = texelFetch(surface_depth, ivec2(pc), 0).r;
  vec4 view_X = frame.view * vec4(X, 1.0);
  float edge_depth = -view_X.z;
#ifdef EL_EDGE_IDS
  /* Visibility first (cheap): the band lies on the edge's two faces, so it shows where one of
   * them does (the surface pass's ids), or the background does (past an outline), or a surface
   * no nearer than the edge within half a pixel's footprint (docs/lines.md, "Visibility"): never
   * on a surface that hides its edge, however thin. */
  vec2 id = texelFetch(surface_id, ivec2(pc), 0).rg;
  bool own = id.x == instance_id && id.y > 0.0 && (id.y == edge_faces.x || id.y == edge_faces.y);
  if (!(id.y > 0.0)) {
    /* Background: a fillet lies within its part's outline (a convex one inside the solid, a
     * concave one over its faces), so the band shows past the outline only in the pixels the
     * part's own edge partly covers: one of the 3x3 around shows this object. */
    ivec2 size = textureSize(surface_id, 0) - 1;
    bool fringe = false;
    for (int dy = -1; dy <= 1; dy++) {
      for (int dx = -1; dx <= 1; dx++) {
        vec2 n = texelFetch(surface_id, clamp(ivec2(pc) + ivec2(dx, dy), ivec2(0), size), 0).rg;
        fringe = fringe || (n.x == instance_id && n.y > 0.0);
      }
    }
    if (!fringe) {
      discard;
    }
  }
  float bias = own ? 3.0e38 : 0.5 * world_per_px + 1e-5 * dist;
#else
  /* Without ids (the OSMesa renderer): the edge lies on its own surface, whose depth at pixels
   * next to the line differs by up to the lateral distance times the faces' depth slope. */
  float c1 = abs(dot(normalize(edge_n1), V)), c2 = abs(dot(normalize(edge_n2), V));
  float cmin = max(min(c1, c2), 1.0 / 16.0);
  float slope = sqrt(max(1.0 - cmin * cmin, 0.0)) / cmin;
  float bias = (abs(across) + 1.0) * world_per_px * (slope + 0.05) + 1e-5 * dist;
#endif
  /* The near and far planes clip the edge line here, not the quad: its depth was pulled toward
   * the eye for the early depth test (edge_highlight.vert). */
  vec4 clip_X = frame.projection * view_X;
  if ((inv_surface > 0.0 && edge_depth > 1.0 / inv_surface + bias) || abs(clip_X.z) > clip_X.w) {
    discard;
  }

  /* Short edges come shaded from the vertex shader; long ones are shaded here, per pixel. */
  int method = el_method();
  /* Only the whole-arc methods shade per edge (edge_highlight.vert). A constant false otherwise,
   * so the branches below fold away: llvmpipe would run them masked, el_arc twice. */
  bool per_edge = (method == EL_METHOD_WHOLE || method == EL_METHOD_PAPER) && edge_color.w > 0.5;
  ElArc g;
  float width, s;
  if (per_edge) {
    width = edge_arc.x;
    s = edge_arc.y;
  }
  else {
    g = el_arc(edge_dir, edge_n1, edge_n2, V);
    width = g.width;
    s = sqrt(dot(g.view, g.view)); /* |E x V| */
  }
  if (!(width > 0.0) || !(s > 0.0)) {
    discard;
  }

  /* The methods before issue 6 (a benchmark and test switch, edge_band.glsl): a band of
   * projected width w (pixels) centred on the edge line, the pixel's box-filtered coverage of it,
   * and the whole visible arc's mean colour. It is exact only if the band were centred and fell
   * within one pixel; measured against fillets it is off already at a pixel (BENCHMARKS.md). */
  float w_px = edge_radius * width / world_per_px;
  float t_wide = (method == EL_METHOD_PARTIAL || method == EL_METHOD_QUADRATURE) ? 1.0 : 0.0;
  float ramp = el_axial_ramp(s);
  vec4 result = vec4(0.0);
  if (t_wide < 1.0) {
    float cover = clamp(min(across + 0.5, 0.5 * w_px) - max(across - 0.5, -0.5 * w_px), 0.0, 1.0);
    if (method == EL_METHOD_PAPER) {
      /* A one-pixel line whatever the width, weighted by the whole arc's image width. */
      if (per_edge) {
        g = el_arc(edge_dir, edge_n1, edge_n2, V);
      }
      float full = edge_radius * length(el_arc_normal(g, 0.0) - el_arc_normal(g, g.alpha)) / world_per_px;
      cover = clamp(1.0 - abs(across), 0.0, 1.0) * min(full, 1.0);
    }
    float W = clamp(tint.w * cover, 0.0, 1.0) * ramp;
    if (W > 0.0) {
      vec3 col = per_edge ? edge_color.rgb : el_edge_colour(g, X, V, edge_dir);
      result = vec4(col * W, W);
    }
  }
  /* EdgeLight's method (docs/highlight_math.md, section 15), at every width: the band where the
   * fillet's image really lies, and each pixel shaded with the part of the arc whose image it
   * covers. A short edge's vertex-shaded colour is not used here: each pixel needs its own part
   * of the arc (about +8% on a dense 100k-edge render, for 2-3x less error at 1 px). */
  if (t_wide > 0.0) {
    if (per_edge) {
      g = el_arc(edge_dir, edge_n1, edge_n2, V);
    }
    vec3 P = el_safe_normalize(cross(el_safe_normalize(edge_dir), V));
    /* Which way P points on screen (the sign of its image along edge_screen's normal). */
    vec4 q0 = frame.projection * (frame.view * vec4(X, 1.0));
    vec4 q1 = frame.projection * (frame.view * vec4(X + P * world_per_px, 1.0));
    float side = dot((q1.xy / q1.w - q0.xy / q0.w) * frame.viewport.xy, edge_screen.zw) < 0.0 ? -1.0 : 1.0;
    vec2 ends = el_band_ends(g, P, edge_fold) * (side * edge_radius / world_per_px);
    float b0 = min(ends.x, ends.y), b1 = max(ends.x, ends.y);
    float pa = max(across - 0.5, b0), pb = min(across + 0.5, b1);
    float cover = clamp(pb - pa, 0.0, 1.0);
    /* The band's ends on the face this pixel lies over (band_ends.py): the pixel's centre on
     * the body's side of each cut. Two bands meeting on a cut then split its pixels exactly
     * (a filtered cut would leave a seam: bands blend over each other, they do not add); the
     * jittered samples antialias the cut as they do the outline. */
    bool on_f1 = across * edge_far.z >= 0.0;
    vec2 cut0 = on_f1 ? edge_cut0.xy : edge_cut0.zw, cut1 = on_f1 ? edge_cut1.xy : edge_cut1.zw;
    if (dot(pc - edge_screen.xy, cut0) < 0.0 || dot(pc - edge_far.xy, cut1) < 0.0) {
      discard;
    }
    float W = clamp(tint.w * cover, 0.0, 1.0) * ramp;
    vec4 wide = vec4(0.0);
    if (W > 0.0 && b1 > b0) {
      /* Fractions of the band from vis.lo's end. */
      float fa = (pa - ends.x) / (ends.y - ends.x), fb = (pb - ends.x) / (ends.y - ends.x);
      ElArc sub = el_sub_arc(g, clamp(min(fa, fb), 0.0, 1.0), clamp(max(fa, fb), 0.0, 1.0));
      vec3 col = method == EL_METHOD_QUADRATURE ? el_edge_colour_quadrature(sub, X, V) : el_edge_colour(sub, X, V, edge_dir);
      wide = vec4(col * W, W);
    }
    result = mix(result, wide, t_wide);
  }
  if (!(result.w > 0.0)) {
    discard;
  }
  out_color = result;
}
#endif
