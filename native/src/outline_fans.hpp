// The surface pass's outline lists where faces are wider than every strip and corner zone: per
// triangle the rounded edges (or corner patches) at its corners that lie flat with it or run
// along its own sides (el_outline_fans in edgelight.h).
#pragma once

#include <cstdint>
#include <vector>

namespace el {

struct FanItems {
    const int32_t* verts;  // verts_per_item per item, -1: none
    uint32_t verts_per_item;
    const float* normals;  // normals_per_item * 3 per item
    uint32_t normals_per_item;
    uint32_t count;
    bool own_sides;  // items are edges (two vertices): tell the triangle's own sides
};

// out: triangle_count * per floats, item + 1 (0: none).
void outline_fans(const uint32_t* tri_verts, const float* tri_normals, uint32_t triangle_count, const FanItems& items,
                  float cos_max, uint32_t per, float* out);

}  // namespace el
