// Silhouette edges per view, from per-face facing bits.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <map>

using namespace fixtures;

namespace {

std::vector<uint32_t> silhouettes(el_view* view) {
    uint32_t n = 0;
    EXPECT_EQ(el_view_get_silhouettes(view, nullptr, 0, &n), EL_OK);
    std::vector<uint32_t> s(n);
    EXPECT_EQ(el_view_get_silhouettes(view, s.data(), n, &n), EL_OK) << el_last_error();
    return s;
}

ViewPtr make_view(const el_mesh* mesh) {
    el_view* v = nullptr;
    EXPECT_EQ(el_view_create(mesh, &v), EL_OK) << el_last_error();
    return ViewPtr(v);
}

// Every vertex of the edge set has degree 2: the edges form closed loops.
void expect_closed_loops(const std::vector<uint32_t>& e, const std::vector<uint32_t>& sel) {
    std::map<uint32_t, int> degree;
    for (uint32_t k : sel) {
        ++degree[e[2 * k]];
        ++degree[e[2 * k + 1]];
    }
    for (auto& [v, d] : degree) EXPECT_EQ(d, 2) << "vertex " << v;
}

}  // namespace

TEST(Silhouette, SphereAlongAxisOrthographicIsTheEquator) {
    const TestMesh m = uv_sphere(32, 16);
    auto mesh = create(m.desc());
    auto view = make_view(mesh.get());
    const el_camera cam = orthographic(0, 0, -1);
    ASSERT_EQ(el_view_update(view.get(), &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK) << el_last_error();
    const auto s = silhouettes(view.get());
    ASSERT_EQ(s.size(), 32u);
    const auto e = edges(mesh.get());
    for (uint32_t k : s) {
        EXPECT_NEAR(m.positions[3 * e[2 * k] + 2], 0.0f, 1e-6f);
        EXPECT_NEAR(m.positions[3 * e[2 * k + 1] + 2], 0.0f, 1e-6f);
    }
    expect_closed_loops(e, s);
}

TEST(Silhouette, SphereFromNearbyEyeIsTheRingAtTheTangentCone) {
    // From (0,0,5) the true silhouette is the circle z = 1/5; the facets change facing at the
    // ring at 78.75 degrees from the pole (z = cos 78.75 = 0.195).
    const TestMesh m = uv_sphere(32, 16);
    auto mesh = create(m.desc());
    auto view = make_view(mesh.get());
    const el_camera cam = perspective(0, 0, 5);
    ASSERT_EQ(el_view_update(view.get(), &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    const auto s = silhouettes(view.get());
    ASSERT_EQ(s.size(), 32u);
    const auto e = edges(mesh.get());
    for (uint32_t k : s)
        for (int j = 0; j < 2; ++j) EXPECT_NEAR(m.positions[3 * e[2 * k + j] + 2], std::cos(78.75f * 3.14159265f / 180.0f), 1e-5f);
    expect_closed_loops(e, s);
}

TEST(Silhouette, CubeFromACornerShowsSixEdges) {
    auto mesh = create(cube().desc());
    auto view = make_view(mesh.get());
    const el_camera cam = perspective(3, 4, 5);  // sees faces x=1, y=1, z=1
    ASSERT_EQ(el_view_update(view.get(), &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    const auto s = silhouettes(view.get());
    EXPECT_EQ(s.size(), 6u);
    const auto e = edges(mesh.get());
    expect_closed_loops(e, s);
    std::vector<uint8_t> facing(12);
    ASSERT_EQ(el_view_get_facing(view.get(), facing.data(), 12), EL_OK);
    EXPECT_EQ(std::count(facing.begin(), facing.end(), 1), 6);
}

TEST(Silhouette, MirroredObjectKeepsFacing) {
    // Scale -1 in x: the world-space sphere is the same set, so is its silhouette.
    const TestMesh m = uv_sphere(32, 16);
    auto mesh = create(m.desc());
    auto view = make_view(mesh.get());
    el_camera cam = perspective(0.3f, 0.2f, 5);
    cam.object_to_world[0] = -1.0f;
    ASSERT_EQ(el_view_update(view.get(), &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    std::vector<uint8_t> facing(m.triangle_count());
    ASSERT_EQ(el_view_get_facing(view.get(), facing.data(), m.triangle_count()), EL_OK);
    // Face centres with x mirrored, normals pointing outwards: front iff n.(eye - c) > 0.
    for (uint32_t t = 0; t < m.triangle_count(); ++t) {
        float c[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) c[j] += m.positions[3 * m.triangles[3 * t + k] + j] / 3.0f;
        c[0] = -c[0];
        const float len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        const float d = (c[0] * (0.3f - c[0]) + c[1] * (0.2f - c[1]) + c[2] * (5.0f - c[2])) / len;
        if (std::abs(d) > 0.05f) EXPECT_EQ(facing[t], d > 0 ? 1 : 0) << "triangle " << t;
    }
}

TEST(Silhouette, TranslatedObjectMovesTheView) {
    auto mesh = create(cube().desc());
    auto view = make_view(mesh.get());
    el_camera cam = orthographic(0, 0, -1);
    cam.object_to_world[3] = 10.0f;  // translation does not change orthographic facing
    ASSERT_EQ(el_view_update(view.get(), &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    EXPECT_EQ(silhouettes(view.get()).size(), 4u) << "the rim of the top face";
}
