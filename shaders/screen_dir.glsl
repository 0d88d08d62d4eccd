/* The image of world direction d at the point whose clip position is c, in pixels (up to a
 * positive factor): the derivative of the perspective divide. Shared by the edge pass's quads
 * and the surface pass's rounded outline. */
vec2 el_screen_dir(vec3 d, vec4 c)
{
  vec4 dc = frame.projection * (frame.view * vec4(d, 0.0));
  return (dc.xy * c.w - c.xy * dc.w) * frame.viewport.xy;
}
