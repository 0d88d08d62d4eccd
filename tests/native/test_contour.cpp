// Smooth contours: zero crossings of n.v interpolated along triangle sides.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

using namespace fixtures;

namespace {

struct Contours {
    std::vector<float> points;
    std::vector<uint32_t> triangles;
};

Contours contours(const el_mesh* mesh, const el_camera& cam) {
    el_view* v = nullptr;
    EXPECT_EQ(el_view_create(mesh, &v), EL_OK);
    ViewPtr view(v);
    EXPECT_EQ(el_view_update(v, &cam, EL_VIEW_CONTOURS, nullptr), EL_OK) << el_last_error();
    uint32_t n = 0;
    EXPECT_EQ(el_view_get_contours(v, nullptr, nullptr, 0, &n), EL_OK);
    Contours c;
    c.points.resize(6 * size_t(n));
    c.triangles.resize(n);
    EXPECT_EQ(el_view_get_contours(v, c.points.data(), c.triangles.data(), n, &n), EL_OK) << el_last_error();
    return c;
}

}  // namespace

TEST(Contour, SphereContourIsClosedAndHasNearZeroNDotV) {
    const TestMesh m = uv_sphere(32, 16);
    // Exact sphere normals, as a host would pass.
    el_mesh_desc d = m.desc();
    d.vertex_normals = m.positions.data();
    auto mesh = create(d);
    const float eye[3] = {0.4f, -0.3f, 5.0f};
    const Contours c = contours(mesh.get(), perspective(eye[0], eye[1], eye[2]));
    ASSERT_GE(c.triangles.size(), 32u);
    float worst = 0.0f;
    std::map<std::tuple<float, float, float>, int> ends;
    for (size_t i = 0; i < c.points.size(); i += 3) {
        const float* p = &c.points[i];
        const float pl = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const float v[3] = {eye[0] - p[0], eye[1] - p[1], eye[2] - p[2]};
        const float vl = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        worst = std::max(worst, std::abs((p[0] * v[0] + p[1] * v[1] + p[2] * v[2]) / (pl * vl)));
        // True contour of the unit sphere from this eye: p . eye = 1.
        EXPECT_NEAR((p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2]) / pl, 1.0f, 0.06f);
        ++ends[{p[0], p[1], p[2]}];
    }
    EXPECT_LT(worst, 0.02f) << "|n.v| at contour points";
    // Neighbouring triangles compute the same crossing bit for bit: one closed loop.
    for (auto& [p, count] : ends) EXPECT_EQ(count, 2);
    EXPECT_EQ(ends.size(), c.triangles.size());
}

TEST(Contour, ComputedNormalsGiveTheSameLoop) {
    const TestMesh m = uv_sphere(32, 16);
    auto mesh = create(m.desc());  // angle-weighted normals from the library
    const Contours c = contours(mesh.get(), orthographic(0.3f, 0.1f, -1.0f));
    ASSERT_GE(c.triangles.size(), 32u);
    const float dir[3] = {0.3f, 0.1f, -1.0f};
    const float dl = std::sqrt(0.3f * 0.3f + 0.1f * 0.1f + 1.0f);
    for (size_t i = 0; i < c.points.size(); i += 3) {
        const float* p = &c.points[i];
        const float pl = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        EXPECT_LT(std::abs((p[0] * dir[0] + p[1] * dir[1] + p[2] * dir[2]) / (pl * dl)), 0.03f);
    }
}

TEST(Contour, CubeFacesHaveNoSmoothContourInsideFlatFaces) {
    // Angle-weighted cube corner normals point diagonally; contours may cross triangles, but
    // every segment's points lie on the cube's surface.
    const TestMesh m = cube();
    auto mesh = create(m.desc());
    const Contours c = contours(mesh.get(), perspective(3, 4, 5));
    for (float v : c.points) {
        EXPECT_GE(v, -1e-6f);
        EXPECT_LE(v, 1.0f + 1e-6f);
    }
}
