// Static classification: angles between face normals, creases by threshold, convexity.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace fixtures;

namespace {
std::vector<float> angles(const el_mesh* mesh) {
    std::vector<float> a(info(mesh).edge_count);
    EXPECT_EQ(el_mesh_get_edge_angles(mesh, a.data(), uint32_t(a.size())), EL_OK);
    return a;
}
}  // namespace

TEST(Classify, CubeHas12ConvexCreasesAt90Degrees) {
    auto mesh = create(cube().desc());
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.crease_edges, 12u);
    EXPECT_EQ(i.convex_edges, 12u);
    EXPECT_EQ(i.concave_edges, 0u);
    EXPECT_EQ(i.border_edges, 0u);
    const auto f = edge_flags(mesh.get());
    const auto a = angles(mesh.get());
    std::vector<float> n(6 * f.size());
    ASSERT_EQ(el_mesh_get_edge_normals(mesh.get(), n.data(), uint32_t(f.size())), EL_OK);
    for (size_t e = 0; e < f.size(); ++e) {
        if (f[e] & EL_EDGE_CREASE) {
            EXPECT_NEAR(a[e], 90.0f, 1e-4f);
            EXPECT_NEAR(n[6 * e] * n[6 * e + 3] + n[6 * e + 1] * n[6 * e + 4] + n[6 * e + 2] * n[6 * e + 5], 0.0f, 1e-6f);
        } else {
            EXPECT_NEAR(a[e], 0.0f, 1e-4f) << "diagonals are flat";
        }
    }
}

TEST(Classify, ThresholdIsStrictAndReclassifies) {
    auto mesh = create(cube().desc());
    ASSERT_EQ(el_mesh_classify(mesh.get(), 90.0f), EL_OK);
    EXPECT_EQ(info(mesh.get()).crease_edges, 0u) << "90 degrees does not exceed 90";
    ASSERT_EQ(el_mesh_classify(mesh.get(), 89.9f), EL_OK);
    EXPECT_EQ(info(mesh.get()).crease_edges, 12u);
    EXPECT_FLOAT_EQ(info(mesh.get()).crease_angle_deg, 89.9f);
    ASSERT_EQ(el_mesh_classify(mesh.get(), 0.0f), EL_OK);
    EXPECT_EQ(info(mesh.get()).crease_edges, 12u) << "flat diagonals never crease";
}

TEST(Classify, TetrahedronEdgesAllCrease) {
    auto mesh = create(tetrahedron().desc());
    EXPECT_EQ(info(mesh.get()).crease_edges, 6u);
    EXPECT_EQ(info(mesh.get()).convex_edges, 6u);
    // Dihedral acos(1/3) = 70.53 deg, so normals are 180 - 70.53 apart.
    const float expected = 180.0f - std::acos(1.0f / 3.0f) * 57.2957795f;
    for (float a : angles(mesh.get())) EXPECT_NEAR(a, expected, 1e-3f);
}

TEST(Classify, IcosphereHasNoCreaseAt30Degrees) {
    auto mesh = create(icosphere(2).desc());
    EXPECT_EQ(info(mesh.get()).crease_edges, 0u);
    EXPECT_EQ(info(mesh.get()).convex_edges, info(mesh.get()).edge_count);
    float largest = 0.0f;
    for (float a : angles(mesh.get())) largest = std::max(largest, a);
    EXPECT_GT(largest, 5.0f);
    EXPECT_LT(largest, 30.0f);
    // The bare icosahedron's edges are 41.8 degrees apart: all creases.
    auto ico = create(icosphere(0).desc());
    EXPECT_EQ(info(ico.get()).crease_edges, 30u);
}

class HingeAngle : public ::testing::TestWithParam<float> {};

TEST_P(HingeAngle, KnownDihedral) {
    const float opening = GetParam();  // angle between the two faces, through the solid side
    auto mesh = create(hinge(opening).desc());
    const float between_normals = std::abs(180.0f - opening);
    const auto f = edge_flags(mesh.get());
    const auto a = angles(mesh.get());
    size_t shared = f.size();
    for (size_t e = 0; e < f.size(); ++e)
        if (f[e] & EL_EDGE_MANIFOLD) shared = e;
    ASSERT_LT(shared, f.size());
    EXPECT_NEAR(a[shared], between_normals, 2e-3f);
    if (opening < 180.0f) EXPECT_TRUE(f[shared] & EL_EDGE_CONCAVE);
    if (opening > 180.0f) EXPECT_TRUE(f[shared] & EL_EDGE_CONVEX);
    ASSERT_EQ(el_mesh_classify(mesh.get(), between_normals - 0.5f), EL_OK);
    EXPECT_TRUE(edge_flags(mesh.get())[shared] & EL_EDGE_CREASE);
    ASSERT_EQ(el_mesh_classify(mesh.get(), between_normals + 0.5f), EL_OK);
    EXPECT_FALSE(edge_flags(mesh.get())[shared] & EL_EDGE_CREASE);
}

INSTANTIATE_TEST_SUITE_P(Openings, HingeAngle, ::testing::Values(30.0f, 90.0f, 135.0f, 179.0f, 200.0f, 270.0f, 330.0f));

TEST(Classify, FlatHingeIsNeitherConvexNorConcave) {
    auto mesh = create(hinge(180.0f).desc());
    EXPECT_EQ(info(mesh.get()).convex_edges + info(mesh.get()).concave_edges, 0u);
    EXPECT_EQ(info(mesh.get()).crease_edges, 0u);
}

TEST(Classify, MaterialBoundaries) {
    const TestMesh m = cube();
    std::vector<uint32_t> materials(m.triangle_count(), 0);
    materials[2] = materials[3] = 1;  // top face (z = 1) has another material
    el_mesh_desc d = m.desc();
    d.triangle_materials = materials.data();
    auto mesh = create(d);
    EXPECT_EQ(info(mesh.get()).material_boundary_edges, 4u);
}

TEST(Classify, EdgeNormalsFollowEdgeDirection) {
    // N1 belongs to the face running the edge first -> second vertex.
    const TestMesh m = hinge(270.0f);
    auto mesh = create(m.desc());
    const auto e = edges(mesh.get());
    const auto f = edge_flags(mesh.get());
    std::vector<float> n(6 * f.size());
    ASSERT_EQ(el_mesh_get_edge_normals(mesh.get(), n.data(), uint32_t(f.size())), EL_OK);
    for (size_t k = 0; k < f.size(); ++k) {
        if (!(f[k] & EL_EDGE_MANIFOLD)) continue;
        const bool forward = e[2 * k] == 0;  // 0 -> 1 is run by the first face (normal +z)
        EXPECT_NEAR(n[6 * k + 2], forward ? 1.0f : 0.0f, 1e-6f);
        EXPECT_NEAR(n[6 * k + 5], forward ? 0.0f : 1.0f, 1e-6f);
    }
}
