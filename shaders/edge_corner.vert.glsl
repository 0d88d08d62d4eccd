/* Corner patch pass: one screen-space square per corner where three rounded convex (or three
 * concave) edges meet (addon/geometry/corner_patches.py), covering the image of the ball of radius r that
 * touches the three faces; the fragment shader finds the ball's point each pixel sees
 * (edge_corner.frag.glsl). corner.xy picks the square's corner (-1, +1), corner.z is the radius,
 * corner.w the fold: +1 convex (the ball under the faces), -1 concave (over them, in the air). */
void main()
{
  vec3 wv = (model * vec4(v, 1.0)).xyz;
  corner_vertex = wv;
  corner_n1 = el_transform_normal(model, m1);
  corner_n2 = el_transform_normal(model, m2);
  corner_n3 = el_transform_normal(model, m3);
  corner_faces_a = faces_a;
  corner_faces_b = faces_b;
  corner_uv = uv;   /* an image's UV at the vertex (batches.corner_uv), zero without one */
  corner_col = col; /* the colour attribute there (batches.corner_colors), zero without one */
  float r = corner.z * el_ball_scale(model, m1, m2, m3);
  corner_radius = r;
  corner_fold = corner.w;
  /* The ball's centre in world space, r under each face's plane (over it where the corner is
   * concave; the model may shear the angles between the faces, so it is solved here, not in
   * object space). */
  mat3 rows = transpose(mat3(corner_n1, corner_n2, corner_n3));
  float det = determinant(rows);
  bool persp = frame.eye.w > 0.5;
  vec3 centre = wv + (abs(det) > 1e-3 ? inverse(rows) * vec3(-r * corner.w) : vec3(0.0));
  corner_centre = centre;
  vec3 to_eye = persp ? frame.eye.xyz - centre : -frame.view_dir.xyz;
  float dist = persp ? length(to_eye) : 1.0;
  vec3 V = to_eye / max(length(to_eye), 1e-30);
  vec4 c = frame.projection * (frame.view * vec4(centre, 1.0));
  float world_per_px = dist / frame.camera.x;
  float r_px = r / world_per_px;
  /* Cull: a shallow corner, no face towards the eye (the patch's normals lie between the three),
   * the eye inside the ball or behind it, or a patch under half a pixel across, where the bands'
   * mitres already cover it to within that. */
  float f1 = dot(corner_n1, V), f2 = dot(corner_n2, V), f3 = dot(corner_n3, V);
  if (!(abs(det) > 1e-3) || max(f1, max(f2, f3)) <= 0.0 || c.w <= 0.0 || (persp && dist <= 1.5 * r) ||
      tint.w * r_px < 0.5) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  /* A sphere's image is an ellipse stretched away from the view axis by up to 1 / cos of the angle
   * off it, and r / sqrt(d^2 - r^2) wide at distance d; a pixel and a half more for the
   * fragment's sub-samples and the jitter. */
  float off_axis = persp ? max(dot(V, -frame.view_dir.xyz), 0.3) : 1.0;
  float grow = persp ? dist / sqrt(max(dist * dist - r * r, 1e-30)) : 1.0;
  float half_px = r_px * grow / off_axis + 1.5;
  vec2 ndc = c.xy / c.w + corner.xy * half_px * 2.0 * frame.viewport.zw;
  /* The world point on the plane through the centre square to the view axis that this corner of
   * the square shows: the same clip w at every corner, so it interpolates linearly. */
  vec4 p = inverse(frame.projection) * vec4(ndc * c.w, c.z, c.w);
  corner_point = (inverse(frame.view) * vec4(p.xyz / p.w, 1.0)).xyz;
  /* Depth: the vertex pulled toward the eye by more than the fragment's own visibility bias
   * anywhere on the square (the faces' planes through it tilt by at most the steepest facing
   * face's slope), so hidden squares fail the early depth test and no visible pixel does. */
  float cmin = 1.0;
  cmin = f1 > 0.0 ? min(cmin, f1) : cmin;
  cmin = f2 > 0.0 ? min(cmin, f2) : cmin;
  cmin = f3 > 0.0 ? min(cmin, f3) : cmin;
  cmin = max(0.5 * cmin, 1.0 / 16.0);
  float slope = sqrt(max(1.0 - cmin * cmin, 0.0)) / cmin;
  vec3 to_v = persp ? frame.eye.xyz - wv : -frame.view_dir.xyz;
  float dist_v = persp ? length(to_v) : 1.0;
  float pull = 2.0 * ((half_px + 1.0) * (dist_v / frame.camera.x) * (slope + 0.05) + 1e-5 * dist_v) + r;
  vec4 cp = frame.projection * (frame.view * vec4(wv + to_v / max(length(to_v), 1e-30) * pull, 1.0));
  float z = (!persp || pull < 0.5 * dist_v) && cp.w > 0.0 ? max(cp.z / cp.w, -1.0) : -1.0;
  gl_Position = vec4(ndc * c.w, z * c.w, c.w);
}
