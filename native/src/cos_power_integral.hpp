// Exact F(phi, m) = integral_0^phi cos^m(t) dt and its companion integral_a^b cos^n(t) sin(t) dt,
// in double. These are the ground truth that the float32 tables are built against and tested
// with (docs/highlight_math.md, "The functions F and G").
#pragma once

namespace el {

// Largest exponent cos_power_integral accepts: the continued fraction needs O(sqrt(m)) steps.
inline constexpr double kCosPowerMaxExponent = 1e9;

// ln(cos t) for |t| <= pi/2, with relative accuracy also near t = 0 (log1p form).
double log_cos(double t);

// cos^m(t) for |t| <= pi/2, m >= 0, as exp(m ln cos t): relative error ~ eps * |m ln cos t|.
double cos_power(double t, double m);

// F(pi/2, m) = sqrt(pi)/2 * Gamma((m+1)/2) / Gamma(m/2 + 1), m >= 0.
double cos_power_integral_full(double m);

// F(phi, m) = 1/2 B(sin^2 phi; 1/2, (m+1)/2), odd in phi; |phi| <= pi/2, 0 <= m <= 1e9.
// Relative error ~1e-15 (incomplete beta continued fraction, modified Lentz).
double cos_power_integral(double phi, double m);

// G(a, b, n) = integral_a^b cos^n(t) sin(t) dt = (cos^(n+1) a - cos^(n+1) b) / (n+1),
// |a|, |b| <= pi/2, n >= 0, written so that nearby a and b do not cancel.
double cos_power_sin_integral(double a, double b, double n);

}  // namespace el
