#ifdef EL_EDGE_IDS
/* View depth where the ray through pixel centre pc meets the plane through world point X with
 * world normal n spanned by edge_dir and the in-plane direction across it; -1 where the plane is
 * seen edge-on. The ray is where two planes of the projection meet (clip x = ndc.x clip w, clip
 * y = ndc.y clip w), so any projection (perspective or orthographic, shifted, jittered) works. */
float el_plane_depth(vec2 pc, vec3 X, vec3 n)
{
  vec2 ndc = pc * frame.viewport.zw * 2.0 - 1.0;
  mat4 P = frame.projection;
  vec4 r0 = vec4(P[0][0], P[1][0], P[2][0], P[3][0]), r1 = vec4(P[0][1], P[1][1], P[2][1], P[3][1]);
  vec4 r3 = vec4(P[0][3], P[1][3], P[2][3], P[3][3]);
  vec4 a = r0 - ndc.x * r3, b = r1 - ndc.y * r3;
  vec3 nv = cross(mat3(frame.view) * edge_dir, mat3(frame.view) * cross(n, edge_dir));
  vec4 c = vec4(nv, -dot(nv, (frame.view * vec4(X, 1.0)).xyz));
  vec3 bc = cross(b.xyz, c.xyz);
  float det = dot(a.xyz, bc);
  if (!(abs(det) > 1e-6 * length(a.xyz) * length(bc))) {
    return -1.0;
  }
  vec3 p = -(a.w * bc + b.w * cross(c.xyz, a.xyz) + c.w * cross(a.xyz, b.xyz)) / det;
  return -p.z;
}
#endif

/* Edge highlight pass: which pixels of the quad may show the band (visibility against the surface
 * pass), and what each shows of it (edge_band_pixel.glsl): the rounded edge's shading integrated
 * over the part of its arc the pixel sees, weighted by the pixel's coverage of the projected band.
 * Output is premultiplied (W Is, W). */
void main()
{
  vec2 pc = gl_FragCoord.xy;
  vec3 X = edge_point;
  bool persp = frame.eye.w > 0.5;
  vec3 to_eye = persp ? frame.eye.xyz - X : -frame.view_dir.xyz;
  float dist = persp ? el_safe_length(to_eye) : 1.0;
  vec3 V = el_safe_normalize(to_eye);

#ifdef EL_BASE_TEXTURE
  float along = clamp(edge_t, 0.0, 1.0);
  el_band_material = el_material_at(mix(edge_uv.xy, edge_uv.zw, along), mix(edge_col0, edge_col1, along));
#endif
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
  /* Background: a fillet lies within its part's outline (a convex one inside the solid, a
   * concave one over its faces), so the band shows past it only in the outline's own pixels.
   * The surface pass draws that outline rounded (rounded_outline.glsl): a silhouette's strip
   * moves it in by up to 0.41 r, and past a corner it is the ball's circle, which the bands'
   * square ends overhang. From a radius of 2 pixels on, where that reaches past a pixel, no band
   * is laid over the background: a silhouette's band changes only the face its pixel's samples
   * show (el_silhouette_band below), since its horizon end is that outline. */
  bool past_outline = !(id.y > 0.0);
  bool wide = edge_radius > 2.0 * world_per_px;
#ifdef EL_FACES_UNDER
  bool as_change = edge_far.w < -0.5 && base_color.a >= 1.0;
#else
  bool as_change = false; /* a toon band blends as a layer */
#endif
  if (past_outline && (!el_outline_fringe(ivec2(pc)) || (wide && !as_change))) {
    discard;
  }
  float bias = own ? 3.0e38 : 0.5 * world_per_px + 1e-5 * dist;
  /* Over another face of its own object: the band lies on the plane of the face on this
   * pixel's side (a fillet runs on across a smooth patch's facets, as far as the radius clamp
   * lets it; the plane through the edge square to the face's mean shading normal along the
   * edge, within 20 degrees of its own), so that plane's depth
   * here is what a surface must not be nearer than; the edge line's depth would hide wide bands
   * on facets that turn toward the eye. Over another object the edge line's depth decides, as a
   * silhouette face's plane continued past the outline can lie far behind it. */
  vec3 n_here = across * edge_far.z >= 0.0 ? edge_n1 : edge_n2;
  if (dot(n_here, V) <= 0.0) {
    n_here = across * edge_far.z >= 0.0 ? edge_n2 : edge_n1; /* a silhouette: its one face in view */
  }
  bool same_object = id.x == instance_id && id.y > 0.0;
  float plane_depth = own || !same_object || dot(n_here, V) <= 0.0 ? -1.0 : el_plane_depth(pc, X, n_here);
  /* The pixel's centre shows one of the edge's faces, or a facet in its plane
   * (el_silhouette_band). */
  bool on_faces = own || (plane_depth > 0.0 && inv_surface > 0.0 && abs(plane_depth - 1.0 / inv_surface) <= bias);
  if (plane_depth > 0.0) {
    edge_depth = plane_depth;
  }
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

  float share1, pixel1;
  vec4 result = el_band_pixel(pc, X, V, world_per_px, across, share1, pixel1);
  if (!(result.w > 0.0)) {
    discard;
  }
#ifdef EL_FACES_UNDER
  /* Blinn-Phong materials: the band replaces the faces under it, not the pixel's mean (a toon
   * surface's faces are not shaded by el_face_colour, so its bands blend over the mean). */
#ifdef EL_EDGE_IDS
  /* At a silhouette, where the pixel's centre shows one of the edge's faces, each sample shows
   * the face or what lies past the outline: the band changes the face's part alone. Both faces
   * lie on N1's side of the line there. Over a third face of its object (a wide band runs over
   * it) or past the outline (where the samples may all miss the face) it stays a layer. */
  if (edge_far.w < -0.5 && base_color.a >= 1.0 && on_faces) {
    out_color = el_silhouette_band(result, X, V, pixel1);
    return;
  }
  /* A wide band's pixel past the outline: its samples show the front face within the band's
   * horizon end, where the surface pass moved the outline to, so W is no more than they cover. */
  if (past_outline && wide) {
    out_color = el_silhouette_band(result, X, V, 1.0);
    return;
  }
#endif
  vec3 far;
  float near_share;
  result.rgb += el_faces_under_band(X, V, pixel1, share1, result.w, far, near_share);
#ifdef EL_EDGE_IDS
  /* Where the line crosses a pixel that shows only the two faces, the pixel is drawn whole: the
   * band and what it leaves of each face, the face at the centre in the first sample's colour
   * there (a smooth face's shading varies across it), the sliver across the line in its face's
   * colour along the edge. The samples' mean of the sharp step would add their noise, as large
   * as the step, to a picture in which the fillet leaves no step. */
  if (near_share < 1.0 && base_color.a >= 1.0) {
    float c_min = max(min(abs(dot(normalize(edge_n1), V)), abs(dot(normalize(edge_n2), V))), 1.0 / 16.0);
    float slope = sqrt(max(1.0 - c_min * c_min, 0.0)) / c_min;
    if (el_only_edge_faces(ivec2(pc), 1.0 / inv_surface, slope, world_per_px)) {
      vec3 centre = texelFetch(surface_color, ivec2(pc), 0).rgb;
      result = vec4(result.rgb + (1.0 - result.w) * mix(far, centre, near_share), 1.0);
    }
  }
#endif
#endif
  out_color = result;
}
