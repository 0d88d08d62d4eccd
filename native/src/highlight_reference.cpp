// The arc is parametrised by t in [0, alpha]: N(t) = cos t U1 + sin t B1 (U1 = N1 projected
// and normalised, B1 = e_z x U1), T(t) = dN/dt. Integrated, all at once:
//   spec = int max(N.H,0)^n [N.V>0] |P.T| dt      diff = int max(N.L,0) [N.V>0] |P.T| dt
//   vis  = int [N.V>0] |P.T| dt                   all  = int |P.T| dt
// The integrand has kinks where N.V, N.H or N.L changes sign. The domain is split at the zeros of
// those three dot products (each is A cos t + B sin t) and at the peak of N.H, so that every
// panel is smooth; the splits only speed convergence up, the indicator [N.V > 0] and the max()
// are still evaluated in 3-D at every node, so a wrong split could not change a result.
#include "highlight_reference.hpp"

#include "highlight_arc.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace el {

namespace {

using glm::dvec3;

constexpr double kPi = std::numbers::pi;

// Gauss-Kronrod 7/15 (QUADPACK qk15): Kronrod nodes x_k (k = 0..7, x_7 = 0) and weights; the
// Gauss nodes are x_1, x_3, x_5, x_7.
constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.0};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

constexpr int kComponents = 4;  // spec, diff, vis, all
constexpr double kNoise = 64.0 * 2.220446049250313e-16;
constexpr int kMaxPanels = 20000;

struct Values {
    double v[kComponents] = {0, 0, 0, 0};
};

dvec3 load(const float* v) { return dvec3(v[0], v[1], v[2]); }

struct Arc {
    dvec3 u1, b1, V, H, L, P;
    double n;
    Values at(double t) const {
        Values r;
        const double c = std::cos(t), s = std::sin(t);
        const dvec3 N = c * u1 + s * b1;
        const dvec3 T = -s * u1 + c * b1;
        const double w = std::fabs(glm::dot(P, T));
        r.v[3] = w;
        if (glm::dot(N, V) > 0.0) {
            r.v[2] = w;
            const double nh = glm::dot(N, H), nl = glm::dot(N, L);
            if (nh > 0.0) r.v[0] = std::pow(nh, n) * w;
            if (nl > 0.0) r.v[1] = nl * w;
        }
        return r;
    }
};

struct Panel {
    double a, b;
    Values k;    // Kronrod estimate
    Values e;    // |Kronrod - Gauss| per component
    double key;  // error relative to the scales of the moment the panel was made
};

// The components' scales: spec, diff and vis are relative to vis (they become I = ./vis),
// all to itself.
void set_key(Panel& p, const Values& total) {
    const double vs = std::max(total.v[2], 1e-300), as = std::max(total.v[3], 1e-300);
    p.key = (p.e.v[0] + p.e.v[1] + p.e.v[2]) / vs + p.e.v[3] / as;
}

Panel gauss_kronrod(const Arc& arc, double a, double b) {
    Panel p{a, b, {}, {}, 0.0};
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    Values g;
    const Values f0 = arc.at(c);
    for (int j = 0; j < kComponents; ++j) {
        p.k.v[j] = kWgk[7] * f0.v[j];
        g.v[j] = kWg[3] * f0.v[j];
    }
    for (int i = 0; i < 7; ++i) {
        const Values f1 = arc.at(c - h * kXgk[i]), f2 = arc.at(c + h * kXgk[i]);
        for (int j = 0; j < kComponents; ++j) {
            const double sum = f1.v[j] + f2.v[j];
            p.k.v[j] += kWgk[i] * sum;
            if (i % 2 == 1) g.v[j] += kWg[i / 2] * sum;
        }
    }
    for (int j = 0; j < kComponents; ++j) {
        p.k.v[j] *= h;
        // Every integrand is a product of 3-D dot products of unit vectors, each rounded to ~1e-16
        // absolutely (the specular power multiplies that by n). A difference at that level is
        // rounding noise, not truncation error: such a panel is exact to double precision and is
        // not split again (thin visible slivers at a horizon would otherwise never converge).
        const double floor = kNoise * 2.0 * h * (j == 0 ? 1.0 + arc.n : 1.0);
        const double diff = std::fabs(p.k.v[j] - g.v[j] * h);
        p.e.v[j] = diff > floor ? diff : 0.0;
    }
    return p;
}

// Zeros of A cos t + B sin t = R cos(t - atan2(B, A)) in (0, alpha), and optionally its maximum.
void add_breaks(std::vector<double>& out, const Arc& arc, dvec3 x, double alpha, bool peak) {
    const double A = glm::dot(arc.u1, x), B = glm::dot(arc.b1, x);
    if (A == 0.0 && B == 0.0) return;
    const double phi = std::atan2(B, A);
    for (int k = -2; k <= 2; ++k) {
        for (double t : {phi + 0.5 * kPi + 2 * kPi * k, phi - 0.5 * kPi + 2 * kPi * k})
            if (t > 0.0 && t < alpha) out.push_back(t);
        if (peak && phi + 2 * kPi * k > 0.0 && phi + 2 * kPi * k < alpha) out.push_back(phi + 2 * kPi * k);
    }
}

