/* Where a rounded edge's band lies across its projected edge line, and which part of its arc
 * one pixel sees (docs/highlight_math.md, section 15). Needs highlight_arc.glsl.
 *
 * Methods (EL_EDGE_METHOD, defined when the program is built; passes/frame.py reads
 * EDGELIGHT_EDGE_METHOD): a debug and benchmark switch, so the ground-truth benchmark can render
 * the earlier methods with the same shaders. A compile-time constant, not a uniform: llvmpipe
 * would run every method's code in every fragment, masked (it doubled the pass). */
#define EL_METHOD_PARTIAL 0    /* default: true band position, each pixel its own part of the arc */
#define EL_METHOD_WHOLE 1      /* until issue 6: band centred on the line, whole-arc mean everywhere */
#define EL_METHOD_PAPER 2      /* seed 000: a 1-pixel line, W = K r |P.(N1 - N2)| / d, whole-arc mean */
#define EL_METHOD_QUADRATURE 3 /* as PARTIAL, the kernel by brute-force quadrature (no table) */

#ifndef EL_EDGE_METHOD
#define EL_EDGE_METHOD EL_METHOD_PARTIAL
#endif

/* Edge quads fitted to where the band lies (edge_highlight.vert); false only to test that
 * against quads symmetric about the line. */
#ifndef EL_TIGHT_QUADS
#define EL_TIGHT_QUADS true
#endif

int el_method()
{
  return EL_EDGE_METHOD;
}

/* Arc normal at angle u from N1. */
vec3 el_arc_normal(ElArc g, float u)
{
  return cos(u) * g.a1 + sin(u) * g.b1;
}

/* The visible band across the edge line, in units of r along P = E x V / |E x V|: the images of
 * the visible arc's ends vis.lo and vis.hi (in that order; either may be the larger). A circular
 * fillet of radius r tangent to both faces has its axis at c - fold r C, C = (N1 + N2) / (1 + N1.N2),
 * and its point of normal N at axis + fold r N: it projects to fold r P.(N - C) from the sharp
 * edge's line. fold is +1 on a convex edge (the axis inside the solid) and -1 on a concave one
 * (the axis in the air, the fillet filling the corner): the same arc of normals, laid across the
 * line the other way round. Near N1 = -N2 the fillet's tangent points run off to infinity; the
 * denominator is floored (the band is then clamped by the quad anyway). */
vec2 el_band_ends(ElArc g, vec3 P, float fold)
{
  vec3 C = (g.a1 + el_arc_normal(g, g.alpha)) / max(1.0 + cos(g.alpha), 1e-3);
  return fold * vec2(dot(P, el_arc_normal(g, g.vis.lo) - C), dot(P, el_arc_normal(g, g.vis.hi) - C));
}

/* The part of the visible arc whose image is the fraction [fa, fb] (0 = vis.lo's end, 1 =
 * vis.hi's) of the band. P.N is linear in cos x along the visible window, x = the angle from its
 * lower horizon (section 2: |dh/du| = r sin x), so the fraction f lies at
 * cos x = cos x_lo - f (cos x_lo - cos x_hi). Returns the arc with that sub-window as its visible
 * part: el_arc_mean then integrates over it alone, weighted by projected width as before. */
ElArc el_sub_arc(ElArc g, float fa, float fb)
{
  float x_lo = g.vis.from_lower, x_hi = EL_PI - g.vis.to_upper;
  float c_lo = cos(x_lo), c_hi = cos(x_hi);
  float xa = acos(clamp(c_lo - fa * (c_lo - c_hi), -1.0, 1.0));
  float xb = acos(clamp(c_lo - fb * (c_lo - c_hi), -1.0, 1.0));
  xa = clamp(xa, x_lo, x_hi);
  xb = clamp(xb, xa, x_hi);
  ElArc s = g;
  s.vis.lo = g.vis.lo + (xa - x_lo);
  s.vis.hi = g.vis.lo + (xb - x_lo);
  s.vis.from_lower = xa;
  s.vis.to_upper = EL_PI - xb;
  s.width = el_window_width(s.vis);
  return s;
}

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

/* el_edge_colour (edge_shading.glsl) with the quadrature kernel. */
vec3 el_edge_colour_quadrature(ElArc g, vec3 X, vec3 V)
{
  float n = spec_color.w;
  vec3 col = frame.ambient.rgb * base_color.rgb;
  int count = int(frame.camera.y + 0.5);
  for (int i = 0; i < count; i++) {
    vec3 L, E;
    light_at(i, X, L, E);
    vec3 H = el_safe_normalize(L + V);
    float spec = length(H) > 0.0 ? el_arc_mean_quadrature(g, H, n) : 0.0;
    float diff = el_arc_mean_quadrature(g, L, 1.0);
    col += E * (base_color.rgb * (diff / 3.14159265) + tint.rgb * spec_color.rgb * blinn_norm(n) * spec);
  }
  return col;
}
