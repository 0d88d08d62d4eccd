// F(phi, m) through the incomplete beta function. With x = sin^2 t, cos^m t dt =
// 1/2 x^(-1/2) (1-x)^((m-1)/2) dx, so F(phi, m) = 1/2 B_x(1/2, b) with b = (m+1)/2 and
// x = sin^2 phi. B_x is evaluated by the usual continued fraction (Numerical Recipes' betacf,
// modified Lentz), which converges fast for x < (a+1)/(a+b+2); above that the symmetry
// B_x(a, b) = B(a, b) - B_(1-x)(b, a) is used, which subtracts a smaller quantity from a larger one.
#include "cos_power_integral.hpp"

#include <cmath>
#include <numbers>

namespace el {

namespace {

constexpr double kPi = std::numbers::pi;

// Continued fraction for B_x(a, b) / (x^a (1-x)^b / a).
double beta_continued_fraction(double a, double b, double x) {
    constexpr int kMaxIter = 1000000;
    constexpr double kEps = 1e-16;
    constexpr double kTiny = 1e-300;
    const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
    double c = 1.0;
    double d = 1.0 - qab * x / qap;
    if (std::fabs(d) < kTiny) d = kTiny;
    d = 1.0 / d;
    double h = d;
    for (int k = 1; k <= kMaxIter; ++k) {
        const double k2 = 2.0 * k;
        double aa = k * (b - k) * x / ((qam + k2) * (a + k2));
        d = 1.0 + aa * d;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = 1.0 + aa / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        h *= d * c;
        aa = -(a + k) * (qab + k) * x / ((a + k2) * (qap + k2));
        d = 1.0 + aa * d;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = 1.0 + aa / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double del = d * c;
        h *= del;
        if (std::fabs(del - 1.0) < kEps) break;
    }
    return h;
}

// ln(Gamma(b) / Gamma(b + 1/2)). Small b: tgamma is accurate to a few ulp. Large b: the
// difference of two Stirling series, arranged so that nothing of size ln(b) * b cancels.
double log_gamma_half_ratio(double b) {
    if (b < 150.0) return std::log(std::tgamma(b) / std::tgamma(b + 0.5));
    // 1/2 - b log1p(x) with x = 1/(2b), as a series: 1/2 * sum (-1)^(j+1) x^j / (j+1).
    const double x = 0.5 / b;
    double series = 0.0, xp = x;
    for (int j = 1; j <= 12; ++j, xp *= x) series += ((j % 2) ? 1.0 : -1.0) * xp / (j + 1);
    // Stirling tail sum B_2k / (2k (2k-1) z^(2k-1)), k = 1..5.
    auto tail = [](double z) {
        const double z2 = z * z;
        const double iz = 1.0 / z, iz2 = 1.0 / z2;
        return iz * (1.0 / 12.0 +
                     iz2 * (-1.0 / 360.0 +
                            iz2 * (1.0 / 1260.0 + iz2 * (-1.0 / 1680.0 + iz2 * (1.0 / 1188.0)))));
    };
    return -0.5 * std::log(b) + 0.5 * series + tail(b) - tail(b + 0.5);
}

}  // namespace

double log_cos(double t) {
    const double s = std::sin(0.5 * t);
    // cos t = 1 - 2 sin^2(t/2): no rounding of cos t near 1. Clamped so |t| = pi/2 gives -inf.
    return std::log1p(std::fmax(-2.0 * s * s, -1.0));
}

double cos_power(double t, double m) {
    if (m == 0.0) return 1.0;
    const double c = std::cos(t);
    if (c <= 0.0) return 0.0;
    return std::exp(m * log_cos(t));
}

double cos_power_integral_full(double m) {
    const double b = 0.5 * (m + 1.0);
    return 0.5 * std::sqrt(kPi) * std::exp(log_gamma_half_ratio(b));
}

double cos_power_integral(double phi, double m) {
    if (phi == 0.0) return 0.0;
    const double sign = phi < 0.0 ? -1.0 : 1.0;
    const double p = std::fabs(phi);
    if (m == 0.0) return phi;
    const double a = 0.5, b = 0.5 * (m + 1.0);
    const double s = std::sin(p);
    const double x = s * s;
    // x^a (1-x)^b = sin(p) * cos^(m+1)(p)
    const double front = s * cos_power(p, m + 1.0);
    if (x < (a + 1.0) / (a + b + 2.0)) {
        // 1/2 B_x(1/2, b) = 1/2 * front * cf / (1/2)
        return sign * front * beta_continued_fraction(a, b, x);
    }
    const double c = std::cos(p);
    const double tail = 0.5 * front * beta_continued_fraction(b, a, c * c) / b;
    return sign * (cos_power_integral_full(m) - tail);
}

double cos_power_sin_integral(double a, double b, double n) {
    const double k = n + 1.0;
    const double ca = std::cos(a), cb = std::cos(b);
    if (!(ca > 0.0) && !(cb > 0.0)) return 0.0;
    // cos b - cos a = -2 sin((a+b)/2) sin((b-a)/2): exact for nearby a, b.
    const double diff = -2.0 * std::sin(0.5 * (a + b)) * std::sin(0.5 * (b - a));
    if (ca >= cb) {
        // (C(a) - C(b)) / k = C(a) * (1 - (cb/ca)^k) / k, with (cb/ca) = 1 + diff/ca
        const double r = std::log1p(std::fmax(diff / ca, -1.0));
        return cos_power(a, k) * -std::expm1(k * r) / k;
    }
    const double r = std::log1p(std::fmax(-diff / cb, -1.0));
    return -cos_power(b, k) * -std::expm1(k * r) / k;
}

}  // namespace el
