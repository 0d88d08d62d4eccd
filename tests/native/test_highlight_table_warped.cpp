// EdgeLight's default table: warped in phi (x = phi / phi_end(m)) and in m (t = ln m / ln m_max),
// storing sqrt(m) F. Its error is measured over m in [1, 10001] (rows, between rows, integer and
// non-integer m) and phi in [0, pi/2], against the exact F.
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;

double exact_F(double phi, double m) {
    double v = 0;
    EXPECT_EQ(el_cos_power_integral(phi, m, &v), EL_OK);
    return v;
}

struct Errors {
    double abs = 0, rel = 0;  // rel: to F(pi/2, m)
    double abs_m = 0, abs_phi = 0;
};

Errors measure(const el_highlight_table* t, const std::vector<double>& ms, float c) {
    Errors e;
    for (double m0 : ms) {
        const float mf = float(m0);
        const double m = mf;
        const double full = exact_F(kHalfPi, m);
        const double phi_end = std::min(kHalfPi, c / std::sqrt(m));
        // Dense where F varies (inside phi_end, 4 samples per texel), sparse beyond it.
        for (int i = 0; i <= 1200; ++i) {
            const double phi = i <= 1024 ? phi_end * i / 1024.0
                                         : phi_end + (kHalfPi - phi_end) * (i - 1024) / 176.0;
            const float pf = float(phi);
            const double p = std::min(double(pf), kHalfPi);
            float got = 0;
            EXPECT_EQ(el_highlight_table_lookup(t, pf, mf, &got), EL_OK);
            const double err = std::fabs(got - exact_F(p, m));
            if (err > e.abs) {
                e.abs = err;
                e.abs_m = m;
                e.abs_phi = p;
            }
            e.rel = std::max(e.rel, err / full);
        }
    }
    return e;
}

TEST(HighlightTableWarped, DefaultTableErrorOverTheWholeRange) {
    el_table_desc desc{EL_TABLE_WARPED, 256, 256, 10001.0f};
    el_highlight_table* t = nullptr;
    ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK) << el_last_error();
    el_table_info info{};
    ASSERT_EQ(el_highlight_table_get_info(t, &info), EL_OK);
    EXPECT_EQ(info.layout, EL_TABLE_WARPED);
    EXPECT_EQ(info.m_max, 10001.0f);
    EXPECT_GE(info.warp_c, 6.0f);  // cos^m beyond phi_end <= exp(-c^2/2) < 1.6e-8
    EXPECT_LT(info.warp_c, 6.5f);

    std::vector<double> ms;
    for (int j = 0; j < 256; ++j) {  // on the rows and half-way between them
        ms.push_back(std::pow(10001.0, j / 255.0));
        if (j < 255) ms.push_back(std::pow(10001.0, (j + 0.5) / 255.0));
    }
    for (int m = 1; m <= 64; ++m) ms.push_back(m);  // small integer exponents
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, std::log(10001.0));
    for (int k = 0; k < 300; ++k) ms.push_back(std::exp(u(rng)));  // any real m
    ms.push_back(10001.0);

    const Errors e = measure(t, ms, info.warp_c);
    // Stated bounds for the default 256 x 256 table (docs/highlight_math.md).
    EXPECT_LT(e.abs, 3e-5);
    EXPECT_LT(e.rel, 6e-5);
    std::printf("[ warped 256x256 ] c = %.4f: max |error| %.3g (m = %.4g, phi = %.4g), max |error| / F(pi/2,m) %.3g\n",
                info.warp_c, e.abs, e.abs_m, e.abs_phi, e.rel);
    el_highlight_table_destroy(t);
}

// Bigger tables converge like h^2 in both directions.
TEST(HighlightTableWarped, ErrorShrinksWithSize) {
    std::vector<double> ms;
    for (int k = 0; k <= 200; ++k) ms.push_back(std::pow(10001.0, k / 200.0 + 0.00123));
    ms.back() = 10001.0;
    double prev = 1.0;
    for (uint32_t n : {64u, 128u, 256u}) {
        el_table_desc desc{EL_TABLE_WARPED, n, n, 10001.0f};
        el_highlight_table* t = nullptr;
        ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK);
        el_table_info info{};
        ASSERT_EQ(el_highlight_table_get_info(t, &info), EL_OK);
        const double err = measure(t, ms, info.warp_c).abs;
        EXPECT_LT(err, prev / 3.0) << n;
        std::printf("[ warped %ux%u ] max |error| %.3g\n", n, n, err);
        prev = err;
        el_highlight_table_destroy(t);
    }
}

TEST(HighlightTableWarped, Layout) {
    el_table_desc desc{EL_TABLE_WARPED, 32, 16, 10001.0f};
    el_highlight_table* t = nullptr;
    ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK);
    el_table_info info{};
    ASSERT_EQ(el_highlight_table_get_info(t, &info), EL_OK);
    std::vector<float> data(32 * 16);
    ASSERT_EQ(el_highlight_table_copy(t, data.data(), data.size()), EL_OK);
    for (int j = 0; j < 16; ++j) {
        const double m = j == 15 ? 10001.0 : std::pow(10001.0, j / 15.0);
        const double phi_end = std::min(kHalfPi, info.warp_c / std::sqrt(m));
        for (int i = 0; i < 32; ++i)
            EXPECT_NEAR(data[j * 32 + i], std::sqrt(m) * exact_F(phi_end * i / 31.0, m), 2e-7)
                << j << " " << i;
        // The last column holds sqrt(m) F(phi_end) = sqrt(m) F(pi/2) to float precision.
        EXPECT_NEAR(data[j * 32 + 31], std::sqrt(m) * exact_F(kHalfPi, m), 2e-7) << j;
    }
    // The kink of phi_end(m) at m = (2c/pi)^2 lies on a row.
    const double t_kink = std::log(std::pow(2.0 * info.warp_c / std::numbers::pi, 2)) / std::log(10001.0);
    EXPECT_NEAR(t_kink * 15.0, std::round(t_kink * 15.0), 1e-4);
    el_highlight_table_destroy(t);
}

}  // namespace
