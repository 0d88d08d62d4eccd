// Unique edges and edge -> face adjacency built from triangle lists.
#include "mesh_fixtures.hpp"
#include "off_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>

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

TEST(Topology, FlippedWindingIsCountedAndOriented) {
    TestMesh m = hinge(90.0f);
    std::swap(m.triangles[4], m.triangles[5]);  // second face now runs the shared edge like the first
    auto mesh = create(m.desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.flipped_winding_edges, 1u) << "counted as given";
    EXPECT_EQ(i.reoriented_triangles, 1u) << "equal areas: the first triangle keeps its winding";
    EXPECT_EQ(i.convex_edges + i.concave_edges, 1u) << "classified in the oriented winding";
    for (uint32_t f : edge_flags(mesh.get())) EXPECT_FALSE(f & EL_EDGE_FLIPPED_WINDING);
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

namespace {

// The adjacency a std::map builds: every undirected side -> its faces, ascending, each once.
std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> reference_adjacency(const TestMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> ref;
    for (uint32_t t = 0; t < m.triangle_count(); ++t)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t a = m.triangles[3 * t + s], b = m.triangles[3 * t + (s + 1) % 3];
            if (a == b) continue;
            auto& faces = ref[ordered(a, b)];
            if (faces.empty() || faces.back() != t) faces.push_back(t);
        }
    return ref;
}

void expect_reference_adjacency(const TestMesh& m, const std::string& what) {
    SCOPED_TRACE(what);
    const auto ref = reference_adjacency(m);
    auto mesh = create(m.desc());
    const auto e = edges(mesh.get());
    ASSERT_EQ(e.size() / 2, ref.size());
    std::vector<uint32_t> faces(m.triangle_count());
    for (uint32_t k = 0; k < e.size() / 2; ++k) {
        ASSERT_LT(e[2 * k], e[2 * k + 1]) << "edges run lower -> higher vertex";
        const auto it = ref.find({e[2 * k], e[2 * k + 1]});
        ASSERT_NE(it, ref.end()) << "edge " << k << " is no side of any triangle";
        uint32_t count = 0;
        ASSERT_EQ(el_mesh_get_edge_faces(mesh.get(), k, faces.data(), uint32_t(faces.size()), &count), EL_OK);
        EXPECT_EQ(std::vector<uint32_t>(faces.begin(), faces.begin() + count), it->second) << "edge " << k;
    }
}

// The same surface with its vertex ids permuted, so triangle order no longer follows vertex order.
TestMesh shuffled_vertices(const TestMesh& m, uint32_t seed) {
    std::vector<uint32_t> perm(m.vertex_count());
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
    TestMesh out;
    out.positions.resize(m.positions.size());
    for (uint32_t v = 0; v < m.vertex_count(); ++v)
        for (int c = 0; c < 3; ++c) out.positions[3 * perm[v] + c] = m.positions[3 * v + c];
    for (uint32_t i : m.triangles) out.triangles.push_back(perm[i]);
    return out;
}

}  // namespace

// The builder sorts each vertex's sides in one of three ways (already in order, rank sort for
// short lists, std::sort for a fan's apex); all must give the map's answer, faces included.
TEST(Topology, AdjacencyMatchesAMapBasedReference) {
    expect_reference_adjacency(grid(12), "grid in vertex order");
    expect_reference_adjacency(shuffled_vertices(grid(12), 7), "grid with shuffled vertices");
    TestMesh fan;  // apex 0 owns 200 sides: more than a short list
    fan.add_vertex(0, 0, 1);
    for (int k = 0; k < 100; ++k) {
        const float a = 6.2831853f * float(k) / 100.0f;
        fan.add_vertex(std::cos(a), std::sin(a), 0);
    }
    for (uint32_t k = 0; k < 100; ++k) fan.add_triangle(0, 1 + k, 1 + (k + 1) % 100);
    expect_reference_adjacency(fan, "cone fan");
    expect_reference_adjacency(shuffled_vertices(fan, 3), "cone fan, shuffled");
    TestMesh odd = cube();  // a fin, a repeated corner and a duplicated face on top of the cube
    const uint32_t p = odd.add_vertex(0.5f, 0.5f, 2.0f);
    odd.add_triangle(0, 1, p);
    odd.add_triangle(0, 0, 1);
    odd.add_triangle(2, 3, 3);
    odd.add_triangle(4, 5, 6);
    expect_reference_adjacency(odd, "cube with a fin, repeated corners and a duplicate face");
    expect_reference_adjacency(shuffled_vertices(odd, 11), "the same, shuffled");
}

TEST(Topology, ScannedMeshWithShuffledVerticesMatchesTheReference) {
    const el_tools::LoadedMesh cow = el_tools::read_off(std::string(EDGELIGHT_TEST_MESH_DIR) + "/cow.off");
    TestMesh m;
    m.positions = cow.positions;
    m.triangles = cow.triangles;
    expect_reference_adjacency(m, "cow");
    expect_reference_adjacency(shuffled_vertices(m, 5), "cow, shuffled");
}

// A million triangles: every topology array is a huge-page block (see big_array.hpp).
TEST(Topology, MillionTriangleGridHasTheGridsCounts) {
    const uint32_t n = 708;  // 2 * 708^2 = 1,002,528 triangles
    const TestMesh m = grid(n);
    auto mesh = create(m.desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.triangle_count, 2 * n * n);
    EXPECT_EQ(i.edge_count, 3 * n * n + 2 * n) << "rows, columns and one diagonal per quad";
    EXPECT_EQ(i.border_edges, 4 * n);
    EXPECT_EQ(i.manifold_edges, i.edge_count - 4 * n);
    EXPECT_EQ(i.non_manifold_edges, 0u);
    EXPECT_EQ(i.flipped_winding_edges, 0u);
    // The last quad's diagonal (its lower-left to upper-right corner) joins its two triangles.
    const auto e = edges(mesh.get());
    const uint32_t a = (n - 1) * (n + 1) + (n - 1), c = a + n + 2;
    bool found = false;
    for (uint32_t k = 0; k < e.size() / 2 && !found; ++k)
        if (e[2 * k] == a && e[2 * k + 1] == c) {
            found = true;
            uint32_t faces[3], count = 0;
            ASSERT_EQ(el_mesh_get_edge_faces(mesh.get(), k, faces, 3, &count), EL_OK);
            ASSERT_EQ(count, 2u);
            EXPECT_EQ(faces[0], 2 * n * n - 2);
            EXPECT_EQ(faces[1], 2 * n * n - 1);
        }
    EXPECT_TRUE(found);
}
