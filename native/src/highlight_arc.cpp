// Float32 evaluation of one pixel's rounded edge, in the order a fragment shader does it. No
// double anywhere: every literal is a float and every call takes float arguments.
//
// Angles are measured in the arc's own frame: u = 0 at N1, u = alpha at N2, turning about e_z.
// The visible and the lit parts of the circle are half circles ("windows"); each meets the arc
// [0, alpha] (alpha <= pi) in one interval, so their intersection is one interval too. The
// integrals are then done in the light's frame theta = u - u_d, where N.D = |D_p| cos(theta).
#include "highlight_arc.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace el {

namespace {

using glm::vec2;
using glm::vec3;

constexpr float kPi = 3.14159265358979f;
constexpr float kHalfPi = 1.57079632679490f;

// 8-point Gauss-Legendre on [-1, 1], mirrored pairs.
constexpr float kGLx[4] = {0.183434642495649805f, 0.525532409916328986f, 0.796666477413626740f,
                           0.960289856497536232f};
constexpr float kGLw[4] = {0.362683783378361983f, 0.313706645877887287f, 0.222381034453374471f,
                           0.101228536290376259f};
static_assert(kGaussPoints == 8, "the node table above is the 8-point rule");

vec3 load(const float* v) { return vec3(v[0], v[1], v[2]); }

// normalize() that neither overflows nor underflows: scale by the largest component first.
// Returns 0 for the zero vector.
vec3 safe_normalize(vec3 v) {
    const float s = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(s > 0.0f)) return vec3(0.0f);
    v /= s;
    return v / std::sqrt(glm::dot(v, v));
}

float safe_length(vec3 v) {
    const float s = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(s > 0.0f)) return 0.0f;
    v /= s;
    return s * std::sqrt(glm::dot(v, v));
}

// a*b - c*d with a single rounding (Kahan): keeps tiny cross products of unit vectors exact.
float diff_of_products(float a, float b, float c, float d) {
    const float w = c * d;
    const float e = std::fma(-c, d, w);
    const float f = std::fma(a, b, -w);
    return f + e;
}

// v * 2^-e with the largest component in [0.5, 1): exact, so directions keep every bit.
vec3 pow2_scale(vec3 v) {
    int e = 0;
    std::frexp(std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}), &e);
    return vec3(std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e));
}

vec3 cross_exact(vec3 a, vec3 b) {
    return vec3(diff_of_products(a.y, b.z, a.z, b.y), diff_of_products(a.z, b.x, a.x, b.z),
                diff_of_products(a.x, b.y, a.y, b.x));
}

// ln(1 + x) without losing x to the rounding of 1 + x (Goldberg's trick; GLSL has no log1p).
float log1p_f(float x) {
    const float u = 1.0f + x;
    return u == 1.0f ? x : std::log(u) * x / (u - 1.0f);
}

// ln cos t. cos t rounds to a multiple of 6e-8 near t = 0, and cos^n multiplies that by n, so
// ln cos t is computed from t as log1p(-2 sin^2(t/2)): a few ulp relative at every t, in one
// branch-free expression (the shader's copy runs in SIMD lanes, where every branch costs all
// lanes; a 3-piece version ran all three pieces).
float log_cos(float t) {
    const float s = std::sin(0.5f * t);
    const float x = -2.0f * s * s;
    return x > -1.0f ? log1p_f(x) : -1e30f;  // exp(n * -1e30) = 0: past pi/2 nothing is lit
}

// cos^n t, relative error ~ 1e-7 * (1 + |n ln cos t|).
float cos_pow(float t, float n) { return std::exp(n * log_cos(t)); }

// Window of directions w with w.dir > 0, as seen on the arc [0, alpha]: the interval
// [lo, hi] (empty when lo > hi), plus the distances of its ends from the window's lower and
// upper horizons (exactly 0 where an end is a horizon), which keep sin(distance) accurate.
struct Window {
    float lo = 1.0f, hi = 0.0f;
    float from_lower = 0.0f;  // lo - lower horizon
    float to_upper = 0.0f;    // upper horizon - hi
    bool empty() const { return lo > hi; }
};

