#include "contour.hpp"

#include <algorithm>

namespace el {

void compute_contours(const MeshData& mesh, const ViewPoint& view, std::vector<float>& points,
                      std::vector<uint32_t>& triangles, std::vector<uint64_t>& keys) {
    points.clear();
    triangles.clear();
    keys.clear();
    const uint32_t vn = mesh.vertex_count();
    std::vector<float> g(vn);
    for (uint32_t v = 0; v < vn; ++v) g[v] = view.facing(mesh.geom.vertex_normals[v], mesh.positions[v]);

    const uint32_t tn = mesh.triangle_count();
    for (uint32_t t = 0; t < tn; ++t) {
        const uint32_t* c = &mesh.triangles[3 * size_t(t)];
        // g == 0 counts as front-facing so a vertex exactly on the contour yields one segment.
        const bool s0 = g[c[0]] >= 0.0f, s1 = g[c[1]] >= 0.0f, s2 = g[c[2]] >= 0.0f;
        if (s0 == s1 && s1 == s2) continue;
        float seg[6];
        uint64_t key[2] = {0, 0};
        int k = 0;
        for (int side = 0; side < 3; ++side) {
            // Lower vertex first, so both triangles of a side compute the same point bit for bit
            // and segments chain exactly.
            const uint32_t a = std::min(c[side], c[(side + 1) % 3]), b = std::max(c[side], c[(side + 1) % 3]);
            if ((g[a] >= 0.0f) == (g[b] >= 0.0f)) continue;
            const float ga = g[a], gb = g[b];
            const float u = ga / (ga - gb);  // signs differ, so ga != gb and u is in [0, 1]
            const glm::vec3 p = mesh.positions[a] + u * (mesh.positions[b] - mesh.positions[a]);
            seg[3 * k] = p.x;
            seg[3 * k + 1] = p.y;
            seg[3 * k + 2] = p.z;
            key[k] = (uint64_t(a) << 32) | b;  // the side the point lies on: shared by both its triangles
            ++k;
        }
        // Exactly two sides change sign when the three signs are not all equal.
        points.insert(points.end(), seg, seg + 6);
        triangles.push_back(t);
        keys.insert(keys.end(), key, key + 2);
    }
}

}  // namespace el
