// Table construction (double) and lookup (float, the shader's steps).
//
// Each row is a cumulative integral: F(x_{i+1}) = F(x_i) + integral over [x_i, x_{i+1}], the
// interval split into panels no wider than 1/sqrt(m) (the width of the cos^m peak) and each panel
// integrated with 8-point Gauss-Legendre. On a panel of one peak width the rule's error is below
// 1e-16 relative, so the rows are exact to double rounding before they are stored as float32.
#include "highlight_table.hpp"

#include "cos_power_integral.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace el {

namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;

// 8-point Gauss-Legendre on [-1, 1].
constexpr double kGLx[4] = {0.183434642495649804939476142360184, 0.525532409916328985817739049189246,
                            0.796666477413626739591553936475831, 0.960289856497536231683560868569473};
constexpr double kGLw[4] = {0.362683783378361982965150449277196, 0.313706645877887287337962201986601,
                            0.222381034453374470544355994426241, 0.101228536290376259152531354309962};

double integrate_cos_power(double a, double b, double m) {
    const double width = b - a;
    const int panels = std::max(1, int(std::ceil(width * std::sqrt(std::max(m, 1.0)))));
    const double h = width / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p) {
        const double mid = a + (p + 0.5) * h, half = 0.5 * h;
        double s = 0.0;
        for (int k = 0; k < 4; ++k)
            s += kGLw[k] * (cos_power(mid - half * kGLx[k], m) + cos_power(mid + half * kGLx[k], m));
        sum += s * half;
    }
    return sum;
}

// Fills one row: values scale * F(x_i * phi_end, m) at x_i = i / (n - 1).
void fill_row(float* out, uint32_t n, double m, double phi_end, double scale) {
    double acc = 0.0, prev = 0.0;
    out[0] = 0.0f;
    for (uint32_t i = 1; i < n; ++i) {
        const double phi = phi_end * double(i) / double(n - 1);
        acc += integrate_cos_power(prev, phi, m);
        prev = phi;
        out[i] = float(scale * acc);
    }
}

double row_exponent(uint32_t j, uint32_t m_count, float m_max) {
    // Row j holds m_j = m_max^(j/(M-1)); the last row is exactly m_max.
    if (j + 1 == m_count) return double(m_max);
    return std::exp(std::log(double(m_max)) * double(j) / double(m_count - 1));
}

}  // namespace

float warp_c_for(uint32_t m_count, float m_max) {
    for (uint32_t j = 0; j < m_count; ++j) {
        const double c = kHalfPi * std::sqrt(row_exponent(j, m_count, m_max));
        if (c >= kWarpCMin) return float(c);
    }
    return float(kHalfPi * std::sqrt(double(m_max)));  // phi_end = pi/2 on every row
}

float bicubic_phi_end(float m, float c) {
    const float k = 0.405284735f;  // (2/pi)^2
    const float r = m / (c * c);
    return std::exp(std::log(k * k * k + r * r * r) * (-1.0f / 6.0f));  // GLSL has no cbrt
}

namespace {

double bicubic_phi_end_exact(double m, double c) {
    const double k = 1.0 / (kHalfPi * kHalfPi), r = m / (c * c);
    return 1.0 / std::sqrt(std::cbrt(k * k * k + r * r * r));
}

}  // namespace

