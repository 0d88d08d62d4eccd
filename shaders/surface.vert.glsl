/* Surface pass: world position and normal per corner. */
void main()
{
  vec4 world = model * vec4(pos, 1.0);
  world_pos = world.xyz;
  world_nor = el_transform_normal(model, nor);
  vec4 v = frame.view * world;
  view_depth = -v.z;
  gl_Position = frame.projection * v;
}
