// Hand-made configurations with closed forms: el_highlight_eval (float, table) and
// el_highlight_reference (double, 3-D quadrature) against the exact values.
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include "highlight_fixtures.hpp"

#include <cmath>
#include <numbers>

using fixtures::set3;
using fixtures::Table;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kS = fixtures::kInvSqrt2;

// Edge along +z through the origin, sun light, orthographic view along view_dir.
el_highlight_input base(float n) {
    el_highlight_input in{};
    set3(in.edge_dir, 0, 0, 1);
    set3(in.n1, 1, 0, 0);
    set3(in.n2, 0, 1, 0);
    in.projection = EL_ORTHOGRAPHIC;
    in.shininess = n;
    in.radius = 0.01f;
    in.K = 10.0f;
    in.ortho_scale = 1.0f;
    return in;
}

el_highlight_result eval(const Table& t, const el_highlight_input& in) {
    el_highlight_result r{};
    EXPECT_EQ(el_highlight_eval(t.t, &in, &r), EL_OK) << el_last_error();
    return r;
}

el_highlight_result reference(const el_highlight_input& in) {
    el_highlight_result r{};
    EXPECT_EQ(el_highlight_reference(&in, &r), EL_OK) << el_last_error();
    return r;
}

double F(double phi, double m) {
    double v = 0;
    EXPECT_EQ(el_cos_power_integral(phi, m, &v), EL_OK);
    return v;
}

double G(double a, double b, double n) {
    double v = 0;
    EXPECT_EQ(el_cos_power_sin_integral(a, b, n, &v), EL_OK);
    return v;
}

// 90-degree cube edge seen along its bisector, light along the bisector (so H = L = V): the arc
// is theta in [-pi/4, pi/4] around the peak, all of it visible and lit, weight cos(theta):
// I = 2 F(pi/4, n+1) / (2 sin(pi/4)); width = sqrt(2).
TEST(HighlightCases, CubeEdgeAlongTheBisector) {
    Table t;
    for (float n : {1.0f, 2.0f, 8.0f, 37.3f, 500.0f, 9999.5f}) {
        el_highlight_input in = base(n);
        set3(in.view_dir, -kS, -kS, 0);
        set3(in.light, 1, 1, 0);
        const double spec = std::sqrt(2.0) * F(kPi / 4, double(n) + 1.0);
        const double diff = std::sqrt(2.0) * F(kPi / 4, 2.0);
        const el_highlight_result e = eval(t, in), r = reference(in);
        EXPECT_NEAR(r.specular, spec, 1e-7) << n;
        EXPECT_NEAR(r.diffuse, diff, 1e-7) << n;
        EXPECT_NEAR(e.specular, spec, 3e-5) << n;
        EXPECT_NEAR(e.diffuse, diff, 3e-5) << n;
        for (const el_highlight_result& x : {e, r}) {
            EXPECT_NEAR(x.r_max, 1.0 / std::sqrt(2.0), 1e-6);
            EXPECT_NEAR(x.weight, 10.0 * 0.01 * std::sqrt(2.0), 1e-6);  // K r width / d
            EXPECT_NEAR(x.visible_fraction, 1.0, 1e-6);
        }
    }
}

// Same, perspective: the eye on the bisector at distance 4, d = 4 in W.
TEST(HighlightCases, CubeEdgePerspective) {
    Table t;
    el_highlight_input in = base(20.0f);
    in.projection = EL_PERSPECTIVE;
    set3(in.point, 1, 2, 3);
    set3(in.eye, 1 + 4 * kS, 2 + 4 * kS, 3);
    in.light_is_point = 1;
    set3(in.light, 1 + 100 * kS, 2 + 100 * kS, 3);
    const double spec = std::sqrt(2.0) * F(kPi / 4, 21.0);
    const el_highlight_result e = eval(t, in), r = reference(in);
    EXPECT_NEAR(r.specular, spec, 1e-6);
    EXPECT_NEAR(e.specular, spec, 3e-5);
    EXPECT_NEAR(e.weight, 10.0 * 0.01 * std::sqrt(2.0) / 4.0, 1e-6);
    EXPECT_NEAR(r.weight, 10.0 * 0.01 * std::sqrt(2.0) / 4.0, 1e-6);
}

