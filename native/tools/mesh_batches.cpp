#include "mesh_batches.hpp"

#include <edgelight/edgelight.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

namespace el_tools {
namespace {

void check(el_status s) {
    if (s != EL_OK) throw std::runtime_error(std::string(el_status_name(s)) + ": " + el_last_error());
}

using MeshPtr = std::unique_ptr<el_mesh, void (*)(el_mesh*)>;

MeshPtr create_mesh(const LoadedMesh& m) {
    el_mesh_desc d{};
    d.positions = m.positions.data();
    d.vertex_count = uint32_t(m.positions.size() / 3);
    d.triangles = m.triangles.data();
    d.triangle_count = uint32_t(m.triangles.size() / 3);
    el_mesh* mesh = nullptr;
    check(el_mesh_create(&d, &mesh));
    return MeshPtr(mesh, el_mesh_destroy);
}

glm::dvec3 vertex(const LoadedMesh& m, uint32_t v) {
    return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

}  // namespace

SurfaceCorners surface_corners(const LoadedMesh& m, float smooth_deg) {
    const size_t tris = m.triangles.size() / 3, verts = m.positions.size() / 3;
    const MeshPtr mesh = create_mesh(m);
    std::vector<float> fn(3 * tris);
    check(el_mesh_get_face_normals(mesh.get(), fn.data(), uint32_t(tris)));
    auto face_normal = [&](size_t t) { return glm::dvec3(fn[3 * t], fn[3 * t + 1], fn[3 * t + 2]); };
    // Faces around each vertex, with the face's angle at that vertex (Blender weights by it).
    std::vector<std::vector<std::pair<uint32_t, double>>> around(verts);
    for (size_t t = 0; t < tris; ++t) {
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = m.triangles[3 * t + c];
            const glm::dvec3 p = vertex(m, v), a = vertex(m, m.triangles[3 * t + (c + 1) % 3]) - p,
                             b = vertex(m, m.triangles[3 * t + (c + 2) % 3]) - p;
            const double la = glm::length(a), lb = glm::length(b);
            const double angle = la > 0.0 && lb > 0.0 ? std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0)) : 0.0;
            around[v].push_back({uint32_t(t), angle});
        }
    }
    const double cos_limit = std::cos(glm::radians(double(smooth_deg)));
    SurfaceCorners out;
    out.pos.reserve(9 * tris);
    out.nor.reserve(9 * tris);
    for (size_t t = 0; t < tris; ++t) {
        const glm::dvec3 own = face_normal(t);
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = m.triangles[3 * t + c];
            glm::dvec3 n(0.0);
            for (const auto& [f, angle] : around[v]) {
                const glm::dvec3 other = face_normal(f);
                if (f == t || glm::dot(own, other) >= cos_limit) n += angle * other;
            }
            const double len = glm::length(n);
            n = len > 0.0 ? n / len : (glm::length(own) > 0.0 ? own : glm::dvec3(0.0, 0.0, 1.0));
            for (int k = 0; k < 3; ++k) {
                out.pos.push_back(m.positions[3 * v + k]);
                out.nor.push_back(float(n[k]));
            }
        }
    }
    out.uv.assign(6 * tris, 0.0f);
    out.col.assign(12 * tris, 0.0f);
    out.tan.assign(12 * tris, 0.0f);
    return out;
}

EdgeSet choose_edges(const LoadedMesh& m, float crease_deg) {
    const MeshPtr mesh = create_mesh(m);
    check(el_mesh_classify(mesh.get(), crease_deg));
    el_mesh_info info{};
    check(el_mesh_get_info(mesh.get(), &info));
    // EL_EDGE_CREASE is manifold, angle above the threshold, and never degenerate: the add-on's
    // choose_edges() with the 'ANGLE' rule.
    uint32_t count = 0;
    check(el_mesh_select_edges(mesh.get(), EL_EDGE_CREASE, 0, nullptr, 0, &count));
    std::vector<uint32_t> chosen(count);
    if (count) check(el_mesh_select_edges(mesh.get(), EL_EDGE_CREASE, 0, chosen.data(), count, &count));
    std::vector<uint32_t> ends(2 * size_t(info.edge_count));
    std::vector<float> normals(6 * size_t(info.edge_count));
    check(el_mesh_get_edges(mesh.get(), ends.data(), info.edge_count));
    check(el_mesh_get_edge_normals(mesh.get(), normals.data(), info.edge_count));
    EdgeSet out;
    auto at = [](const float* p) { return std::array<float, 3>{p[0], p[1], p[2]}; };
    for (uint32_t e : chosen) {
        out.p0.push_back(at(&m.positions[3 * size_t(ends[2 * e])]));
        out.p1.push_back(at(&m.positions[3 * size_t(ends[2 * e + 1])]));
        out.n1.push_back(at(&normals[6 * size_t(e)]));
        out.n2.push_back(at(&normals[6 * size_t(e) + 3]));
    }
    return out;
}

EdgeQuads edge_quads(const EdgeSet& edges, float radius, Provoking provoking) {
    // (end, side) of corners 0..3; corner 0 is the shading vertex.
    static constexpr float kCorners[4][2] = {{0, -1}, {0, 1}, {1, -1}, {1, 1}};
    static constexpr uint32_t kTrisFirst[6] = {0, 1, 3, 0, 3, 2};
    static constexpr uint32_t kTrisLast[6] = {1, 3, 0, 3, 2, 0};
    const uint32_t* tris = provoking == Provoking::first ? kTrisFirst : kTrisLast;
    const size_t n = edges.size();
    EdgeQuads q;
    // Buffer position of (edge i, corner c): shading corners first, so vertex SIMD groups either
    // all shade or none do (batches.py).
    auto slot = [n](size_t i, uint32_t c) { return uint32_t(c == 0 ? i : n + 3 * i + (c - 1)); };
    q.p0.resize(12 * n);
    q.p1.resize(12 * n);
    q.n1.resize(12 * n);
    q.n2.resize(12 * n);
    q.corner.resize(16 * n);
    q.faces.assign(8 * n, 0.0f);
    q.ends.assign(16 * n, float(std::numbers::pi / 2.0));
    q.turn1.assign(12 * n, 0.0f);
    q.turn2.assign(12 * n, 0.0f);
    q.uv.assign(16 * n, 0.0f);
    q.col0.assign(16 * n, 0.0f);
    q.col1.assign(16 * n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        for (uint32_t c = 0; c < 4; ++c) {
            const size_t s = slot(i, c);
            for (int k = 0; k < 3; ++k) {
                q.p0[3 * s + k] = edges.p0[i][k];
                q.p1[3 * s + k] = edges.p1[i][k];
                q.n1[3 * s + k] = edges.n1[i][k];
                q.n2[3 * s + k] = edges.n2[i][k];
            }
            q.corner[4 * s + 0] = kCorners[c][0];
            q.corner[4 * s + 1] = kCorners[c][1];
            q.corner[4 * s + 2] = radius;
            q.corner[4 * s + 3] = c == 0 ? 1.0f : 0.0f;
        }
        for (int k = 0; k < 6; ++k) q.indices.push_back(slot(i, tris[k]));
    }
    return q;
}

}  // namespace el_tools