// The window's horizons as principal angles in (-pi, pi]: `lower` (where the window starts
// when turning positively) and `upper` = lower + pi. Valid for any window of length pi.
Window window_on_arc(float lower, float upper, float alpha) {
    Window w;
    if (lower > 0.0f) {
        w.lo = lower;
        w.from_lower = 0.0f;
        w.hi = alpha;
        w.to_upper = (lower + kPi) - alpha;
        return w;
    }
    w.lo = 0.0f;
    w.from_lower = -lower;
    // upper = lower + pi lies in (0, pi] here; undo a wrap of pi to -pi (signed zeros).
    const float up = (upper < -kHalfPi) ? upper + 2.0f * kPi : std::max(upper, 0.0f);
    if (up < alpha) {
        w.hi = up;
        w.to_upper = 0.0f;
    } else {
        w.hi = alpha;
        w.to_upper = up - alpha;
    }
    return w;
}

// Unit-radius projected width of a visible interval: |sin(hi - u_v) - sin(lo - u_v)| written as
// 2 sin(L/2) sin(distance of the midpoint from the nearer horizon).
float window_width(const Window& w) {
    if (w.empty()) return 0.0f;
    const float len = w.hi - w.lo;
    return 2.0f * std::sin(0.5f * len) * std::sin(std::min(w.from_lower, w.to_upper) + 0.5f * len);
}

// The view weight cos(u - u_v) = |P.T| |E x V| at offset t from sub-interval [a, b] of window
// vis: measured from whichever horizon is nearer, so it stays accurate where it is small.
struct Weight {
    float offset;  // distance of the evaluation start from the chosen horizon
    bool from_lower;
    float len;
    float at(float t) const { return std::sin(from_lower ? offset + t : offset + (len - t)); }
};

Weight weight_on(const Window& vis, float a, float b) {
    const float off_lo = vis.from_lower + (a - vis.lo);
    const float off_hi = vis.to_upper + (vis.hi - b);
    return off_lo <= off_hi ? Weight{off_lo, true, b - a} : Weight{off_hi, false, b - a};
}

struct Geometry {
    float alpha;  // arc length
    vec2 view;    // V projected onto the arc plane, in the arc frame (|view| = |E x V|)
    Window vis;   // visible part of the arc
    float width;  // its projected width, unit radius
};

