/* The rounded-edge integral of one pixel (docs/highlight_math.md): the float path of
 * native/src/highlight_arc.cpp and the table lookup of highlight_table.cpp, step for step, so
 * the native tests of that code speak for this shader. Needs the sampler cos_power_table and the
 * table's el_table_info fixed when the program is built (shaders/passes.json: EL_TABLE_LAYOUT,
 * EL_TABLE_M_MAX, EL_TABLE_WARP_C): llvmpipe runs fragments as SIMD lanes with masks and pays for
 * both sides of a branch on a uniform, so the lookup code of the other layouts must not be in the
 * program at all, and constants are no push constants (Vulkan and Metal guarantee 128 bytes). */
#ifndef EL_TABLE_LAYOUT
#define EL_TABLE_LAYOUT 2 /* EL_TABLE_BICUBIC, the library's default */
#endif
#if !defined(EL_TABLE_M_MAX) || !defined(EL_TABLE_WARP_C)
#error "the highlight table's m_max and warp_c are defined when the program is built (shaders/passes.json)"
#endif
#define EL_PI 3.14159265358979
#define EL_HALF_PI 1.57079632679490
#define EL_ANTIPARALLEL_BAND 1e-6
#define EL_AXIAL_RAMP_S0 1e-2
#define EL_GAUSS_SPAN 4.0

/* 8-point Gauss-Legendre on [-1, 1], mirrored pairs. */
const vec4 el_gl_x = vec4(0.183434642495649805, 0.525532409916328986, 0.796666477413626740, 0.960289856497536232);
const vec4 el_gl_w = vec4(0.362683783378361983, 0.313706645877887287, 0.222381034453374471, 0.101228536290376259);

float el_max3(vec3 v)
{
  return max(abs(v.x), max(abs(v.y), abs(v.z)));
}

vec3 el_safe_normalize(vec3 v)
{
  float s = el_max3(v);
  if (!(s > 0.0)) {
    return vec3(0.0);
  }
  v /= s;
  return v * inversesqrt(dot(v, v));
}

float el_safe_length(vec3 v)
{
  float s = el_max3(v);
  if (!(s > 0.0)) {
    return 0.0;
  }
  v /= s;
  return s * sqrt(dot(v, v));
}

/* v * 2^-e with the largest component in [0.5, 1): exact, so directions keep every bit. As
 * frexp and ldexp (GLSL 4.00), from the float's bits: 2^-e in two halves, each a normal float. */
vec3 el_pow2_scale(vec3 v)
{
  float m = el_max3(v);
  if (!(m > 0.0) || isinf(m)) {
    return v; /* frexp: e = 0 */
  }
  if (m < 1.17549435e-38) {      /* subnormal: its exponent field is 0 */
    v *= 18446744073709551616.0; /* 2^64, exact */
    m *= 18446744073709551616.0;
  }
  int e = int((floatBitsToUint(m) >> 23) & 0xffu) - 126;
  int half_e = e / 2;
  v *= uintBitsToFloat(uint(127 - half_e) << 23);
  return v * uintBitsToFloat(uint(127 - (e - half_e)) << 23);
}

/* a*b - c*d with a single rounding (Kahan): tiny cross products of unit vectors stay exact. */
float el_diff_of_products(float a, float b, float c, float d)
{
#if __VERSION__ >= 400
  float w = c * d;
  float e = fma(-c, d, w);
  float f = fma(a, b, -w);
  return f + e;
#else
  return a * b - c * d; /* GLSL 3.30 (OpenGL 3.3) has no fma: two roundings */
#endif
}

vec3 el_cross_exact(vec3 a, vec3 b)
{
  return vec3(el_diff_of_products(a.y, b.z, a.z, b.y),
              el_diff_of_products(a.z, b.x, a.x, b.z),
              el_diff_of_products(a.x, b.y, a.y, b.x));
}

float el_log1p(float x)
{
  float u = 1.0 + x;
  return u == 1.0 ? x : log(u) * x / (u - 1.0);
}

/* ln cos t as log1p(-2 sin^2(t/2)): relative accuracy near t = 0 (cos t rounds to a multiple
 * of 6e-8 there, and cos^n multiplies that by n), one branch-free expression (a piecewise
 * version runs every piece in llvmpipe's SIMD lanes). */
float el_log_cos(float t)
{
  float s = sin(0.5 * t);
  float x = -2.0 * s * s;
  return x > -1.0 ? el_log1p(x) : -1e30;
}

