#include "radius_clamp.hpp"

#include <glm/glm.hpp>

#include <algorithm>

namespace el {

void width_bounds(const el_polygons& polys, const float* positions, const uint32_t* edges, const int32_t* edge_polys,
                  uint32_t count, double* out) {
    auto at = [&](uint32_t v) { return glm::dvec3(positions[3 * size_t(v)], positions[3 * size_t(v) + 1], positions[3 * size_t(v) + 2]); };
    for (uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 a = at(edges[2 * size_t(i)]);
        const glm::dvec3 d = at(edges[2 * size_t(i) + 1]) - a;
        const double length = std::max(glm::length(d), 1e-30);
        for (int side = 0; side < 2; ++side) {
            const int32_t p = edge_polys[2 * size_t(i) + size_t(side)];
            double w = 0.0;
            if (p >= 0)
                for (uint32_t k = 0; k < 3; ++k) {
                    const uint32_t corner = polys.start[p] + (k * polys.total[p]) / 3;
                    const glm::dvec3 v = at(polys.loop_vert[corner]) - a;
                    w = std::max(w, glm::length(glm::cross(d, v)) / length);
                }
            out[2 * size_t(i) + size_t(side)] = w;
        }
    }
}

}  // namespace el
