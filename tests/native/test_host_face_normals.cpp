// Face normals given by the host (a triangulated polygon's own normal): zero-area pieces along a
// polygon's side and slivers of a near-planar polygon classify by their polygon.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

using namespace fixtures;

namespace {

// Two polygons folded at 90 degrees along a side cut into four segments by three extra collinear
// vertices (D, E, F), each fanned from the corner C as Blender's triangulation may do, which
// makes zero-area triangles C-D-E, C-E-F, C-F-G in the top polygon.
struct Fold {
    std::vector<float> positions, normals;
    std::vector<uint32_t> triangles, edges, triangle_edges;
    std::vector<std::pair<uint32_t, uint32_t>> shared;  // the four segments between the polygons

    explicit Fold(float lift) {
        // A B C D E F G: top (z = 1); H I: the back polygon's lower corners (y = 1), which makes
        // the back polygon the larger one.
        const float p[][3] = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0.75f, 1, 1}, {0.5f, 1, 1 + lift},
                              {0.25f, 1, 1}, {0, 1, 1}, {1, 1, -1}, {0, 1, -1}};
        for (auto& v : p) positions.insert(positions.end(), v, v + 3);
        add_polygon({2, 3, 4, 5, 6, 0, 1}, {0, 0, 1});   // fanned from C
        add_polygon({7, 2, 3, 4, 5, 6, 8}, {0, 1, 0});   // fanned from H
        for (uint32_t v = 2; v < 6; ++v) shared.push_back(ordered(v, v + 1));
    }

    void add_polygon(std::vector<uint32_t> loop, glm::vec3 normal) {
        // Wind the loop so its triangles face `normal` (the fan's first non-degenerate one).
        auto P = [&](uint32_t v) { return glm::vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]); };
        if (glm::dot(glm::cross(P(loop[loop.size() - 2]) - P(loop[0]), P(loop.back()) - P(loop[0])), normal) < 0.0f)
            std::reverse(loop.begin() + 1, loop.end());
        for (size_t i = 1; i + 1 < loop.size(); ++i) {
            const uint32_t c[3] = {loop[0], loop[i], loop[i + 1]};
            for (int s = 0; s < 3; ++s) {
                triangles.push_back(c[s]);
                const uint32_t a = c[s], b = c[(s + 1) % 3];
                // A fan's inner sides are diagonals: no edge of the polygon.
                const bool boundary = (s == 1) || (s == 0 && i == 1) || (s == 2 && i + 2 == loop.size());
                if (!boundary) {
                    triangle_edges.push_back(EL_NO_EDGE);
                    continue;
                }
                auto [it, inserted] = ids.try_emplace(ordered(a, b), uint32_t(ids.size()));
                if (inserted) edges.insert(edges.end(), {a, b});
                triangle_edges.push_back(it->second);
            }
            normals.insert(normals.end(), {normal.x, normal.y, normal.z});
        }
    }

    el_mesh_desc desc(bool with_normals) const {
        el_mesh_desc d{};
        d.positions = positions.data();
        d.vertex_count = uint32_t(positions.size() / 3);
        d.triangles = triangles.data();
        d.triangle_count = uint32_t(triangles.size() / 3);
        d.edges = edges.data();
        d.edge_count = uint32_t(edges.size() / 2);
        d.triangle_edges = triangle_edges.data();
        d.triangle_normals = with_normals ? normals.data() : nullptr;
        return d;
    }

    uint32_t edge_of(std::pair<uint32_t, uint32_t> key) const { return ids.at(key); }

    std::map<std::pair<uint32_t, uint32_t>, uint32_t> ids;
};

std::vector<float> angles(const el_mesh* mesh) {
    std::vector<float> out(info(mesh).edge_count);
    EXPECT_EQ(el_mesh_get_edge_angles(mesh, out.data(), uint32_t(out.size())), EL_OK);
    return out;
}

}  // namespace

TEST(HostFaceNormals, CollinearCornersKeepEverySegmentOfTheFold) {
    const Fold fold(0.0f);
    auto own = create(fold.desc(false));
    auto host = create(fold.desc(true));
    const auto own_flags = edge_flags(own.get()), flags = edge_flags(host.get());
    const auto a = angles(host.get());
    int degenerate_without = 0;
    for (auto seg : fold.shared) {
        const uint32_t e = fold.edge_of(seg);
        degenerate_without += (own_flags[e] & EL_EDGE_DEGENERATE) != 0;
        EXPECT_EQ(flags[e] & (EL_EDGE_MANIFOLD | EL_EDGE_DEGENERATE | EL_EDGE_CREASE | EL_EDGE_CONVEX),
                  EL_EDGE_MANIFOLD | EL_EDGE_CREASE | EL_EDGE_CONVEX) << "segment " << seg.first << "-" << seg.second;
        EXPECT_NEAR(a[e], 90.0f, 1e-3f);
    }
    EXPECT_GE(degenerate_without, 3) << "the fold's zero-area pieces drop segments without the polygon's normal";
    EXPECT_EQ(info(host.get()).degenerate_triangles, 0u);
}

TEST(HostFaceNormals, SliversTakeTheirPolygonsNormal) {
    const Fold fold(2e-4f);  // E lifted: the fan's pieces along the side become slivers
    auto own = create(fold.desc(false));
    auto host = create(fold.desc(true));
    const auto own_a = angles(own.get()), a = angles(host.get());
    float worst_without = 0.0f;
    for (auto seg : fold.shared) {
        const uint32_t e = fold.edge_of(seg);
        EXPECT_NEAR(a[e], 90.0f, 0.1f) << "segment " << seg.first << "-" << seg.second;
        worst_without = std::max(worst_without, std::abs(own_a[e] - 90.0f));
    }
    EXPECT_GT(worst_without, 30.0f) << "a sliver's own normal is far from its polygon's";
}

TEST(HostFaceNormals, FlippedTrianglesNegateTheGivenNormal) {
    // The top polygon imported flipped, its normal with it (the host's normal follows the
    // polygon's winding): the library reorients it and must agree with the consistent fold.
    Fold fold(0.0f);
    auto consistent = create(fold.desc(true));
    for (size_t t = 0; t < 5; ++t) {  // the top polygon's fan
        std::swap(fold.triangles[3 * t + 1], fold.triangles[3 * t + 2]);
        std::swap(fold.triangle_edges[3 * t], fold.triangle_edges[3 * t + 2]);
        for (int k = 0; k < 3; ++k) fold.normals[3 * t + k] = -fold.normals[3 * t + k];
    }
    auto flipped = create(fold.desc(true));
    EXPECT_EQ(info(flipped.get()).reoriented_triangles, 5u);
    EXPECT_EQ(edge_flags(flipped.get()), edge_flags(consistent.get()));
    EXPECT_EQ(angles(flipped.get()), angles(consistent.get()));
}

TEST(HostFaceNormals, NonUnitOrNonFiniteNormalsAreRefused) {
    Fold fold(0.0f);
    fold.normals[0] = 2.0f;
    el_mesh* m = nullptr;
    const el_mesh_desc long_normal = fold.desc(true);
    EXPECT_EQ(el_mesh_create(&long_normal, &m), EL_ERR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(el_last_error()).find("length"), std::string::npos);
    fold.normals[0] = std::nanf("");
    const el_mesh_desc nan_normal = fold.desc(true);
    EXPECT_EQ(el_mesh_create(&nan_normal, &m), EL_ERR_NON_FINITE);
    EXPECT_EQ(m, nullptr);
}
