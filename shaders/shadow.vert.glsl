/* Shadow pass: a surface seen from a light (shaders/shadows.glsl). The depth stored is clip z
 * for an orthographic layer (linear in distance) and clip w, the distance along the layer's
 * axis, for a perspective one: both vary linearly over a triangle, so the interpolation is
 * exact on any rasteriser. */
void main()
{
  vec4 clip = light_matrix * (model * vec4(pos, 1.0));
  bool ortho = light_matrix[0][3] == 0.0 && light_matrix[1][3] == 0.0 && light_matrix[2][3] == 0.0;
  light_depth = ortho ? clip.z : clip.w;
  shadow_uv = uv; /* an alpha-cut surface's UV (EL_SHADOW_CUT), zero otherwise (batches.slot_uv) */
  gl_Position = clip;
}
