// Double-precision reference for el_highlight_eval: the arc integral done directly in 3-D by
// adaptive Gauss-Kronrod quadrature. It shares no code with the float path (no table, no closed
// form, no windows); only the conventions of highlight_arc.hpp that define degenerate cases.
#pragma once

#include <edgelight/edgelight.h>

namespace el {

// Relative tolerance of every integral (to the visible width, or the full width).
inline constexpr double kReferenceTolerance = 1e-12;

struct ReferenceStats {
    int panels = 0;  // Gauss-Kronrod panels evaluated
    bool converged = true;
};

// Inputs must have passed capi_highlight.cpp's validation.
el_highlight_result highlight_reference(const el_highlight_input& in, ReferenceStats* stats = nullptr);

}  // namespace el
