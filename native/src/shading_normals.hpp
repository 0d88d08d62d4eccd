// The normals a rounded edge's band is shaded between at each of its ends: its faces' own,
// turned to the corner normals its sides are shaded with there (el_shading_normals).
#pragma once

#include <cstdint>

namespace el {

struct ShadingInputs {
    const float* positions;       // 3 per vertex
    const uint32_t* edges;        // 2 per edge
    const float* edge_normals;    // 6 per edge: N1, N2
    const int32_t* edge_faces;    // 2 per edge, -1: none
    const uint32_t* tri_verts;    // 3 per triangle
    const float* corner_normals;  // 9 per triangle
};

// out: 12 floats per selected edge.
void shading_normals(const ShadingInputs& in, const uint32_t* selected, uint32_t count, double max_turn_deg, float* out);

}  // namespace el
