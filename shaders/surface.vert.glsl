/* Surface pass: world position and normal per corner. */
void main()
{
  vec4 world = model * vec4(pos, 1.0);
  world_pos = world.xyz;
  world_nor = el_transform_normal(model, nor);
  vec4 v = frame.view * world;
  view_depth = -v.z;
  gl_Position = frame.projection * v;
  surface_uv = uv;   /* zero where the slot draws no image (batches.slot_uv) */
  surface_col = col; /* the colour attribute its node program reads, zero without one (batches.slot_colors) */
  /* A Normal Map's tangent (batches.slot_tangents), turned with the object as EEVEE turns it;
   * the bitangent's sign flips with a mirroring transform, as EEVEE's ObjectInfo sign does. */
  surface_tan = vec4(mat3(model) * tan.xyz, tan.w * (determinant(mat3(model)) < 0.0 ? -1.0 : 1.0));
  /* Three vertices per triangle, in order, whether all are drawn or an indexed subset
   * (passes/batches.py): the triangle's number in its slot's batch. */
  surface_tri = float(gl_VertexID / 3);
#ifdef EL_ROUNDED_OUTLINE
  outline_strip0 = el_outline_strips(gl_VertexID / 3, gl_Position, outline_dist, outline_along, outline_strip1,
                                     outline_length, outline_end0, outline_end1);
  outline_ball = el_outline_corners(gl_VertexID / 3, gl_Position, outline_corner0, outline_corner1, outline_corner2,
                                    outline_corner3);
#endif
}
