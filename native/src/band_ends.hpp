// Where a rounded edge's band ends on each of its faces (el_band_ends in edgelight.h;
// docs/highlight_math.md, "Band ends").
#pragma once

#include <edgelight/edgelight.h>

#include <cstdint>

namespace el {

struct BandEndInputs {
    const el_polygons* polys;
    const float* positions;  // 3 per vertex
    uint32_t vertex_count;
    const uint32_t* edges;      // 2 per edge
    const float* edge_normals;  // 6 per edge
    const uint8_t* rounded;     // per edge
    const uint8_t* smooth;      // per edge, or null
    const int32_t* edge_polys;  // 2 per edge, or null
    uint32_t edge_count;
};

// out: 4 angles per selected edge.
void band_ends(const BandEndInputs& in, const uint32_t* selected, const int32_t* faces, uint32_t count, float* out);

}  // namespace el
