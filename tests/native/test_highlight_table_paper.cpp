// The paper's table, 1024 x 128: F(phi, m) for integer m at phi uniform on [0, pi/2]. Its stated
// bound is the linear-interpolation error h^2/8 max|F''| ("about 2.0e-6"); measured per m against
// the exact F on a grid 16 times denser than the table's (and on the texel centres).
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;

// max over phi of |F''| = |d/dphi cos^m| = m cos^(m-1) sin, reached at sin^2 = 1/m.
double max_second_derivative(int m) {
    if (m == 1) return 1.0;
    return std::sqrt(double(m)) * std::pow(1.0 - 1.0 / m, 0.5 * (m - 1));
}

TEST(HighlightTablePaper, InterpolationBoundAt1024x128) {
    el_table_desc desc{EL_TABLE_PAPER, 1024, 128, 0.0f};
    el_highlight_table* t = nullptr;
    ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK) << el_last_error();
    el_table_info info{};
    ASSERT_EQ(el_highlight_table_get_info(t, &info), EL_OK);
    EXPECT_EQ(info.layout, EL_TABLE_PAPER);
    EXPECT_EQ(info.m_max, 128.0f);

    const double h = kHalfPi / 1023.0;
    const double paper_bound = h * h / 8.0 * max_second_derivative(128);
    // The paper's "about 2.0e-6" is the bound at m = 128.
    EXPECT_NEAR(paper_bound, 2.0e-6, 0.05e-6);

    double worst = 0, worst_ratio = 0;
    int worst_m = 0;
    for (int m = 1; m <= 128; ++m) {
        double full = 0;
        ASSERT_EQ(el_cos_power_integral(kHalfPi, m, &full), EL_OK);
        // Interpolation plus float32: storage rounds each texel by <= 2^-24 F(pi/2, m); the
        // lookup's own float arithmetic adds a few more such ulps.
        const double bound = h * h / 8.0 * max_second_derivative(m) + 4.0 * std::ldexp(full, -24);
        double err_m = 0;
        for (int i = 0; i <= 16 * 1023; ++i) {
            const float phi = float(kHalfPi * i / (16.0 * 1023.0));
            const double p = std::min(double(phi), kHalfPi);
            double exact = 0;
            ASSERT_EQ(el_cos_power_integral(p, m, &exact), EL_OK);
            float got = 0;
            ASSERT_EQ(el_highlight_table_lookup(t, phi, float(m), &got), EL_OK);
            err_m = std::max(err_m, std::fabs(got - exact));
        }
        EXPECT_LE(err_m, bound) << "m = " << m;
        if (err_m > worst) {
            worst = err_m;
            worst_m = m;
        }
        worst_ratio = std::max(worst_ratio, err_m / bound);
    }
    EXPECT_LE(worst, paper_bound + 4.0 * std::ldexp(1.0, -24));
    std::printf(
        "[ paper 1024x128 ] bound h^2/8 max|F''| at m=128: %.4g; measured max error %.4g (m = %d); "
        "max measured/bound over m: %.3f\n",
        paper_bound, worst, worst_m, worst_ratio);
    el_highlight_table_destroy(t);
}

// Between integer rows the paper's table interpolates linearly in m: far less accurate there
// (F is convex in m), which is why EdgeLight's default is the warped layout.
TEST(HighlightTablePaper, BetweenIntegerExponents) {
    el_table_desc desc{EL_TABLE_PAPER, 1024, 128, 0.0f};
    el_highlight_table* t = nullptr;
    ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK);
    double worst = 0;
    for (double m = 1.5; m < 128; m += 1.0)
        for (int i = 0; i <= 200; ++i) {
            const double phi = kHalfPi * i / 200.0;
            double exact = 0;
            ASSERT_EQ(el_cos_power_integral(phi, m, &exact), EL_OK);
            float got = 0;
            ASSERT_EQ(el_highlight_table_lookup(t, float(phi), float(m), &got), EL_OK);
            worst = std::max(worst, std::fabs(got - exact));
        }
    EXPECT_GT(worst, 1e-3);  // measurably worse than at the rows
    EXPECT_LT(worst, 5e-2);
    std::printf("[ paper 1024x128 ] max error at half-integer m: %.3g\n", worst);
    el_highlight_table_destroy(t);
}

TEST(HighlightTablePaper, LayoutIsRowMajorOverIntegerExponents) {
    el_table_desc desc{EL_TABLE_PAPER, 64, 8, 0.0f};
    el_highlight_table* t = nullptr;
    ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK);
    std::vector<float> data(64 * 8);
    ASSERT_EQ(el_highlight_table_copy(t, data.data(), data.size()), EL_OK) << el_last_error();
    for (int m = 1; m <= 8; ++m)
        for (int i = 0; i < 64; ++i) {
            double exact = 0;
            ASSERT_EQ(el_cos_power_integral(kHalfPi * i / 63.0, m, &exact), EL_OK);
            EXPECT_NEAR(data[(m - 1) * 64 + i], exact, 1e-7) << m << " " << i;
        }
    el_highlight_table_destroy(t);
}

}  // namespace
