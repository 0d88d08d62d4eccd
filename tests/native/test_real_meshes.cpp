// libcgal-demo's classic meshes through assimp and the C API: the counts a closed surface must have.
#include "mesh_fixtures.hpp"
#include "off_mesh.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace fixtures;

namespace {

struct Expect {
    const char* name;
    uint32_t triangles;
    int euler;  // V - E + F after equal positions are welded (off_mesh.cpp, as mesh_io.cpp)
};

class RealMesh : public ::testing::TestWithParam<Expect> {};

}  // namespace

TEST_P(RealMesh, ClosedOrientableWithEulerCharacteristic) {
    const Expect x = GetParam();
    const std::string path = std::string(EDGELIGHT_TEST_MESH_DIR) + "/" + x.name + ".off";
    el_tools::LoadedMesh m;
    ASSERT_NO_THROW(m = el_tools::read_off(path)) << path << " (apt-get install libcgal-demo)";
    el_mesh_desc d{};
    d.positions = m.positions.data();
    d.vertex_count = uint32_t(m.positions.size() / 3);
    d.triangles = m.triangles.data();
    d.triangle_count = uint32_t(m.triangles.size() / 3);
    auto mesh = create(d);
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.triangle_count, x.triangles);
    EXPECT_EQ(i.border_edges, 0u);
    EXPECT_EQ(i.non_manifold_edges, 0u);
    EXPECT_EQ(i.flipped_winding_edges, 0u);
    EXPECT_EQ(uint64_t(i.edge_count) * 2, uint64_t(i.triangle_count) * 3);
    EXPECT_EQ(int64_t(i.vertex_count) - int64_t(i.edge_count) + int64_t(i.triangle_count), x.euler);
    EXPECT_EQ(i.convex_edges + i.concave_edges + (i.edge_count - i.convex_edges - i.concave_edges), i.edge_count);
    // A closed surface seen from outside: silhouettes form closed loops (even vertex degrees).
    el_view* v = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &v), EL_OK);
    ViewPtr view(v);
    const el_camera cam = perspective(10, 7, 5);
    ASSERT_EQ(el_view_update(v, &cam, EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS, nullptr), EL_OK);
    uint32_t n = 0;
    ASSERT_EQ(el_view_get_silhouettes(v, nullptr, 0, &n), EL_OK);
    std::vector<uint32_t> s(n);
    ASSERT_EQ(el_view_get_silhouettes(v, s.data(), n, &n), EL_OK);
    EXPECT_GT(n, 0u);
    const auto e = edges(mesh.get());
    std::vector<int> degree(i.vertex_count, 0);
    for (uint32_t k : s) {
        ++degree[e[2 * k]];
        ++degree[e[2 * k + 1]];
    }
    for (uint32_t vtx = 0; vtx < i.vertex_count; ++vtx) EXPECT_EQ(degree[vtx] % 2, 0) << "vertex " << vtx;
}

INSTANTIATE_TEST_SUITE_P(LibCgalDemo, RealMesh,
                         // cow.off has two vertices at one position: welding pinches them into
                         // one vertex (2904 -> 2903), so its sphere counts 2 - 1.
                         ::testing::Values(Expect{"cow", 5804, 1}, Expect{"fandisk", 12946, 2},
                                           Expect{"armadillo", 52000, 2}),
                         [](const auto& info) { return std::string(info.param.name); });
