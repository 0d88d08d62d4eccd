// F(phi, m) = int_0^phi cos^m and G(a, b, n) = int_a^b cos^n sin: closed forms, the reduction
// recurrence, and the same identities read back through both table layouts.
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

constexpr double kPi = std::numbers::pi;

double F(double phi, double m) {
    double v = NAN;
    EXPECT_EQ(el_cos_power_integral(phi, m, &v), EL_OK) << el_last_error();
    return v;
}

double G(double a, double b, double n) {
    double v = NAN;
    EXPECT_EQ(el_cos_power_sin_integral(a, b, n, &v), EL_OK) << el_last_error();
    return v;
}

// cos^p(phi) without the rounding of cos near 1 (what the recurrence's first term needs).
double cos_pow(double phi, double p) {
    const double s = std::sin(0.5 * phi);
    return std::exp(p * std::log1p(-2.0 * s * s));
}

TEST(HighlightCosPower, ClosedFormsForExponentsOneAndTwo) {
    double worst1 = 0, worst2 = 0;
    for (int i = 0; i <= 4000; ++i) {
        const double phi = -0.5 * kPi + kPi * i / 4000.0;
        worst1 = std::max(worst1, std::fabs(F(phi, 1) - std::sin(phi)));
        worst2 = std::max(worst2, std::fabs(F(phi, 2) - (phi / 2 + std::sin(2 * phi) / 4)));
    }
    EXPECT_LT(worst1, 2e-15);
    EXPECT_LT(worst2, 2e-15);
    EXPECT_DOUBLE_EQ(F(0.3, 0), 0.3);  // m = 0: F = phi
    EXPECT_EQ(F(0.0, 7.5), 0.0);
}

TEST(HighlightCosPower, OddInPhi) {
    for (double m : {1.0, 2.5, 40.0, 9999.5})
        for (double phi : {1e-9, 0.01, 0.7, 1.5})
            EXPECT_EQ(F(-phi, m), -F(phi, m)) << phi << " " << m;
}

// F(phi, n) = cos^(n-1) phi sin phi / n + (n-1)/n F(phi, n-2), for integer and real n, up to
// the largest exponents the tables cover. Errors are relative to F(pi/2, n).
TEST(HighlightCosPower, ReductionRecurrence) {
    // The continued fraction takes O(sqrt(n)) steps, so its rounding grows like sqrt(n) eps.
    double worst_small = 0, worst_large = 0;
    for (double n : {2.0, 3.0, 4.5, 7.25, 20.0, 101.5, 1000.0, 3333.3, 10001.0, 123456.7}) {
        const double scale = F(0.5 * kPi, n);
        double& worst = n <= 10001.0 ? worst_small : worst_large;
        for (int i = 0; i <= 2000; ++i) {
            const double phi = -0.5 * kPi + kPi * i / 2000.0;
            const double rhs = cos_pow(phi, n - 1) * std::sin(phi) / n + (n - 1) / n * F(phi, n - 2);
            worst = std::max(worst, std::fabs(F(phi, n) - rhs) / scale);
        }
    }
    EXPECT_LT(worst_small, 5e-14);
    EXPECT_LT(worst_large, 5e-13);
    std::printf("[ recurrence ] max |F(n) - rhs| / F(pi/2, n) = %.3g (n <= 10001), %.3g (n = 123456.7)\n",
                worst_small, worst_large);
}

// Wallis: F(pi/2, n) / F(pi/2, n-2) = (n-1)/n, and F(pi/2, n) -> sqrt(pi / (2n)).
TEST(HighlightCosPower, FullIntegral) {
    for (double n : {2.0, 3.0, 10.5, 149.0, 151.0, 1e4, 1e6})
        EXPECT_NEAR(F(0.5 * kPi, n) / F(0.5 * kPi, n - 2), (n - 1) / n, 1e-14) << n;
    EXPECT_NEAR(F(0.5 * kPi, 1e9) / std::sqrt(kPi / 2e9), 1.0 - 1.0 / 4e9, 1e-14);
    EXPECT_NEAR(F(0.5 * kPi, 2), kPi / 4, 1e-15);
    EXPECT_NEAR(F(0.5 * kPi, 3), 2.0 / 3.0, 1e-15);
}