HighlightTable build_highlight_table(int32_t layout, uint32_t phi_count, uint32_t m_count,
                                     float m_max, double c_override) {
    HighlightTable t;
    t.layout = layout;
    t.phi_count = phi_count;
    t.m_count = m_count;
    t.data.resize(size_t(phi_count) * m_count);
    if (layout == EL_TABLE_PAPER) {
        t.m_max = float(m_count);
        for (uint32_t j = 0; j < m_count; ++j)
            fill_row(&t.data[size_t(j) * phi_count], phi_count, double(j + 1), kHalfPi, 1.0);
        return t;
    }
    t.m_max = m_max;
    t.log_m_max = std::log(m_max);
    if (layout == EL_TABLE_BICUBIC) {
        t.warp_c = float(c_override > 0.0 ? c_override : kBicubicC);
        for (uint32_t j = 0; j < m_count; ++j) {
            const double m = row_exponent(j, m_count, m_max);
            // phi_end from the float c the shader gets, so that both place the texels alike.
            const double phi_end = std::min(kHalfPi, bicubic_phi_end_exact(m, double(t.warp_c)));
            fill_row(&t.data[size_t(j) * phi_count], phi_count, m, phi_end, std::sqrt(m));
        }
        return t;
    }
    t.warp_c = warp_c_for(m_count, m_max);
    for (uint32_t j = 0; j < m_count; ++j) {
        const double m = row_exponent(j, m_count, m_max);
        const double phi_end = std::min(kHalfPi, double(t.warp_c) / std::sqrt(m));
        fill_row(&t.data[size_t(j) * phi_count], phi_count, m, phi_end, std::sqrt(m));
    }
    return t;
}

TableRow table_row(const HighlightTable& t, float m) {
    TableRow r{};
    const float last_row = float(t.m_count - 1);
    float y;
    if (t.layout == EL_TABLE_PAPER) {
        y = m - 1.0f;  // row j holds m = j + 1
        r.phi_to_texel = float(t.phi_count - 1) / 1.57079632679f;
        r.out_scale = 1.0f;
    } else {
        y = std::log(m) / t.log_m_max * last_row;
        const float phi_end = t.layout == EL_TABLE_BICUBIC
                                  ? std::min(1.57079632679f, bicubic_phi_end(m, t.warp_c))
                                  : std::min(1.57079632679f, t.warp_c / std::sqrt(m));
        r.phi_to_texel = float(t.phi_count - 1) / phi_end;
        r.out_scale = 1.0f / std::sqrt(m);
    }
    y = std::clamp(y, 0.0f, last_row);
    float j;
    if (t.layout == EL_TABLE_BICUBIC) {
        // Rows j0 .. j0+3 around y (shifted inwards at the ends).
        j = std::clamp(std::floor(y) - 1.0f, 0.0f, last_row - 3.0f);
        r.row_frac = y - j;
        lagrange4(r.row_frac, r.row_w);
    } else {
        j = std::min(std::floor(y), last_row - 1.0f);
        r.row_frac = y - j;
        r.row_w[0] = 1.0f - r.row_frac;
        r.row_w[1] = r.row_frac;
    }
    r.row0 = t.data.data() + size_t(j) * t.phi_count;
    return r;
}

float table_lookup(const HighlightTable& t, const TableRow& r, float phi) {
    const float last = float(t.phi_count - 1);
    // Beyond phi_end the warped rows are constant, so clamping the texel coordinate is exact.
    const float x = std::min(std::fabs(phi) * r.phi_to_texel, last);
    if (t.layout == EL_TABLE_BICUBIC) {
        const float i = std::clamp(std::floor(x) - 1.0f, 0.0f, last - 3.0f);
        float wx[4];
        lagrange4(x - i, wx);
        const size_t k = size_t(i);
        float v = 0.0f;
        for (int row = 0; row < 4; ++row) {
            const float* p = r.row0 + size_t(row) * t.phi_count + k;
            const float s = wx[0] * p[0] + wx[1] * p[1] + wx[2] * p[2] + wx[3] * p[3];
            v += r.row_w[row] * s;
        }
        return std::copysign(v * r.out_scale, phi);
    }
    const float i = std::min(std::floor(x), last - 1.0f);
    const float fx = x - i;
    const size_t k = size_t(i);
    const float* row1 = r.row0 + t.phi_count;
    const float v0 = r.row0[k] + fx * (r.row0[k + 1] - r.row0[k]);
    const float v1 = row1[k] + fx * (row1[k + 1] - row1[k]);
    const float v = v0 + r.row_frac * (v1 - v0);
    return std::copysign(v * r.out_scale, phi);
}

}  // namespace el
