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
HighlightTable build_highlight_table(int32_t layout, uint32_t phi_count, uint32_t m_count,
                                     float m_max);

// Everything a lookup needs that depends on m only: the two rows, their weight, and the phi and
// output scales. A pixel computes this once and reads several phi from it.
struct TableRow {
    const float* row0;
    const float* row1;
    float row_weight;   // weight of row1
    float phi_to_texel; // texel coordinate per radian
    float out_scale;    // F = out_scale * bilinear value (1/sqrt(m) for WARPED)
};

// m in [1, table.m_max].
TableRow table_row(const HighlightTable& table, float m);

// F(phi, m) for phi in [-pi/2, pi/2], float32 arithmetic only.
float table_lookup(const HighlightTable& table, const TableRow& row, float phi);

}  // namespace el