// One of the two kernels: I = int max(N.D,0)^n w dtheta / int w dtheta over the visible arc.
// d: D in the arc frame (|D| = d_len); d_axial = (D.E)^2 / (D.D). ln |D_p| = 1/2 ln(1 - d_axial)
// stays exact when D is nearly in the arc's plane (|D_p|^n with n = 1e4 would otherwise multiply
// the rounding of |D_p| near 1 by 1e4); when D is nearly along the edge, |d| / |D| is exact.
float arc_kernel(const HighlightTable& table, const Geometry& g, vec2 d, float d_len, float d_axial,
                 float n, ArcPath* path) {
    *path = ArcPath::Empty;
    const float dlen = std::sqrt(glm::dot(d, d));
    if (g.vis.empty() || !(dlen > 0.0f)) return 0.0f;
    // Lit window (its edges only need to be roughly right: the integrand vanishes there), then
    // lit and visible.
    float u_d = std::atan2(d.y, d.x);
    float lower = u_d - kHalfPi, upper = u_d + kHalfPi;
    if (lower <= -kPi) lower += 2.0f * kPi;
    if (upper > kPi) upper -= 2.0f * kPi;
    const Window lit = window_on_arc(lower, upper, g.alpha);
    const float a = std::max(g.vis.lo, lit.lo), b = std::min(g.vis.hi, lit.hi);
    if (a > b) return 0.0f;
    // Light frame: theta = u - u_d, the lit window is theta in [-pi/2, pi/2].
    if (u_d < -kHalfPi) u_d += 2.0f * kPi;
    const float ta = std::clamp(a - u_d, -kHalfPi, kHalfPi);
    const float tb = std::clamp(b - u_d, -kHalfPi, kHalfPi);
    const float log_dp = d_axial < 0.5f ? 0.5f * log1p_f(-d_axial) : std::log(dlen / d_len);
    const float log_dn = n * log_dp;  // ln |D_p|^n
    const float m = n + 1.0f;
    const float sqrt_m = std::sqrt(m);
    const float lv = g.vis.hi - g.vis.lo, ll = b - a;

    // The diffuse kernel (n = 1) always takes this branch: a cosine over at most pi is within
    // ~1e-9 of exact with 8 nodes (docs/highlight_math.md, "Short arcs"), and the shader then
    // folds the table branch away (llvmpipe would run it masked in every fragment).
    if (n == 1.0f || ll * sqrt_m <= kGaussSpan) {
        // Short lit interval: Gauss-Legendre. If it is the whole visible interval, the same nodes
        // give the denominator, and I is a weighted mean of the integrand: no cancellation.
        const Weight wj = weight_on(g.vis, a, b);
        const float h = 0.5f * ll;
        const float dp = std::exp(log_dp);
        float num = 0.0f, den = 0.0f;
        for (int k = 0; k < 4; ++k) {
            for (int s = -1; s <= 1; s += 2) {
                const float t = h * (1.0f + float(s) * kGLx[k]);
                const float wv = kGLw[k] * wj.at(t);
                // n = 1 (diffuse) needs no power
                const float f = n == 1.0f ? dp * std::max(std::cos(ta + t), 0.0f)
                                          : std::exp(log_dn + n * log_cos(ta + t));
                num += wv * f;
                den += wv;
            }
        }
        if (a == g.vis.lo && b == g.vis.hi) {
            *path = ArcPath::Gauss;
            return den > 0.0f ? std::clamp(num / den, 0.0f, 1.0f) : 0.0f;
        }
        *path = ArcPath::Mixed;
        const float jnum = h * num;
        float wden;
        if (lv * sqrt_m <= kGaussSpan) {
            const Weight wv = weight_on(g.vis, g.vis.lo, g.vis.hi);
            const float hv = 0.5f * lv;
            wden = 0.0f;
            for (int k = 0; k < 4; ++k)
                wden += kGLw[k] * (wv.at(hv * (1.0f - kGLx[k])) + wv.at(hv * (1.0f + kGLx[k])));
            wden *= hv;
        } else {
            wden = g.width;
        }
        return wden > 0.0f ? std::clamp(jnum / wden, 0.0f, 1.0f) : 0.0f;
    }

    // Long interval: J = |D_p|^n [P_y (F(tb, m) - F(ta, m)) - P_x (C(ta) - C(tb)) / m] with
    // C = cos^m and P = e_z x v_hat, i.e. P_y = cos(th_v), P_x = -sin(th_v) for the view's angle
    // th_v in the light frame. (F and C from the table and cos_pow; the table is odd in phi.)
    *path = ArcPath::Table;
    const vec2 vhat = g.view / std::sqrt(glm::dot(g.view, g.view));
    const vec2 dhat = d / dlen;
    const float cos_v = glm::dot(vhat, dhat);
    const float sin_v = dhat.x * vhat.y - dhat.y * vhat.x;
    const TableRow row = table_row(table, m);
    const float dF = table_lookup(table, row, tb) - table_lookup(table, row, ta);
    const float dC = cos_pow(ta, m) - cos_pow(tb, m);
    const float j = std::exp(log_dn) * (cos_v * dF + sin_v * dC / m);
    return g.width > 0.0f ? std::clamp(j / g.width, 0.0f, 1.0f) : 0.0f;
}

// W's fade as the view turns onto the edge's axis (|E x V| = s).
float axial_ramp(float s) {
    constexpr float s0 = float(kAxialRampS0);
    return std::clamp((s - s0) / s0, 0.0f, 1.0f);
}

}  // namespace

float highlight_weight(float K, float r_e, float d, float r_max) {
    if (!(K > 0.0f) || !(r_e > 0.0f) || !(r_max > 0.0f)) return 0.0f;
    // The C API's helper, not the shader path: in double so that no product of float32 extremes
    // overflows or underflows into 0 * inf.
    const double w = double(K) * double(r_e) / (double(d) * double(r_max));
    return float(std::min(w, 1.0));
}