// N1 = N2: no arc. I is the limit max(N1.D, 0)^n; the width is 0, so W = 0 and r_max = 0.
TEST(HighlightCases, FlatEdge) {
    Table t;
    for (float n : {1.0f, 30.0f, 4000.0f}) {
        el_highlight_input in = base(n);
        set3(in.n2, 1, 0, 0);
        set3(in.view_dir, -1, -0.2f, 0);
        set3(in.light, 1, 0.05f, 0.01f);
        const double vx = 1 / std::sqrt(1.04), vy = 0.2 / std::sqrt(1.04);
        const double l = std::sqrt(1 + 0.0025 + 0.0001);
        const double lx = 1 / l, ly = 0.05 / l, lz = 0.01 / l;
        const double hn = std::sqrt((vx + lx) * (vx + lx) + (vy + ly) * (vy + ly) + lz * lz);
        const double spec = std::pow((vx + lx) / hn, n);
        for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
            EXPECT_NEAR(x.specular, spec, 3e-5 * (1 + n * 1e-3)) << n;
            EXPECT_NEAR(x.diffuse, lx, 1e-6);
            EXPECT_EQ(x.weight, 0.0f);
            EXPECT_EQ(x.r_max, 0.0f);
            EXPECT_EQ(x.visible_fraction, 1.0f);
        }
        // Facing away: nothing.
        set3(in.view_dir, 1, 0, 0);
        for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
            EXPECT_EQ(x.specular, 0.0f);
            EXPECT_EQ(x.diffuse, 0.0f);
            EXPECT_EQ(x.visible_fraction, 0.0f);
        }
    }
}

// Arc from x to y seen from (1, -1, 0)/sqrt2: N.V = cos(u + pi/4) > 0 only for u < pi/4, the
// first half of the arc. Visible width 1 - sin(pi/4) = hidden width; light along x:
// I_d = int_0^{pi/4} cos u cos(u + pi/4) du / (1 - sqrt2/2) = (pi sqrt2 / 16) / (1 - sqrt2/2).
// Specular: H at -pi/8 from x, so theta in [pi/8, 3pi/8] and the weight is
// cos(pi/8) cos(theta) - sin(pi/8) sin(theta).
TEST(HighlightCases, HalfHiddenArc) {
    Table t;
    for (float n : {1.0f, 6.0f, 55.5f}) {
        el_highlight_input in = base(n);
        set3(in.view_dir, -kS, kS, 0);
        set3(in.light, 1, 0, 0);
        const double width = 1 - std::sqrt(0.5);
        const double diff = kPi * std::sqrt(2.0) / 16 / width;
        const double m = double(n) + 1;
        const double J = std::cos(kPi / 8) * (F(3 * kPi / 8, m) - F(kPi / 8, m)) -
                         std::sin(kPi / 8) * G(kPi / 8, 3 * kPi / 8, n);
        const double spec = J / width;
        const el_highlight_result e = eval(t, in), r = reference(in);
        EXPECT_NEAR(r.diffuse, diff, 1e-7);
        EXPECT_NEAR(r.specular, spec, 1e-7) << n;
        EXPECT_NEAR(e.diffuse, diff, 3e-5);
        EXPECT_NEAR(e.specular, spec, 3e-5) << n;
        for (const el_highlight_result& x : {e, r}) {
            EXPECT_NEAR(x.visible_fraction, 0.5, 1e-6);
            EXPECT_NEAR(x.r_max, 1 / width, 1e-4);
            EXPECT_NEAR(x.weight, 10 * 0.01 * width, 1e-6);
        }
    }
}

