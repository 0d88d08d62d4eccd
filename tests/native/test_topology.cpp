// Unique edges and edge -> face adjacency built from triangle lists.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace fixtures;

TEST(Topology, CubeIsClosedWithDiagonals) {
    const TestMesh m = cube();
    auto mesh = create(m.desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.vertex_count, 8u);
    EXPECT_EQ(i.triangle_count, 12u);
    EXPECT_EQ(i.edge_count, 18u);  // 12 cube edges + 6 quad diagonals
    EXPECT_EQ(i.manifold_edges, 18u);
    EXPECT_EQ(i.border_edges, 0u);
    EXPECT_EQ(i.non_manifold_edges, 0u);
    EXPECT_EQ(i.flipped_winding_edges, 0u);
    EXPECT_EQ(i.host_edges, 0u);
}

TEST(Topology, EdgesAreUniqueAndEveryFaceListsIts3Edges) {
    const TestMesh m = icosphere(2);
    auto mesh = create(m.desc());
    const auto e = edges(mesh.get());
    std::set<std::pair<uint32_t, uint32_t>> unique;
    for (size_t i = 0; i < e.size(); i += 2) unique.insert(ordered(e[i], e[i + 1]));
    EXPECT_EQ(unique.size(), e.size() / 2);
    // Euler: closed genus-0 triangle mesh has E = 3F/2.
    EXPECT_EQ(e.size() / 2, size_t(m.triangle_count()) * 3 / 2);
    for (uint32_t k = 0; k < e.size() / 2; ++k) {
        uint32_t faces[4], count = 0;
        ASSERT_EQ(el_mesh_get_edge_faces(mesh.get(), k, faces, 4, &count), EL_OK);
        ASSERT_EQ(count, 2u);
        for (uint32_t f = 0; f < count; ++f) {
            const uint32_t* t = &m.triangles[3 * faces[f]];
            EXPECT_TRUE(std::count(t, t + 3, e[2 * k]) == 1 && std::count(t, t + 3, e[2 * k + 1]) == 1);
        }
    }
}

TEST(Topology, OpenBoxHasOneBorderLoopOf4) {
    const TestMesh box = open_box();
    auto mesh = create(box.desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.border_edges, 4u);
    EXPECT_EQ(i.non_manifold_edges, 0u);
    // The 4 border edges form one loop: every vertex on it has exactly 2 border edges.
    const auto e = edges(mesh.get());
    const auto f = edge_flags(mesh.get());
    std::map<uint32_t, int> degree;
    for (size_t k = 0; k < f.size(); ++k)
        if (f[k] & EL_EDGE_BORDER) {
            ++degree[e[2 * k]];
            ++degree[e[2 * k + 1]];
            EXPECT_FALSE(f[k] & EL_EDGE_CREASE) << "border edges are not creases";
        }
    EXPECT_EQ(degree.size(), 4u);
    for (auto& [v, d] : degree) {
        EXPECT_EQ(d, 2) << "vertex " << v;
        EXPECT_EQ(box.positions[3 * v + 2], 1.0f) << "the loop is the missing top's rim";
    }
}

TEST(Topology, NonManifoldFin) {
    auto mesh = create(fin().desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.edge_count, 7u);
    EXPECT_EQ(i.non_manifold_edges, 1u);
    EXPECT_EQ(i.border_edges, 6u);
    EXPECT_EQ(i.manifold_edges, 0u);
    EXPECT_EQ(i.crease_edges, 0u) << "non-manifold edges have no single dihedral";
    const auto f = edge_flags(mesh.get());
    const auto e = edges(mesh.get());
    for (size_t k = 0; k < f.size(); ++k)
        if (f[k] & EL_EDGE_NON_MANIFOLD) {
            EXPECT_EQ(ordered(e[2 * k], e[2 * k + 1]), std::make_pair(0u, 1u));
            uint32_t faces[3], count = 0;
            ASSERT_EQ(el_mesh_get_edge_faces(mesh.get(), uint32_t(k), faces, 3, &count), EL_OK);
            EXPECT_EQ(count, 3u);
        }
}

TEST(Topology, FlippedWindingIsFlagged) {
    TestMesh m = hinge(90.0f);
    std::swap(m.triangles[4], m.triangles[5]);  // second face now runs the shared edge like the first
    auto mesh = create(m.desc());
    EXPECT_EQ(info(mesh.get()).flipped_winding_edges, 1u);
    EXPECT_EQ(info(mesh.get()).convex_edges + info(mesh.get()).concave_edges, 0u);
}

TEST(Topology, DegenerateTrianglesAreFlaggedWithoutNaN) {
    TestMesh m = cube();
    const uint32_t a = m.add_vertex(2, 0, 0), b = m.add_vertex(3, 0, 0), c = m.add_vertex(4, 0, 0);
    m.add_triangle(a, b, c);  // collinear: zero area
    m.add_triangle(a, a, b);  // repeated corner
    auto mesh = create(m.desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.degenerate_triangles, 2u);
    std::vector<float> n(3 * m.triangle_count());
    ASSERT_EQ(el_mesh_get_face_normals(mesh.get(), n.data(), m.triangle_count()), EL_OK);
    for (float v : n) EXPECT_TRUE(std::isfinite(v));
    EXPECT_EQ(n[3 * 12], 0.0f);
    std::vector<float> en(6 * size_t(i.edge_count));
    ASSERT_EQ(el_mesh_get_edge_normals(mesh.get(), en.data(), i.edge_count), EL_OK);
    for (float v : en) EXPECT_TRUE(std::isfinite(v));
    std::vector<uint8_t> deg(m.triangle_count());
    ASSERT_EQ(el_mesh_get_degenerate_triangles(mesh.get(), deg.data(), m.triangle_count()), EL_OK);
    EXPECT_EQ(std::count(deg.begin(), deg.end(), 1), 2);
    EXPECT_EQ(deg[12], 1);
    EXPECT_EQ(deg[13], 1);
    EXPECT_EQ(i.crease_edges, 12u) << "the cube's creases are unaffected";
}