float el_cos_pow(float t, float n)
{
  return exp(n * el_log_cos(t));
}

/* Weights of the cubic Lagrange polynomial through nodes 0, 1, 2, 3 at s in [0, 3]. */
vec4 el_lagrange4(float s)
{
  float a = s, b = s - 1.0, c = s - 2.0, d = s - 3.0;
  return vec4(-(b * c * d) * (1.0 / 6.0), (a * c * d) * 0.5, -(a * b * d) * 0.5, (a * b * c) * (1.0 / 6.0));
}

/* EL_TABLE_BICUBIC's phi_end(m) = ((2/pi)^6 + m^3/c^6)^(-1/6): smooth in ln m. */
float el_bicubic_phi_end(float m, float c)
{
  float k = 0.405284735; /* (2/pi)^2 */
  float r = m / (c * c);
  return exp(log(k * k * k + r * r * r) * (-1.0 / 6.0));
}

/* Table row for exponent m: (first row of the stencil, y minus it, texel per radian, output
 * scale). EL_TABLE_LAYOUT: 0 paper, 1 warped, 2 bicubic. */
vec4 el_table_row(float m)
{
  ivec2 size = textureSize(cos_power_table, 0);
  float last_row = float(size.y - 1);
  float y, phi_to_texel, out_scale;
  if (EL_TABLE_LAYOUT == 0) { /* EL_TABLE_PAPER */
    y = m - 1.0;
    phi_to_texel = float(size.x - 1) / 1.57079632679;
    out_scale = 1.0;
  }
  else {
    y = log(m) / log(EL_TABLE_M_MAX) * last_row;
    float phi_end = EL_TABLE_LAYOUT == 2 ? min(1.57079632679, el_bicubic_phi_end(m, EL_TABLE_WARP_C))
                                         : min(1.57079632679, EL_TABLE_WARP_C / sqrt(m));
    phi_to_texel = float(size.x - 1) / phi_end;
    out_scale = 1.0 / sqrt(m);
  }
  y = clamp(y, 0.0, last_row);
  float j = EL_TABLE_LAYOUT == 2 ? clamp(floor(y) - 1.0, 0.0, last_row - 3.0) : min(floor(y), last_row - 1.0);
  return vec4(j, y - j, phi_to_texel, out_scale);
}

/* EL_TABLE_BICUBIC: 4 x 4 texels, cubic Lagrange in both directions. */
float el_table_lookup_bicubic(vec4 row, float x, float last)
{
  float i = clamp(floor(x) - 1.0, 0.0, last - 3.0);
  vec4 wx = el_lagrange4(x - i);
  vec4 wy = el_lagrange4(row.y);
  int k = int(i), j = int(row.x);
  float v = 0.0;
  for (int r = 0; r < 4; ++r) {
    float p0 = texelFetch(cos_power_table, ivec2(k, j + r), 0).r;
    float p1 = texelFetch(cos_power_table, ivec2(k + 1, j + r), 0).r;
    float p2 = texelFetch(cos_power_table, ivec2(k + 2, j + r), 0).r;
    float p3 = texelFetch(cos_power_table, ivec2(k + 3, j + r), 0).r;
    float s = wx.x * p0 + wx.y * p1 + wx.z * p2 + wx.w * p3;
    v += wy[r] * s;
  }
  return v;
}

float el_table_lookup(vec4 row, float phi)
{
  float last = float(textureSize(cos_power_table, 0).x - 1);
  float x = min(abs(phi) * row.z, last);
  if (EL_TABLE_LAYOUT == 2) {
    return sign(phi) * el_table_lookup_bicubic(row, x, last) * row.w;
  }
  float i = min(floor(x), last - 1.0);
  float fx = x - i;
  int k = int(i), j = int(row.x);
  float a0 = texelFetch(cos_power_table, ivec2(k, j), 0).r;
  float a1 = texelFetch(cos_power_table, ivec2(k + 1, j), 0).r;
  float b0 = texelFetch(cos_power_table, ivec2(k, j + 1), 0).r;
  float b1 = texelFetch(cos_power_table, ivec2(k + 1, j + 1), 0).r;
  float v0 = a0 + fx * (a1 - a0);
  float v1 = b0 + fx * (b1 - b0);
  float v = v0 + row.y * (v1 - v0);
  return sign(phi) * v * row.w;
}

/* Part of the arc [0, alpha] inside a half circle: lo, hi (empty if lo > hi) and the distances
 * of the ends from the window's lower and upper horizons. */
