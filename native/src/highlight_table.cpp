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

HighlightTable build_highlight_table(int32_t layout, uint32_t phi_count, uint32_t m_count,
                                     float m_max) {
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
    t.warp_c = warp_c_for(m_count, m_max);
    t.log_m_max = std::log(m_max);
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
        const float phi_end = std::min(1.57079632679f, t.warp_c / std::sqrt(m));
        r.phi_to_texel = float(t.phi_count - 1) / phi_end;
        r.out_scale = 1.0f / std::sqrt(m);
    }
    y = std::clamp(y, 0.0f, last_row);
    const float j = std::min(std::floor(y), last_row - 1.0f);
    r.row_weight = y - j;
    r.row0 = t.data.data() + size_t(j) * t.phi_count;
    r.row1 = r.row0 + t.phi_count;
    return r;
}

float table_lookup(const HighlightTable& t, const TableRow& r, float phi) {
    const float last = float(t.phi_count - 1);
    // Beyond phi_end the warped rows are constant, so clamping the texel coordinate is exact.
    const float x = std::min(std::fabs(phi) * r.phi_to_texel, last);
    const float i = std::min(std::floor(x), last - 1.0f);
    const float fx = x - i;
    const size_t k = size_t(i);
    const float v0 = r.row0[k] + fx * (r.row0[k + 1] - r.row0[k]);
    const float v1 = r.row1[k] + fx * (r.row1[k + 1] - r.row1[k]);
    const float v = v0 + r.row_weight * (v1 - v0);
    return std::copysign(v * r.out_scale, phi);
}

}  // namespace el
