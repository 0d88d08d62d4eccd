#include "outline_fans.hpp"

#include <algorithm>
#include <cmath>

namespace el {

void outline_fans(const uint32_t* tri_verts, const float* tri_normals, uint32_t triangle_count, const FanItems& items,
                  float cos_max, uint32_t per, float* out) {
    std::fill(out, out + size_t(triangle_count) * per, 0.0f);
    // The items at each vertex, in item order (CSR over the triangles' vertices: an item at a
    // vertex no triangle has is at no triangle's corner).
    uint32_t vmax = 0;
    for (size_t k = 0; k < 3 * size_t(triangle_count); ++k) vmax = std::max(vmax, tri_verts[k] + 1);
    auto listed = [&](int32_t v) { return v >= 0 && uint32_t(v) < vmax; };
    std::vector<uint32_t> start(size_t(vmax) + 1, 0), at_vertex;
    for (size_t k = 0; k < size_t(items.count) * items.verts_per_item; ++k)
        if (listed(items.verts[k])) ++start[size_t(items.verts[k]) + 1];
    for (size_t v = 0; v < vmax; ++v) start[v + 1] += start[v];
    at_vertex.resize(start[vmax]);
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (uint32_t i = 0; i < items.count; ++i)
            for (uint32_t j = 0; j < items.verts_per_item; ++j) {
                const int32_t v = items.verts[size_t(i) * items.verts_per_item + j];
                if (listed(v)) at_vertex[fill[size_t(v)]++] = i;
            }
    }
    std::vector<uint32_t> own, other;
    for (uint32_t t = 0; t < triangle_count; ++t) {
        own.clear();
        other.clear();
        const uint32_t* tv = tri_verts + 3 * size_t(t);
        const float* tn = tri_normals + 3 * size_t(t);
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = tv[c];
            if (v >= vmax) continue;
            for (uint32_t k = start[v]; k < start[size_t(v) + 1]; ++k) {
                const uint32_t item = at_vertex[k];
                bool is_own = false;
                if (items.own_sides) {
                    const int32_t* ends = items.verts + 2 * size_t(item);
                    const int64_t far = int64_t(ends[0]) == int64_t(v) ? ends[1] : ends[0];
                    int first = -1;
                    for (int j = 0; j < 3; ++j)
                        if (int64_t(tv[j]) == far) {
                            first = j;
                            break;
                        }
                    is_own = first >= 0;
                    if (is_own && first < c) continue;  // an own side is reached from both ends: kept from the first
                }
                if (!is_own) {
                    // Flat with the triangle: one of the item's faces (or sectors) is its own plane.
                    float best = 0.0f;
                    for (uint32_t j = 0; j < items.normals_per_item; ++j) {
                        const float* n = items.normals + 3 * (size_t(item) * items.normals_per_item + j);
                        best = std::max(best, std::abs(tn[0] * n[0] + tn[1] * n[1] + tn[2] * n[2]));
                    }
                    if (!(best >= cos_max)) continue;
                }
                (is_own ? own : other).push_back(item);
            }
        }
        // Own sides first, then the others in the order met.
        float* o = out + size_t(t) * per;
        for (size_t k = 0; k < own.size() && k < per; ++k) o[k] = float(own[k] + 1);
        for (size_t k = 0; own.size() + k < per && k < other.size(); ++k) o[own.size() + k] = float(other[k] + 1);
    }
}

}  // namespace el
