// The blend weight W = K r_e / (d r_max), clamped to [0, 1], and the visible fraction.
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

float weight(float K, float r, float d, float r_max) {
    float w = -1;
    EXPECT_EQ(el_highlight_weight(K, r, d, r_max, &w), EL_OK) << el_last_error();
    return w;
}

TEST(HighlightWeight, Formula) {
    EXPECT_FLOAT_EQ(weight(100, 0.01f, 4, 2), 100 * 0.01f / (4 * 2));
    EXPECT_EQ(weight(0, 0.01f, 4, 2), 0.0f);                // K = 0 switches highlights off
    EXPECT_EQ(weight(100, 0, 4, 2), 0.0f);                  // no radius, no edge
    EXPECT_EQ(weight(100, 0.01f, 4, 0), 0.0f);              // r_max = 0: nothing visible
    EXPECT_EQ(weight(1e30f, 1e30f, 1e-30f, 1e-30f), 1.0f);  // clamped, no overflow
    EXPECT_EQ(weight(1e-30f, 1e-30f, 1e30f, 1e30f), 0.0f);  // underflows to 0, not NaN
    float prev = 0;
    for (float r = 0.001f; r < 0.2f; r *= 1.5f) {  // grows with the radius, then clamps
        const float w = weight(100, r, 4, 2);
        EXPECT_GE(w, prev);
        EXPECT_LE(w, 1.0f);
        prev = w;
    }
    EXPECT_EQ(prev, 1.0f);
}

el_highlight_input cube_edge(float radius, float K) {
    el_highlight_input in{};
    set3(in.edge_dir, 0, 0, 1);
    set3(in.n1, 1, 0, 0);
    set3(in.n2, 0, 1, 0);
    in.projection = EL_PERSPECTIVE;
    set3(in.eye, 3 * kS, 3 * kS, 0);  // d = 3 along the bisector
    set3(in.light, 1, 1, 0.2f);
    in.shininess = 40;
    in.radius = radius;
    in.K = K;
    return in;
}

TEST(HighlightWeight, EvalWeight) {
    Table t;
    el_highlight_result r{};
    el_highlight_input in = cube_edge(0.01f, 0.0f);
    ASSERT_EQ(el_highlight_eval(t.t, &in, &r), EL_OK);
    EXPECT_EQ(r.weight, 0.0f);  // K = 0
    EXPECT_GT(r.specular, 0.0f);
    float prev = 0;
    for (float radius = 1e-4f; radius < 1.0f; radius *= 2) {
        in = cube_edge(radius, 500);
        ASSERT_EQ(el_highlight_eval(t.t, &in, &r), EL_OK);
        // W = K r width / d with width = sqrt(2), and el_highlight_weight agrees from r_max.
        EXPECT_NEAR(r.weight, std::min(500 * radius * std::sqrt(2.0) / 3, 1.0), 1e-6);
        EXPECT_NEAR(r.weight, weight(500, radius, 3, r.r_max), 1e-6);
        EXPECT_GE(r.weight, prev);
        prev = r.weight;
    }
    EXPECT_EQ(prev, 1.0f);
}

// W I = K r J / d: r_max cancels, so the pixel's highlight does not depend on it (while W < 1).
TEST(HighlightWeight, ProductIsIndependentOfRmax) {
    Table t;
    el_highlight_input in = cube_edge(0.002f, 500);
    set3(in.light, 1, 1, 0);  // H along the bisector: J = 2 F(pi/4, n + 1)
    el_highlight_result r{};
    ASSERT_EQ(el_highlight_eval(t.t, &in, &r), EL_OK);
    double F = 0;
    ASSERT_EQ(el_cos_power_integral(kPi / 4, 41, &F), EL_OK);
    EXPECT_NEAR(r.weight * r.specular, 500 * 0.002 * 2 * F / 3, 2e-6);
}

