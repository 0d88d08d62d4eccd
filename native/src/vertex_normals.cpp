#include "vertex_normals.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace el {

void compute_vertex_normals(const MeshData& mesh, Geometry& geom) {
    std::vector<glm::vec3> acc(mesh.vertex_count(), glm::vec3(0.0f));
    const uint32_t n = mesh.triangle_count();
    for (uint32_t t = 0; t < n; ++t) {
        if (geom.face_degenerate[t]) continue;
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = mesh.triangles[3 * t + c];
            const glm::vec3 p = mesh.positions[v];
            const glm::vec3 u = mesh.positions[mesh.triangles[3 * t + (c + 1) % 3]] - p;
            const glm::vec3 w = mesh.positions[mesh.triangles[3 * t + (c + 2) % 3]] - p;
            const float lu = glm::length(u), lw = glm::length(w);
            if (!(lu > 0.0f && lw > 0.0f)) continue;
            const float angle = std::acos(std::clamp(glm::dot(u, w) / (lu * lw), -1.0f, 1.0f));
            acc[v] += angle * geom.face_normals[t];
        }
    }
    for (glm::vec3& a : acc) {
        const float len = glm::length(a);
        a = len > 0.0f ? a / len : glm::vec3(0.0f);
    }
    geom.vertex_normals = std::move(acc);
}

}  // namespace el
