// The F(phi, m) lookup table (docs/highlight_math.md, "Tables"): built in double, stored as
// float32 exactly as the shader's R32F texture, and read back with the shader's arithmetic.
#pragma once

#include <edgelight/edgelight.h>

#include <cstdint>
#include <vector>

namespace el {

// EL_TABLE_WARPED's c in phi_end(m) = min(pi/2, c / sqrt(m)) is at least kWarpCMin:
// cos^m(phi_end) <= exp(-c^2/2) = 1.5e-8, so F beyond phi_end differs from F(phi_end) by < 1e-9
// of F(pi/2, m). It is then raised to the nearest value that puts the kink of phi_end(m), at
// m = (2c/pi)^2, exactly on a row: linear interpolation across a kink would cost 1e-2.
inline constexpr double kWarpCMin = 6.0;

// The c a warped table of these dimensions uses.
float warp_c_for(uint32_t m_count, float m_max);

// EL_TABLE_BICUBIC's phi_end(m) = ((2/pi)^6 + m^3/c^6)^(-1/6), a smooth minimum of pi/2 and
// c/sqrt(m): bicubic interpolation across rows needs phi_end smooth in ln m (WARPED's kink would
// cost first-order error). It is below both, by at most 2^(-1/6) where they cross, so c is raised
// to 6.5: the effective c stays >= 5.79 and the tail beyond phi_end below 1e-8 / sqrt(m); at m = 1
// phi_end misses pi/2 by 9e-5 rad, a change of F below 1e-8.
inline constexpr double kBicubicC = 6.5;
inline constexpr uint32_t kBicubicMinCount = 4;  // the 4-point stencil

// Creation limits: the byte size must fit an int32 (GPU upload APIs count bytes in int), and the
// warped exponent range must stay where the float path is meaningful.
inline constexpr uint64_t kMaxTableFloats = (uint64_t(1) << 29) - 1;
inline constexpr float kMaxTableExponent = 1e6f;

struct HighlightTable {
    int32_t layout = EL_TABLE_WARPED;
    uint32_t phi_count = 0;
    uint32_t m_count = 0;
    float m_max = 0.0f;   // largest m the table covers (PAPER: m_count)
    float warp_c = 0.0f;  // WARPED only
    float log_m_max = 0.0f;
    std::vector<float> data;  // m_count rows of phi_count
};

// Builds a table; arguments must already be valid (capi_highlight.cpp checks them).
// c_override > 0 replaces BICUBIC's c (for the table study only).
HighlightTable build_highlight_table(int32_t layout, uint32_t phi_count, uint32_t m_count,
                                     float m_max, double c_override = 0.0);

// Everything a lookup needs that depends on m only: the rows, their weights, and the phi and
// output scales. A pixel computes this once and reads several phi from it.
struct TableRow {
    const float* row0;   // first row of the stencil (2 rows, or 4 for BICUBIC)
    float row_frac;      // y - j0 (the shader's row.y)
    float row_w[4];      // weights of rows j0 .. j0+3 (linear: 1 - frac, frac)
    float phi_to_texel;  // texel coordinate per radian
    float out_scale;     // F = out_scale * interpolated value (1/sqrt(m) for WARPED and BICUBIC)
};

// Weights of the cubic Lagrange polynomial through nodes 0, 1, 2, 3 at s in [0, 3], in the
// shader's operation order.
inline void lagrange4(float s, float w[4]) {
    const float a = s, b = s - 1.0f, c = s - 2.0f, d = s - 3.0f;
    w[0] = -(b * c * d) * (1.0f / 6.0f);
    w[1] = (a * c * d) * 0.5f;
    w[2] = -(a * b * d) * 0.5f;
    w[3] = (a * b * c) * (1.0f / 6.0f);
}

// BICUBIC's phi_end(m) in float, as the shader computes it.
float bicubic_phi_end(float m, float c);

// m in [1, table.m_max].
TableRow table_row(const HighlightTable& table, float m);

// F(phi, m) for phi in [-pi/2, pi/2], float32 arithmetic only.
float table_lookup(const HighlightTable& table, const TableRow& row, float phi);

}  // namespace el