Values integrate(const Arc& arc, double alpha, ReferenceStats& stats) {
    std::vector<double> cuts{0.0, alpha};
    add_breaks(cuts, arc, arc.V, alpha, false);
    add_breaks(cuts, arc, arc.H, alpha, true);
    add_breaks(cuts, arc, arc.L, alpha, false);
    std::sort(cuts.begin(), cuts.end());

    std::vector<Panel> panels;
    for (size_t i = 0; i + 1 < cuts.size(); ++i)
        if (cuts[i + 1] > cuts[i]) panels.push_back(gauss_kronrod(arc, cuts[i], cuts[i + 1]));
    auto by_err = [](const Panel& x, const Panel& y) { return x.key < y.key; };
    Values total, err;
    for (const Panel& p : panels)
        for (int j = 0; j < kComponents; ++j) {
            total.v[j] += p.k.v[j];
            err.v[j] += p.e.v[j];
        }
    for (Panel& p : panels) set_key(p, total);
    std::make_heap(panels.begin(), panels.end(), by_err);
    stats.panels = int(panels.size());
    stats.converged = true;
    for (;;) {
        const double vis_scale = std::max(total.v[2], 1e-300);
        const double all_scale = std::max(total.v[3], 1e-300);
        const bool done = err.v[0] <= kReferenceTolerance * vis_scale &&
                          err.v[1] <= kReferenceTolerance * vis_scale &&
                          err.v[2] <= kReferenceTolerance * vis_scale &&
                          err.v[3] <= kReferenceTolerance * all_scale;
        if (done || panels.empty()) break;
        std::pop_heap(panels.begin(), panels.end(), by_err);
        const Panel worst = panels.back();
        panels.pop_back();
        const double mid = 0.5 * (worst.a + worst.b);
        if (stats.panels >= kMaxPanels || !(mid > worst.a && mid < worst.b)) {
            stats.converged = false;  // keep the estimate: the panel cannot be split further
            break;
        }
        for (int j = 0; j < kComponents; ++j) {
            total.v[j] -= worst.k.v[j];
            err.v[j] -= worst.e.v[j];
        }
        for (Panel child : {gauss_kronrod(arc, worst.a, mid), gauss_kronrod(arc, mid, worst.b)}) {
            for (int j = 0; j < kComponents; ++j) {
                total.v[j] += child.k.v[j];
                err.v[j] += child.e.v[j];
            }
            set_key(child, total);
            panels.push_back(child);
            std::push_heap(panels.begin(), panels.end(), by_err);
        }
        stats.panels += 2;
        // Running sums drift by rounding; recompute them now and then.
        if (stats.panels % 512 == 0) {
            total = Values{};
            err = Values{};
            for (const Panel& p : panels)
                for (int j = 0; j < kComponents; ++j) {
                    total.v[j] += p.k.v[j];
                    err.v[j] += p.e.v[j];
                }
        }
    }
    return total;
}

float to_unit(double x) { return float(std::clamp(x, 0.0, 1.0)); }

}  // namespace

el_highlight_result highlight_reference(const el_highlight_input& in, ReferenceStats* stats_out) {
    ReferenceStats stats;
    el_highlight_result out{};
    const dvec3 p = load(in.point);
    const dvec3 E = glm::normalize(load(in.edge_dir));
    const bool persp = in.projection == EL_PERSPECTIVE;
    const dvec3 to_eye = persp ? load(in.eye) - p : -load(in.view_dir);
    const dvec3 V = glm::normalize(to_eye);
    const double dist = persp ? glm::length(to_eye) : double(in.ortho_scale);
    const dvec3 L = glm::normalize(in.light_is_point ? load(in.light) - p : load(in.light));
    const dvec3 lv = L + V;
    const double lv_len = glm::length(lv);
    const dvec3 H = lv_len > 0.0 ? lv / lv_len : dvec3(0.0);
    const double n = in.shininess;

    const dvec3 n1 = load(in.n1), n2 = load(in.n2);
    const dvec3 u1 = glm::normalize(n1 - E * glm::dot(E, n1));
    const dvec3 u2 = glm::normalize(n2 - E * glm::dot(E, n2));
    const double det = glm::dot(glm::cross(u1, u2), E);
    const double c12 = glm::dot(u1, u2);
    dvec3 ez = E;
    double alpha;
    if (c12 < 0.0 && std::fabs(det) <= kAntiparallelBand) {
        alpha = kPi;
    } else {
        if (det < 0.0) ez = -E;
        alpha = std::atan2(std::fabs(det), c12);
    }

    const dvec3 exv = glm::cross(E, V);
    const double s = glm::length(exv);
    if (!(s > 0.0)) {
        if (stats_out) *stats_out = stats;
        return out;  // looking exactly along the edge: P is undefined, nothing is seen
    }
    Arc arc{u1, glm::cross(ez, u1), V, H, L, exv / s, n};

    if (alpha == 0.0) {
        // Flat edge: the limit of a vanishing arc.
        const bool visible = glm::dot(u1, V) > 0.0;
        if (visible) {
            const double nh = glm::dot(u1, H), nl = glm::dot(u1, L);
            out.specular = to_unit(nh > 0.0 ? std::pow(nh, n) : 0.0);
            out.diffuse = to_unit(std::max(nl, 0.0));
            out.visible_fraction = 1.0f;
        }
        if (stats_out) *stats_out = stats;
        return out;
    }

    const Values r = integrate(arc, alpha, stats);
    const double spec = r.v[0], diff = r.v[1], vis = r.v[2], all = r.v[3];
    if (vis > 0.0) {
        out.specular = to_unit(spec / vis);
        out.diffuse = to_unit(diff / vis);
        out.r_max = float(std::min(1.0 / vis, double(std::numeric_limits<float>::max())));
        out.visible_fraction = to_unit(all > 0.0 ? vis / all : 0.0);
        const double ramp = std::clamp((s - kAxialRampS0) / kAxialRampS0, 0.0, 1.0);
        if (in.K > 0.0f && in.radius > 0.0f)
            out.weight = to_unit(std::min(double(in.K) * in.radius * vis / dist, 1.0) * ramp);
    }
    if (stats_out) *stats_out = stats;
    return out;
}

}  // namespace el