struct ElWindow {
  float lo, hi, from_lower, to_upper;
};

/* The window's horizons as principal angles in (-pi, pi]: `lower` (where it starts turning
 * positively) and `upper` = lower + pi. */
ElWindow el_window_on_arc(float lower, float upper, float alpha)
{
  ElWindow w;
  if (lower > 0.0) {
    w.lo = lower;
    w.from_lower = 0.0;
    w.hi = alpha;
    w.to_upper = (lower + EL_PI) - alpha;
    return w;
  }
  w.lo = 0.0;
  w.from_lower = -lower;
  float up = (upper < -EL_HALF_PI) ? upper + 2.0 * EL_PI : max(upper, 0.0);
  if (up < alpha) {
    w.hi = up;
    w.to_upper = 0.0;
  }
  else {
    w.hi = alpha;
    w.to_upper = up - alpha;
  }
  return w;
}

float el_window_width(ElWindow w)
{
  if (w.lo > w.hi) {
    return 0.0;
  }
  float len = w.hi - w.lo;
  return 2.0 * sin(0.5 * len) * sin(min(w.from_lower, w.to_upper) + 0.5 * len);
}

/* View weight cos(u - u_v) along [a, b], measured from the nearer horizon of the visible window. */
struct ElWeight {
  float offset;
  bool from_lower;
  float len;
};

float el_weight_at(ElWeight w, float t)
{
  return sin(w.from_lower ? w.offset + t : w.offset + (w.len - t));
}

ElWeight el_weight_on(ElWindow vis, float a, float b)
{
  float off_lo = vis.from_lower + (a - vis.lo);
  float off_hi = vis.to_upper + (vis.hi - b);
  ElWeight w;
  w.from_lower = off_lo <= off_hi;
  w.offset = w.from_lower ? off_lo : off_hi;
  w.len = b - a;
  return w;
}

struct ElArc {
  float alpha;  /* arc length */
  vec2 view;    /* V in the arc frame; |view| = |E x V| */
  ElWindow vis; /* visible part */
  float width;  /* its projected width, unit radius */
  float hidden; /* projected width of the hidden part */
  vec3 a1, b1;  /* arc frame: N1 direction, and ez x a1 */
};

/* E, n1, n2, V need not be unit. */
ElArc el_arc(vec3 edge, vec3 n1, vec3 n2, vec3 V)
{
  ElArc g;
  vec3 E = el_safe_normalize(edge);
  n1 = el_pow2_scale(n1);
  n2 = el_pow2_scale(n2);
  vec3 p1 = n1 - E * dot(E, n1), p2 = n2 - E * dot(E, n2);
  float l1 = el_safe_length(p1), l2 = el_safe_length(p2);
  /* Orientation and arc length from (N1 x N2).E of the unrounded inputs: a tiny arc keeps its
   * relative accuracy. */
  float det = dot(el_cross_exact(n1, n2), E) / l1 / l2;
  float dot12 = dot(p1 / l1, p2 / l2);
  vec3 ez = E;
  if (dot12 < 0.0 && abs(det) <= EL_ANTIPARALLEL_BAND) {
    g.alpha = EL_PI;
  }
  else {
    if (det < 0.0) {
      ez = -E;
    }
    g.alpha = atan(abs(det), dot12);
  }
  g.a1 = p1 / l1;
  g.b1 = cross(ez, g.a1);
  g.view = vec2(dot(V, g.a1), dot(V, g.b1));
  /* Horizons (N.V = 0): the view turned by -90 and +90 degrees; the hidden window is the
   * visible one with the two swapped. */
  float h_lo = atan(-g.view.x, g.view.y), h_hi = atan(g.view.x, -g.view.y);
  g.vis = el_window_on_arc(h_lo, h_hi, g.alpha);
  g.width = el_window_width(g.vis);
  g.hidden = el_window_width(el_window_on_arc(h_hi, h_lo, g.alpha));
  return g;
}

/* Mean of max(N.D, 0)^n over the visible arc, weighted by projected width. d: D in the arc frame
 * (|D| = d_len), d_axial = (D.E)^2 / (D.D). */