// The closed-form second term against direct numeric integration (composite 8-point
// Gauss-Legendre on 4000 panels), including arcs too short for a naive difference. Errors are
// relative to int |cos^n sin| (the integrand changes sign at 0, where the result may cancel).
TEST(HighlightCosPower, SinTermAgainstNumericIntegration) {
    static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    auto numeric = [&](double a, double b, double n, bool absolute) {
        const int panels = 4000;
        const double h = (b - a) / panels;
        double sum = 0;
        for (int p = 0; p < panels; ++p) {
            const double c = a + (p + 0.5) * h;
            for (int k = 0; k < 4; ++k)
                for (double s : {-1.0, 1.0}) {
                    const double t = c + s * 0.5 * h * x[k];
                    const double f = cos_pow(t, n) * std::sin(t);
                    sum += w[k] * 0.5 * h * (absolute ? std::fabs(f) : f);
                }
        }
        return sum;
    };
    double worst = 0;
    for (double n : {0.0, 1.0, 2.5, 30.0, 1000.0, 10000.0})
        for (double a : {-1.5, -0.4, 0.0, 0.01, 0.9})
            for (double len : {1e-7, 1e-3, 0.3, 1.2}) {
                const double b = std::min(a + len, 0.5 * kPi);
                const double g = G(a, b, n), ref = numeric(a, b, n, false);
                const double scale = std::max(numeric(a, b, n, true), 1e-300);
                worst = std::max(worst, std::fabs(g - ref) / scale);
                EXPECT_NEAR(G(b, a, n), -g, 1e-15 * std::fabs(g) + 1e-300);
                if (len == 0.3) {  // well-separated ends: the plain formula agrees
                    EXPECT_NEAR(g, (cos_pow(a, n + 1) - cos_pow(b, n + 1)) / (n + 1), 1e-14);
                }
            }
    EXPECT_LT(worst, 1e-12);
    std::printf("[ sin term ] max relative error vs numeric = %.3g\n", worst);
}

// The same closed forms read back through a table (float32 storage and interpolation).
TEST(HighlightCosPower, ClosedFormsThroughTables) {
    for (el_table_desc desc : {el_table_desc{EL_TABLE_PAPER, 1024, 128, 0.0f},
                               el_table_desc{EL_TABLE_WARPED, 256, 256, 10001.0f},
                               el_table_desc EL_TABLE_DEFAULT_DESC}) {
        el_highlight_table* t = nullptr;
        ASSERT_EQ(el_highlight_table_create(&desc, &t), EL_OK) << el_last_error();
        double worst1 = 0, worst2 = 0;
        for (int i = 0; i <= 3000; ++i) {
            const float phi = float(-0.5 * kPi + kPi * i / 3000.0);
            const double p = std::clamp(double(phi), -0.5 * kPi, 0.5 * kPi);
            float f1 = NAN, f2 = NAN;
            ASSERT_EQ(el_highlight_table_lookup(t, phi, 1.0f, &f1), EL_OK) << el_last_error();
            ASSERT_EQ(el_highlight_table_lookup(t, phi, 2.0f, &f2), EL_OK) << el_last_error();
            worst1 = std::max(worst1, std::fabs(f1 - std::sin(p)));
            worst2 = std::max(worst2, std::fabs(f2 - (p / 2 + std::sin(2 * p) / 4)));
        }
        // Interpolation: h^2/8 max|F''| (PAPER: h = pi/2/1023 -> 2.9e-7; WARPED rows are
        // bilinear in ln m, see test_highlight_table_warped) plus float32 rounding.
        const double bound = desc.layout == EL_TABLE_PAPER ? 4e-7 : 3e-5;
        EXPECT_LT(worst1, bound) << desc.layout;
        EXPECT_LT(worst2, bound) << desc.layout;
        std::printf("[ tables ] layout %d: max |F(phi,1) - sin| = %.3g, max |F(phi,2) - ...| = %.3g\n",
                    desc.layout, worst1, worst2);
        el_highlight_table_destroy(t);
    }
}

}  // namespace
