/* The edge pass's earlier methods, kept for the benchmarks and tests that compare against them
 * (bench/shaders/edge_methods.json adds these files to the add-on's edge_highlight program,
 * this one before edge_shading.glsl; bench/edge_methods.py and native/tools/render_passes.cpp
 * build it). The add-on ships one method, EdgeLight's (shaders/edge_band_extent.glsl,
 * edge_band_pixel.glsl).
 *
 * EL_EDGE_METHOD, defined when the program is built: a compile-time constant, not a uniform:
 * llvmpipe would run every method's code in every fragment, masked (it doubled the pass). */
#define EL_METHOD_PARTIAL 0    /* EdgeLight's: true band position, each pixel its own part of the arc */
#define EL_METHOD_WHOLE 1      /* band centred on the line, the whole visible arc's mean everywhere */
#define EL_METHOD_PAPER 2      /* the paper's 1-pixel line, W = K r |P.(N1 - N2)| / d, whole-arc mean */
#define EL_METHOD_QUADRATURE 3 /* as PARTIAL, the kernel by brute-force quadrature (no table) */

#ifndef EL_EDGE_METHOD
#define EL_EDGE_METHOD EL_METHOD_PARTIAL
#endif

/* Edge quads fitted to where the band lies (as the add-on draws them); false only to test that
 * against quads symmetric about the line. */
#ifndef EL_TIGHT_QUADS
#define EL_TIGHT_QUADS true
#endif

/* The whole-arc methods shade edges shorter than this on screen once per edge, in the vertex
 * shader: their colour barely changes along them. */
#define EL_SHADE_PER_EDGE_BELOW_PX 16.0

vec3 el_arc_normal(ElArc g, float u); /* edge_band.glsl */

/* Brute-force mean of max(N.D, 0)^n over the visible window, weighted by projected width
 * (sin x): the per-pixel reference integral, free of the table and the closed form. */
float el_arc_mean_quadrature(ElArc g, vec3 D, float n)
{
  const int steps = 256;
  float len = g.vis.hi - g.vis.lo;
  if (!(len > 0.0)) {
    return 0.0;
  }
  vec3 Dn = el_safe_normalize(D);
  float num = 0.0, den = 0.0;
  for (int k = 0; k < steps; k++) {
    float t = (float(k) + 0.5) / float(steps) * len;
    float w = sin(g.vis.from_lower + t);
    float c = max(dot(el_arc_normal(g, g.vis.lo + t), Dn), 0.0);
    num += w * pow(c, n);
    den += w;
  }
  return den > 0.0 ? num / den : 0.0;
}

/* The quadrature method is EdgeLight's with this kernel: el_edge_colour (edge_shading.glsl,
 * which follows) then takes its arc means from it. */
#if EL_EDGE_METHOD == EL_METHOD_QUADRATURE
#define el_arc_mean(g, D, E, n) el_arc_mean_quadrature(g, D, n)
#endif
