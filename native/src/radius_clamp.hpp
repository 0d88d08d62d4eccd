// The radius clamp: how wide a rounded edge's faces are across it, so that its fillets fit
// (el_width_bounds in edgelight.h; the walks across smooth patches are still the add-on's).
#pragma once

#include <edgelight/edgelight.h>

#include <cstdint>

namespace el {

// out: 2 per edge, the farthest of three corners of each side's polygon from the edge's line.
void width_bounds(const el_polygons& polys, const float* positions, const uint32_t* edges, const int32_t* edge_polys,
                  uint32_t count, double* out);

}  // namespace el
