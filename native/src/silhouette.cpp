#include "silhouette.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>

namespace el {

float ViewPoint::facing(const glm::vec3& n, const glm::vec3& p) const {
    return orthographic ? glm::dot(n, to_viewer) : glm::dot(n, eye - p);
}

void compute_facing(const MeshData& mesh, const ViewPoint& view, std::vector<uint64_t>& bits) {
    const uint32_t n = mesh.triangle_count();
    bits.assign((size_t(n) + 63) / 64, 0u);
    const glm::vec3* normals = mesh.geom.face_normals.data();
    const float* offsets = mesh.geom.face_offsets.data();
    // dot(n, eye - p) = dot(n, eye) - plane offset: reads only the face's own data.
    for (uint32_t w = 0; w < bits.size(); ++w) {
        const uint32_t begin = w * 64, end = std::min<uint32_t>(begin + 64, n);
        uint64_t word = 0;
        if (view.orthographic) {
            for (uint32_t f = begin; f < end; ++f)
                word |= uint64_t(glm::dot(normals[f], view.to_viewer) > 0.0f) << (f - begin);
        } else {
            for (uint32_t f = begin; f < end; ++f)
                word |= uint64_t(glm::dot(normals[f], view.eye) - offsets[f] > 0.0f) << (f - begin);
        }
        bits[w] = word;
    }
}

uint64_t count_flips(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b) {
    if (a.size() != b.size()) return UINT64_MAX;
    uint64_t flips = 0;
    for (size_t i = 0; i < a.size(); ++i) flips += std::popcount(a[i] ^ b[i]);
    return flips;
}

void collect_silhouettes(const MeshData& mesh, const std::vector<uint64_t>& bits, std::vector<uint32_t>& out) {
    out.clear();
    const Classification& cls = mesh.cls;
    const uint32_t edge_count = mesh.edge_count();
    for (uint32_t e = 0; e < edge_count; ++e) {
        const uint32_t f1 = cls.face1[e], f2 = cls.face2[e];
        // face1/face2 are set for manifold edges only; degenerate faces have no facing.
        if (f1 == EL_NO_EDGE || (cls.edge_flags[e] & EL_EDGE_DEGENERATE)) continue;
        if (facing_bit(bits, f1) != facing_bit(bits, f2)) out.push_back(e);
    }
}

}  // namespace el
