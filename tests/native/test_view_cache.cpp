// An unchanged view costs nothing; a moved view recomputes only what changed.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

using namespace fixtures;

namespace {
el_view_stats stats(const el_view* v) {
    el_view_stats s{};
    EXPECT_EQ(el_view_get_stats(v, &s), EL_OK);
    return s;
}
}  // namespace

TEST(ViewCache, SameCameraIsACacheHit) {
    auto mesh = create(uv_sphere(32, 16).desc());
    el_view* raw = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &raw), EL_OK);
    ViewPtr view(raw);
    const el_camera cam = perspective(0, 0, 5);
    const uint32_t what = EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS;
    uint32_t changed = 7;
    ASSERT_EQ(el_view_update(raw, &cam, what, &changed), EL_OK);
    EXPECT_EQ(changed, 1u);
    ASSERT_EQ(el_view_update(raw, &cam, what, &changed), EL_OK);
    EXPECT_EQ(changed, 0u);
    const el_view_stats s = stats(raw);
    EXPECT_EQ(s.updates, 2u);
    EXPECT_EQ(s.cache_hits, 1u);
    EXPECT_EQ(s.facing_passes, 1u);
    EXPECT_EQ(s.contour_passes, 1u);
    EXPECT_EQ(s.silhouette_edges, 32u);
}

TEST(ViewCache, SmallMoveWithoutFlipsKeepsTheEdgeList) {
    auto mesh = create(uv_sphere(32, 16).desc());
    el_view* raw = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &raw), EL_OK);
    ViewPtr view(raw);
    el_camera cam = perspective(0, 0, 5);
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    cam.eye[2] = 5.001f;  // no facet changes facing
    uint32_t changed = 7;
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, &changed), EL_OK);
    EXPECT_EQ(changed, 0u);
    el_view_stats s = stats(raw);
    EXPECT_EQ(s.facing_passes, 2u);
    EXPECT_EQ(s.faces_flipped, uint64_t(uv_sphere(32, 16).triangle_count()));  // only the first pass
    EXPECT_EQ(s.silhouette_rebuilds, 1u);
    cam.eye[0] = 4.0f;  // a real orbit: facets flip
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, &changed), EL_OK);
    EXPECT_EQ(changed, 1u);
    s = stats(raw);
    EXPECT_EQ(s.silhouette_rebuilds, 2u);
    EXPECT_GT(s.faces_flipped, uint64_t(uv_sphere(32, 16).triangle_count()));
}

TEST(ViewCache, ObjectAndCameraMovingTogetherIsAHit) {
    auto mesh = create(cube().desc());
    el_view* raw = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &raw), EL_OK);
    ViewPtr view(raw);
    el_camera cam = perspective(3, 4, 5);
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    cam.eye[0] += 2.0f;
    cam.object_to_world[3] = 2.0f;  // same object-space eye
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    EXPECT_EQ(stats(raw).cache_hits, 1u);
}

TEST(ViewCache, ViewOutlivesItsMeshHandle) {
    el_mesh* m = nullptr;
    const TestMesh cubemesh = cube();
    const el_mesh_desc d = cubemesh.desc();
    ASSERT_EQ(el_mesh_create(&d, &m), EL_OK);
    el_view* raw = nullptr;
    ASSERT_EQ(el_view_create(m, &raw), EL_OK);
    ViewPtr view(raw);
    el_mesh_destroy(m);
    const el_camera cam = perspective(3, 4, 5);
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    EXPECT_EQ(stats(raw).silhouette_edges, 6u);
}

TEST(ViewCache, DroppingAnOutputClearsIt) {
    auto mesh = create(uv_sphere(16, 8).desc());
    el_view* raw = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &raw), EL_OK);
    ViewPtr view(raw);
    const el_camera cam = perspective(0, 0, 5);
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS, nullptr), EL_OK);
    EXPECT_GT(stats(raw).contour_segments, 0u);
    uint32_t changed = 0;
    ASSERT_EQ(el_view_update(raw, &cam, EL_VIEW_SILHOUETTES, &changed), EL_OK);
    EXPECT_EQ(changed, 1u);
    EXPECT_EQ(stats(raw).contour_segments, 0u);
    EXPECT_EQ(stats(raw).silhouette_edges, 16u);
}