// Seen from the other side of the bisector's plane, part of the arc is hidden: the visible
// fraction and W follow the visible sub-arc (paper: |P.(N1 - N2)| counts it all).
TEST(HighlightWeight, VisibleFractionAgainstReference) {
    Table t;
    for (double view_angle : {-80.0, -60.0, -30.0, 0.0, 20.0, 45.0, 100.0, 180.0}) {
        // V rotating in the xy plane: angle 45 is the bisector; beyond +-90 from it hidden parts.
        const double a = (45.0 + view_angle) * kPi / 180.0;
        el_highlight_input in = cube_edge(0.001f, 500);
        in.projection = EL_ORTHOGRAPHIC;
        in.ortho_scale = 3;
        set3(in.view_dir, float(-std::cos(a)), float(-std::sin(a)), 0);
        el_highlight_result e{}, r{};
        ASSERT_EQ(el_highlight_eval(t.t, &in, &e), EL_OK);
        ASSERT_EQ(el_highlight_reference(&in, &r), EL_OK);
        EXPECT_NEAR(e.visible_fraction, r.visible_fraction, 1e-6) << view_angle;
        EXPECT_NEAR(e.weight, r.weight, 1e-6) << view_angle;
        EXPECT_NEAR(e.r_max, r.r_max, 1e-5 * r.r_max) << view_angle;
        if (std::fabs(view_angle) <= 45) {
            EXPECT_NEAR(r.visible_fraction, 1.0, 1e-7);
        }
        if (view_angle == 100) {
            // V at 145 degrees: visible u in (55, 90], width 1 - sin(55 - 55)... = 1 - cos(35);
            // hidden u in [0, 55): width 1 - cos(55).
            const double vis = 1 - std::cos(35 * kPi / 180), hid = 1 - std::cos(55 * kPi / 180);
            EXPECT_NEAR(r.visible_fraction, vis / (vis + hid), 1e-7);
            EXPECT_NEAR(r.r_max, 1 / vis, 1e-5 / vis);
        }
        if (view_angle == 180) {
            EXPECT_EQ(r.visible_fraction, 0.0f);
            EXPECT_EQ(e.weight, 0.0f);
        }
    }
}

// K = focal length in pixels makes W the pixel coverage: project the visible arc through a
// pinhole camera (focal f pixels, looking along +z) and measure its image width across the edge.
TEST(HighlightWeight, FocalLengthGivesPixelCoverage) {
    Table t;
    const double f = 1200, d = 25, radius = 0.01;
    for (double tilt : {0.0, 0.3, 0.7}) {  // rotate the arc about the edge (x axis)
        el_highlight_input in{};
        set3(in.point, 0, 0, float(d));
        set3(in.edge_dir, 1, 0, 0);
        // Face normals of a 100-degree edge, turned by `tilt`, facing the camera (-z).
        const double a1 = -kPi / 2 + tilt - 50 * kPi / 180, a2 = -kPi / 2 + tilt + 50 * kPi / 180;
        set3(in.n1, 0, float(std::cos(a1)), float(std::sin(a1)));
        set3(in.n2, 0, float(std::cos(a2)), float(std::sin(a2)));
        in.projection = EL_PERSPECTIVE;
        set3(in.eye, 0, 0, 0);
        set3(in.light, 0, 0, -1);
        in.shininess = 10;
        in.radius = float(radius);
        in.K = float(f);
        el_highlight_result r{};
        ASSERT_EQ(el_highlight_eval(t.t, &in, &r), EL_OK);
        // Image of the visible points c + r N(u): y_img = f Y / Z.
        double lo = 1e30, hi = -1e30;
        for (int i = 0; i <= 100000; ++i) {
            const double u = a1 + (a2 - a1) * i / 100000.0;
            const double ny = std::cos(u), nz = std::sin(u);
            if (-nz <= 0) continue;  // N.V with V = -z at the edge
            const double y = f * (radius * ny) / (d + radius * nz);
            lo = std::min(lo, y);
            hi = std::max(hi, y);
        }
        EXPECT_NEAR(r.weight, hi - lo, 2e-3 * (hi - lo)) << tilt;  // O(r/d) from perspective
    }
}

}  // namespace
