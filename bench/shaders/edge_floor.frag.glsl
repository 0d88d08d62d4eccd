/* The edge pass's floor (EL_EDGE_FLOOR): the same quads, vertex shader and depth test, and a
 * fragment shader that does next to nothing: what the pass costs before any shading
 * (BENCHMARKS.md). It reads every input the pass binds, so the same uniforms can be set, and
 * writes an invisible 1e-20 of them. Without EL_EDGE_FLOOR, the add-on's main follows
 * (edge_methods.json puts shaders/edge_highlight.frag.glsl between this file and
 * edge_floor_end.glsl). */
#ifdef EL_EDGE_FLOOR
void main()
{
  vec4 inputs = vec4(edge_point, edge_radius) + EL_TABLE_M_MAX + base_color + spec_color + tint +
                texelFetch(cos_power_table, ivec2(0), 0).r + texelFetch(surface_depth, ivec2(0), 0).r +
                texelFetch(surface_color, ivec2(0), 0).r;
#ifdef EL_EDGE_IDS
  inputs += texelFetch(surface_id, ivec2(0), 0).r + edge_faces.x + instance_id;
#endif
  out_color = inputs * 1e-20;
}
#else
