// Corner patches: where three rounded edges meet at a vertex, all convex or all concave, their
// fillets end on the ball touching the three faces (el_corner_patches in edgelight.h).
#pragma once

#include <cstdint>
#include <vector>

namespace el {

struct CornerPatch {
    uint32_t vertex;
    uint32_t edges[3];
    float normals[9];  // the sectors' unit normals: AB, BC, CA
    float radius;
    float centre[3];
    float fold;  // +1 convex, -1 concave
};

struct CornerInputs {
    const float* positions;  // 3 per vertex
    uint32_t vertex_count;
    const uint32_t* edges;      // 2 per edge
    const float* edge_normals;  // 6 per edge
    const uint8_t* convex;      // per edge
    const uint8_t* chosen;      // per edge
    const float* radius;        // per edge
    const uint8_t* stop;        // per edge, or null: the chosen
    uint32_t edge_count;
};

std::vector<CornerPatch> corner_patches(const CornerInputs& in);

}  // namespace el
