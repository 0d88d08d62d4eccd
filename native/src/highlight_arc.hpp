// The per-pixel rounded-edge integral in float32, written step for step as the edge_highlight
// fragment shader does it (docs/highlight_math.md): frame, windows, closed form through the
// table, Gauss-Legendre for short arcs, blend weight.
#pragma once

#include "highlight_table.hpp"

#include <edgelight/edgelight.h>

namespace el {

// Conventions that define the result in degenerate configurations. The double reference uses
// the same numbers, so they are definitions, not tolerances (docs/highlight_math.md).
//  - N1 ~ -N2: when N1.N2 < 0 and |(N1 x N2).E| <= kAntiparallelBand (unit projected normals) the
//    arc is the half circle from N1 turning positively about edge_dir.
//  - View along the edge: W is multiplied by clamp((|E x V| - s0) / s0, 0, 1), s0 = kAxialRampS0.
inline constexpr double kAntiparallelBand = 1e-6;
inline constexpr double kAxialRampS0 = 1e-2;

// A normal is rejected when |n x E| < kMinNormalSine |n| (it says nothing about the arc).
inline constexpr double kMinNormalSine = 1e-3;

// Short-arc switch: the lit and visible interval of length L (and, for the denominator, the
// visible one) is integrated with kGaussPoints-point Gauss-Legendre when L sqrt(n + 1) <=
// kGaussSpan, i.e. when it spans at most 4 widths of the cos^n peak; longer ones through the
// table and the closed form (docs/highlight_math.md, "Short arcs").
inline constexpr int kGaussPoints = 8;
inline constexpr float kGaussSpan = 4.0f;

// Which branch produced a result (tests and benchmarks look at it).
enum class ArcPath { Empty, Gauss, Mixed, Table };

struct ArcTrace {
    ArcPath specular = ArcPath::Empty;
    ArcPath diffuse = ArcPath::Empty;
};

// Inputs must have passed capi_highlight.cpp's validation; the result is then always finite,
// with specular, diffuse, weight and visible_fraction in [0, 1].
el_highlight_result highlight_eval(const HighlightTable& table, const el_highlight_input& in,
                                   ArcTrace* trace = nullptr);

// W = K r_e / (d r_max) clamped to [0, 1]; r_max = 0 (the "nothing visible" value) gives 0.
float highlight_weight(float K, float r_e, float d, float r_max);

}  // namespace el
