/* Where a rounded edge's band lies across its projected edge line, and which part of its arc
 * one pixel sees (docs/highlight_math.md, section 15). Needs highlight_arc.glsl. */

/* The square pixel's footprint across a line of unit screen normal n (docs/highlight_math.md,
 * "The pixel's footprint across the line"): its extent across the line is the sum of two uniform
 * spans, a = max(|n.x|, |n.y|) and b = min(|n.x|, |n.y|), a trapezoid 1 to sqrt(2) wide. It is
 * taken as boxes of width a centred on the midpoints of `count` equal parts of b (the midpoint
 * rule: the trapezoid's ramps become stairs of at most EL_FOOTPRINT_STEP), one box at the centre
 * where b is that small (an axis-aligned line's exact box). Returns (a, b, count). */
const float EL_FOOTPRINT_STEP = 0.18;

vec3 el_footprint(vec2 n)
{
  float a = max(abs(n.x), abs(n.y)), b = min(abs(n.x), abs(n.y));
  return vec3(a, b, clamp(ceil(b / EL_FOOTPRINT_STEP), 1.0, 4.0));
}

/* The centre of box k of the footprint fp, from the pixel's centre across the line. */
float el_footprint_box(vec3 fp, int k)
{
  return ((float(k) + 0.5) / fp.z - 0.5) * fp.y;
}

/* How far the footprint reaches across the line from the pixel's centre. */
float el_footprint_reach(vec2 n)
{
  vec3 fp = el_footprint(n);
  return 0.5 * fp.x - el_footprint_box(fp, 0);
}

/* The rounded edge's frame at line parameter t (0 at its first end, 1 at its second): the
 * normals its arc runs between there and the fillet's axis (docs/highlight_math.md, "The arc's
 * ends on smooth-shaded faces"). A smooth face's shading normal changes along the edge (Blender
 * interpolates its corner normals), so the arc does: N_i(t) = normalize(edge_n_i + (t - 1/2)
 * edge_turn_i). A rolling ball touches each face where the face's normal points at its centre,
 * so its axis is square to both normals: it is taken as the edge's direction turned as N1 x N2
 * turns away from its value at the mean normals (el_arc projects the normals square to it).
 * Where neither normal turns, the frame is the edge's own, exactly. */
void el_edge_frame_at(float t, out vec3 E, out vec3 n1, out vec3 n2)
{
  E = edge_dir;
  n1 = edge_n1;
  n2 = edge_n2;
  if (edge_turn1 != vec3(0.0) || edge_turn2 != vec3(0.0)) {
    float d = t - 0.5;
    n1 = el_safe_normalize(edge_n1 + d * edge_turn1);
    n2 = el_safe_normalize(edge_n2 + d * edge_turn2);
    /* Over |N1 x N2| = sin(fold) at most, so the turn the cross product gives the axis fades
     * out on folds under about twice the normals' turn (or within it of 180 degrees), where it
     * is ill-conditioned and the band thin: there the axis stays near the edge. */
    vec3 a = cross(edge_n1, edge_n2);
    float den = max(length(a), 2.0 * max(length(edge_turn1), length(edge_turn2)));
    float sg = dot(a, edge_dir) < 0.0 ? -1.0 : 1.0;
    E = el_safe_normalize(el_safe_normalize(edge_dir) + (cross(n1, n2) - a) * (sg / den));
  }
}

void el_edge_frame(float t, out vec3 E, out vec3 n1, out vec3 n2)
{
  el_edge_frame_at(clamp(t, 0.0, 1.0), E, n1, n2);
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