// N2 = -N1: the half circle turning positively about edge_dir (here from x through +y).
TEST(HighlightCases, AntiparallelNormalsTurnPositivelyAboutTheEdge) {
    Table t;
    el_highlight_input in = base(10.0f);
    set3(in.n2, -1, 0, 0);
    set3(in.light, 0, 1, 0);
    set3(in.view_dir, 0, -1, 0);  // eye on +y: the whole half circle faces it
    // Width |P.(N1 - N2)| = 2, weight sin(u); I_d = int sin^2 / 2 = pi/4.
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
        EXPECT_NEAR(x.visible_fraction, 1.0, 1e-6);
        EXPECT_NEAR(x.r_max, 0.5, 1e-6);
        EXPECT_NEAR(x.diffuse, kPi / 4, 3e-5);
    }
    set3(in.view_dir, 0, 1, 0);  // eye on -y: the half circle is the back
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
        EXPECT_EQ(x.visible_fraction, 0.0f);
        EXPECT_EQ(x.weight, 0.0f);
        EXPECT_EQ(x.specular, 0.0f);
    }
    set3(in.edge_dir, 0, 0, -1);  // the other half circle (through -y) now faces the eye
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
        EXPECT_NEAR(x.visible_fraction, 1.0, 1e-6);
        EXPECT_NEAR(x.r_max, 0.5, 1e-6);
    }
    // Nearly antiparallel (1e-8 rad, inside the 1e-6 band): still the half circle about +E.
    set3(in.edge_dir, 0, 0, 1);
    set3(in.n2, -1, -1e-8f, 0);
    set3(in.view_dir, 0, -1, 0);
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) EXPECT_NEAR(x.visible_fraction, 1.0, 1e-6);
}

// Looking along the edge: P is undefined, W = 0. Near it W fades over |E x V| in [s0, 2 s0],
// s0 = 0.01.
TEST(HighlightCases, ViewAlongTheEdge) {
    Table t;
    el_highlight_input in = base(10.0f);
    set3(in.view_dir, 0, 0, -1);
    set3(in.light, 1, 1, 1);
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
        EXPECT_EQ(x.weight, 0.0f);
        EXPECT_TRUE(std::isfinite(x.specular) && std::isfinite(x.r_max));
    }
    auto weight_at = [&](double s, bool ref) {
        // V = (s/sqrt2)(1, 1, 0) + sqrt(1 - s^2) z: |E x V| = s, V along the arc's bisector.
        set3(in.view_dir, float(-s * std::sqrt(0.5)), float(-s * std::sqrt(0.5)), float(-std::sqrt(1 - s * s)));
        return ref ? reference(in).weight : eval(t, in).weight;
    };
    for (bool ref : {false, true}) {
        // The projected width |P.(N1 - N2)| depends only on the direction of V's part across
        // the edge, not on |E x V|: without the ramp W would be the same for every s > 0.
        const double full = weight_at(0.5, ref);
        EXPECT_NEAR(full, 10 * 0.01 * std::sqrt(2.0), 1e-6);
        EXPECT_EQ(weight_at(0.005, ref), 0.0f);
        EXPECT_NEAR(weight_at(0.015, ref), 0.5 * full, 1e-3 * full);
        EXPECT_NEAR(weight_at(0.03, ref), full, 1e-6);
    }
}

// D along the edge: N.D = 0 on the whole arc. Light along E gives no diffuse; a half vector
// along E (L the mirror of V about E) no specular.
TEST(HighlightCases, LightOrHalfVectorAlongTheEdge) {
    Table t;
    el_highlight_input in = base(5.0f);
    set3(in.view_dir, -0.6f, -0.6f, -0.52915026f);
    set3(in.light, 0, 0, 1);
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) EXPECT_NEAR(x.diffuse, 0.0, 1e-6);
    // V = (0.6, 0.6, 0.529): L = 2 (V.E) E - V = (-0.6, -0.6, 0.529), H = z.
    set3(in.light, -0.6f, -0.6f, 0.52915026f);
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) {
        EXPECT_NEAR(x.specular, 0.0, 1e-6);
        EXPECT_GT(x.weight, 0.0f);
    }
    // Light exactly behind the object (L = -V): H is undefined, defined as no specular.
    set3(in.light, -0.6f, -0.6f, -0.52915026f);
    for (const el_highlight_result& x : {eval(t, in), reference(in)}) EXPECT_EQ(x.specular, 0.0f);
}

}  // namespace