float el_arc_kernel(ElArc g, vec2 d, float d_len, float d_axial, float n)
{
  float dlen = sqrt(dot(d, d));
  if (g.vis.lo > g.vis.hi || !(dlen > 0.0)) {
    return 0.0;
  }
  /* Lit window from u_d -+ 90 degrees (its edges need only be roughly right: the integrand
   * vanishes there), then lit and visible. */
  float u_d = atan(d.y, d.x);
  float lower = u_d - EL_HALF_PI, upper = u_d + EL_HALF_PI;
  if (lower <= -EL_PI) {
    lower += 2.0 * EL_PI;
  }
  if (upper > EL_PI) {
    upper -= 2.0 * EL_PI;
  }
  ElWindow lit = el_window_on_arc(lower, upper, g.alpha);
  float a = max(g.vis.lo, lit.lo), b = min(g.vis.hi, lit.hi);
  if (a > b) {
    return 0.0;
  }
  if (u_d < -EL_HALF_PI) {
    u_d += 2.0 * EL_PI;
  }
  float ta = clamp(a - u_d, -EL_HALF_PI, EL_HALF_PI);
  float tb = clamp(b - u_d, -EL_HALF_PI, EL_HALF_PI);
  float log_dp = d_axial < 0.5 ? 0.5 * el_log1p(-d_axial) : log(dlen / d_len);
  float log_dn = n * log_dp;
  float m = n + 1.0;
  float sqrt_m = sqrt(m);
  float lv = g.vis.hi - g.vis.lo, ll = b - a;

  /* The diffuse mean (n = 1, a constant where el_edge_colour calls it) always takes the 8-point
   * rule: its integrand is a cosine over at most pi (error ~1e-9), and with the table branch
   * folded away llvmpipe no longer runs that branch's 32 texel reads masked in every fragment. */
  if (n == 1.0 || ll * sqrt_m <= EL_GAUSS_SPAN) {
    ElWeight wj = el_weight_on(g.vis, a, b);
    float h = 0.5 * ll;
    float dp = exp(log_dp);
    float num = 0.0, den = 0.0;
    for (int k = 0; k < 4; k++) {
      for (int s = -1; s <= 1; s += 2) {
        float t = h * (1.0 + float(s) * el_gl_x[k]);
        float wv = el_gl_w[k] * el_weight_at(wj, t);
        /* n = 1 (diffuse) needs no power */
        float f = n == 1.0 ? dp * max(cos(ta + t), 0.0) : exp(log_dn + n * el_log_cos(ta + t));
        num += wv * f;
        den += wv;
      }
    }
    if (a == g.vis.lo && b == g.vis.hi) {
      return den > 0.0 ? clamp(num / den, 0.0, 1.0) : 0.0;
    }
    float jnum = h * num;
    float wden;
    if (lv * sqrt_m <= EL_GAUSS_SPAN) {
      ElWeight wv = el_weight_on(g.vis, g.vis.lo, g.vis.hi);
      float hv = 0.5 * lv;
      wden = 0.0;
      for (int k = 0; k < 4; k++) {
        wden += el_gl_w[k] * (el_weight_at(wv, hv * (1.0 - el_gl_x[k])) + el_weight_at(wv, hv * (1.0 + el_gl_x[k])));
      }
      wden *= hv;
    }
    else {
      wden = g.width;
    }
    return wden > 0.0 ? clamp(jnum / wden, 0.0, 1.0) : 0.0;
  }

  vec2 vhat = g.view / sqrt(dot(g.view, g.view));
  vec2 dhat = d / dlen;
  float cos_v = dot(vhat, dhat);
  float sin_v = dhat.x * vhat.y - dhat.y * vhat.x;
  vec4 row = el_table_row(m);
  float dF = el_table_lookup(row, tb) - el_table_lookup(row, ta);
  float dC = el_cos_pow(ta, m) - el_cos_pow(tb, m);
  float j = exp(log_dn) * (cos_v * dF + sin_v * dC / m);
  return g.width > 0.0 ? clamp(j / g.width, 0.0, 1.0) : 0.0;
}

/* Specular (D = H, exponent n) or diffuse (D = L, exponent 1) mean over the arc. */
float el_arc_mean(ElArc g, vec3 D, vec3 E, float n)
{
  float dd = dot(D, D);
  float de = dot(D, el_safe_normalize(E));
  return el_arc_kernel(g, vec2(dot(D, g.a1), dot(D, g.b1)), sqrt(dd), dd > 0.0 ? de * de / dd : 1.0, n);
}

float el_axial_ramp(float s)
{
  return clamp((s - EL_AXIAL_RAMP_S0) / EL_AXIAL_RAMP_S0, 0.0, 1.0);
}