el_highlight_result highlight_eval(const HighlightTable& table, const el_highlight_input& in,
                                   ArcTrace* trace) {
    el_highlight_result out{};
    ArcTrace local;
    ArcTrace& tr = trace ? *trace : local;
    tr = ArcTrace{};

    const vec3 p = load(in.point);
    const vec3 E = safe_normalize(load(in.edge_dir));
    const bool persp = in.projection == EL_PERSPECTIVE;
    const vec3 to_eye = persp ? load(in.eye) - p : -load(in.view_dir);
    const vec3 V = safe_normalize(to_eye);
    const float dist = persp ? safe_length(to_eye) : in.ortho_scale;
    const vec3 L = safe_normalize(in.light_is_point ? load(in.light) - p : load(in.light));
    const vec3 H = safe_normalize(L + V);  // 0 when the light is exactly behind: no specular

    // Normals projected onto the plane perpendicular to the edge.
    const vec3 n1 = pow2_scale(load(in.n1)), n2 = pow2_scale(load(in.n2));
    const vec3 p1 = n1 - E * glm::dot(E, n1), p2 = n2 - E * glm::dot(E, n2);
    const float l1 = safe_length(p1), l2 = safe_length(p2);
    // Orientation and arc length from the triple product (N1 x N2).E = (P1 x P2).E, taken from the
    // unrounded inputs so that a tiny arc keeps its relative accuracy.
    const float det = glm::dot(cross_exact(n1, n2), E) / l1 / l2;
    const float dot12 = glm::dot(p1 / l1, p2 / l2);
    vec3 ez = E;
    float alpha;
    if (dot12 < 0.0f && std::fabs(det) <= float(kAntiparallelBand)) {
        alpha = kPi;  // N1 ~ -N2: the half circle about +edge_dir
    } else {
        if (det < 0.0f) ez = -E;
        alpha = std::atan2(std::fabs(det), dot12);
    }
    const vec3 a1 = p1 / l1;
    const vec3 b1 = glm::cross(ez, a1);

    Geometry g;
    g.alpha = alpha;
    g.view = vec2(glm::dot(V, a1), glm::dot(V, b1));
    const float s = std::sqrt(glm::dot(g.view, g.view));  // |E x V|
    if (!(s > 0.0f)) return out;                          // looking exactly along the edge
    // The horizons, where N.V = 0: the view direction turned by -90 and +90 degrees. The hidden
    // window is the visible one with the two swapped.
    const float h_lo = std::atan2(-g.view.x, g.view.y), h_hi = std::atan2(g.view.x, -g.view.y);
    g.vis = window_on_arc(h_lo, h_hi, alpha);
    g.width = window_width(g.vis);
    const float hidden = window_width(window_on_arc(h_hi, h_lo, alpha));

    const vec2 h2(glm::dot(H, a1), glm::dot(H, b1));
    const vec2 l2d(glm::dot(L, a1), glm::dot(L, b1));
    const float hh = glm::dot(H, H), ll = glm::dot(L, L);
    const float he = glm::dot(H, E), le = glm::dot(L, E);
    out.specular = arc_kernel(table, g, h2, std::sqrt(hh), hh > 0.0f ? he * he / hh : 1.0f,
                              in.shininess, &tr.specular);
    out.diffuse = arc_kernel(table, g, l2d, std::sqrt(ll), le * le / ll, 1.0f, &tr.diffuse);

    if (g.width > 0.0f) {
        out.r_max = std::min(1.0f / g.width, std::numeric_limits<float>::max());
        out.visible_fraction = g.width / (g.width + hidden);
        if (in.K > 0.0f && in.radius > 0.0f) {
            const float w = in.K * (in.radius / dist) * g.width;
            out.weight = std::min(w, 1.0f) * axial_ramp(s);
        }
    } else if (!g.vis.empty() && hidden == 0.0f && g.view.x > 0.0f && alpha == 0.0f) {
        out.visible_fraction = 1.0f;  // a flat edge facing the eye
    }
    return out;
}

}  // namespace el
