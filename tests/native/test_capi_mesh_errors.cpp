// Every bad input to the mesh and view entry points gets a status and a message, never a crash.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>

using namespace fixtures;

namespace {

// Expects `status`, a non-empty message mentioning `needle`, and a NULL handle.
void expect_create_fails(const el_mesh_desc& d, el_status status, const char* needle) {
    el_mesh* m = reinterpret_cast<el_mesh*>(0x1);
    EXPECT_EQ(el_mesh_create(&d, &m), status) << el_last_error();
    EXPECT_EQ(m, nullptr);
    EXPECT_NE(std::string(el_last_error()).find(needle), std::string::npos) << el_last_error();
}

struct HostCube {
    TestMesh m = cube();
    std::vector<uint32_t> edges, tri_edges;
    HostCube() {
        // Library-built topology as host input: valid by construction.
        auto mesh = create(m.desc());
        edges = fixtures::edges(mesh.get());
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> ids;
        for (uint32_t k = 0; k < edges.size() / 2; ++k) ids[ordered(edges[2 * k], edges[2 * k + 1])] = k;
        for (uint32_t t = 0; t < m.triangle_count(); ++t)
            for (uint32_t s = 0; s < 3; ++s)
                tri_edges.push_back(ids.at(ordered(m.triangles[3 * t + s], m.triangles[3 * t + (s + 1) % 3])));
    }
    el_mesh_desc desc() const {
        el_mesh_desc d = m.desc();
        d.edges = edges.data();
        d.edge_count = uint32_t(edges.size() / 2);
        d.triangle_edges = tri_edges.data();
        return d;
    }
};

}  // namespace

TEST(CapiErrors, AbiVersionAndStatusNames) {
    EXPECT_EQ(el_abi_version(), EL_ABI_VERSION);
    EXPECT_STREQ(el_status_name(EL_ERR_NON_FINITE), "EL_ERR_NON_FINITE");
    EXPECT_STREQ(el_status_name(static_cast<el_status>(999)), "EL_ERR_UNKNOWN");
}

TEST(CapiErrors, MessageClearsAfterSuccess) {
    EXPECT_EQ(el_mesh_create(nullptr, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_STRNE(el_last_error(), "");
    auto mesh = create(cube().desc());
    EXPECT_STREQ(el_last_error(), "");
}

TEST(CapiErrors, CreateNullsAndCounts) {
    const TestMesh c = cube();
    el_mesh* m = nullptr;
    EXPECT_EQ(el_mesh_create(nullptr, &m), EL_ERR_NULL_POINTER);
    const el_mesh_desc good = c.desc();
    EXPECT_EQ(el_mesh_create(&good, nullptr), EL_ERR_NULL_POINTER);

    el_mesh_desc d = good;
    d.positions = nullptr;
    expect_create_fails(d, EL_ERR_NULL_POINTER, "positions");
    d = good;
    d.triangles = nullptr;
    expect_create_fails(d, EL_ERR_NULL_POINTER, "triangles");
    d = good;
    d.vertex_count = 0;
    expect_create_fails(d, EL_ERR_INVALID_COUNT, "vertex_count");
    d = good;
    d.triangle_count = 0;
    expect_create_fails(d, EL_ERR_INVALID_COUNT, "no triangles");
    d = good;
    d.triangle_count = std::numeric_limits<uint32_t>::max() / 3 + 1;
    expect_create_fails(d, EL_ERR_OVERFLOW, "triangle_count");
}

TEST(CapiErrors, CreateIndicesAndValues) {
    TestMesh c = cube();
    c.triangles[7] = 8;
    expect_create_fails(c.desc(), EL_ERR_INDEX_OUT_OF_RANGE, "triangle 2 corner 1 refers to vertex 8");
    c = cube();
    c.positions[4] = std::nanf("");
    expect_create_fails(c.desc(), EL_ERR_NON_FINITE, "position of vertex 1");
    c = cube();
    c.positions[23] = std::numeric_limits<float>::infinity();
    expect_create_fails(c.desc(), EL_ERR_NON_FINITE, "position of vertex 7");
    c = cube();
    std::vector<float> normals(c.positions);
    normals[0] = std::nanf("");
    el_mesh_desc d = c.desc();
    d.vertex_normals = normals.data();
    expect_create_fails(d, EL_ERR_NON_FINITE, "normal of vertex 0");
}

TEST(CapiErrors, CreateHostEdges) {
    HostCube h;
    auto ok = create(h.desc());
    ASSERT_NE(ok, nullptr);

    el_mesh_desc d = h.desc();
    d.triangle_edges = nullptr;
    expect_create_fails(d, EL_ERR_NULL_POINTER, "triangle_edges");
    d = h.desc();
    d.edges = nullptr;
    expect_create_fails(d, EL_ERR_NULL_POINTER, "edges");
    d = h.desc();
    d.edge_count = 0;
    expect_create_fails(d, EL_ERR_INVALID_COUNT, "edge_count 0");
    d = h.desc();
    d.edge_count = std::numeric_limits<uint32_t>::max() / 2 + 1;
    expect_create_fails(d, EL_ERR_OVERFLOW, "edge_count");

    HostCube bad;
    bad.edges[3] = 99;
    expect_create_fails(bad.desc(), EL_ERR_INDEX_OUT_OF_RANGE, "edge 1 refers to vertex 99");
    bad = HostCube();
    bad.edges[1] = bad.edges[0];
    expect_create_fails(bad.desc(), EL_ERR_INVALID_ARGUMENT, "to itself");
    bad = HostCube();
    bad.tri_edges[4] = 1000;
    expect_create_fails(bad.desc(), EL_ERR_INDEX_OUT_OF_RANGE, "triangle 1 side 1 maps to edge 1000");
    bad = HostCube();
    std::swap(bad.tri_edges[0], bad.tri_edges[1]);
    expect_create_fails(bad.desc(), EL_ERR_INVALID_ARGUMENT, "triangle 0 side 0");

    std::vector<uint32_t> marks(h.edges.size() / 2, 0);
    marks[5] = 1u << 3;
    d = h.desc();
    d.edge_marks = marks.data();
    expect_create_fails(d, EL_ERR_INVALID_ARGUMENT, "edge 5 has marks");
    std::vector<float> w(h.edges.size() / 2, 0.0f);
    w[2] = std::nanf("");
    d = h.desc();
    d.edge_bevel_weights = w.data();
    expect_create_fails(d, EL_ERR_NON_FINITE, "bevel weight of edge 2");
    w[2] = 1.5f;
    expect_create_fails(d, EL_ERR_INVALID_ARGUMENT, "outside [0, 1]");

    const TestMesh c = cube();
    d = c.desc();
    d.edge_marks = marks.data();
    expect_create_fails(d, EL_ERR_INVALID_ARGUMENT, "need host edges");
}

TEST(CapiErrors, Getters) {
    auto mesh = create(cube().desc());
    const uint32_t n = info(mesh.get()).edge_count;
    std::vector<uint32_t> u(2 * n);
    std::vector<float> f(6 * n);
    std::vector<uint8_t> b(12);
    el_mesh_info i{};
    EXPECT_EQ(el_mesh_get_info(nullptr, &i), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_info(mesh.get(), nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_edges(nullptr, u.data(), n), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_edges(mesh.get(), nullptr, n), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_edges(mesh.get(), u.data(), n - 1), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_NE(std::string(el_last_error()).find("capacity_edges"), std::string::npos);
    EXPECT_EQ(el_mesh_get_edge_flags(mesh.get(), u.data(), 0), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_mesh_get_edge_face_counts(mesh.get(), nullptr, n), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_edge_normals(mesh.get(), f.data(), 3), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_mesh_get_edge_angles(nullptr, f.data(), n), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_face_normals(mesh.get(), f.data(), 11), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_mesh_get_degenerate_triangles(mesh.get(), b.data(), 2), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_mesh_get_triangle_flips(nullptr, b.data(), 12), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_triangle_flips(mesh.get(), nullptr, 12), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_triangle_flips(mesh.get(), b.data(), 11), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_NE(std::string(el_last_error()).find("el_mesh_get_triangle_flips: capacity_triangles"), std::string::npos)
        << el_last_error();
    EXPECT_EQ(el_mesh_get_triangle_flips(mesh.get(), b.data(), 12), EL_OK);
    uint32_t count = 0;
    EXPECT_EQ(el_mesh_get_edge_faces(mesh.get(), n, u.data(), 4, &count), EL_ERR_INDEX_OUT_OF_RANGE);
    EXPECT_EQ(el_mesh_get_edge_faces(mesh.get(), 0, u.data(), 4, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_edge_faces(mesh.get(), 0, nullptr, 4, &count), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_get_edge_faces(mesh.get(), 0, nullptr, 0, &count), EL_OK) << "count only";
    EXPECT_EQ(count, 2u);
    EXPECT_EQ(el_mesh_select_edges(mesh.get(), EL_EDGE_CREASE, 0, u.data(), 5, &count), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_mesh_select_edges(mesh.get(), EL_EDGE_CREASE, 0, u.data(), 12, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_classify(nullptr, 30.0f), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_classify(mesh.get(), std::nanf("")), EL_ERR_NON_FINITE);
    EXPECT_EQ(el_mesh_classify(mesh.get(), -1.0f), EL_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(el_mesh_classify(mesh.get(), 181.0f), EL_ERR_INVALID_ARGUMENT);
    el_mesh_destroy(nullptr);
    el_view_destroy(nullptr);
}

TEST(CapiErrors, Views) {
    auto mesh = create(cube().desc());
    el_view* v = reinterpret_cast<el_view*>(0x1);
    EXPECT_EQ(el_view_create(nullptr, &v), EL_ERR_NULL_POINTER);
    EXPECT_EQ(v, nullptr);
    EXPECT_EQ(el_view_create(mesh.get(), nullptr), EL_ERR_NULL_POINTER);
    ASSERT_EQ(el_view_create(mesh.get(), &v), EL_OK);
    ViewPtr view(v);

    std::vector<uint8_t> facing(12);
    EXPECT_EQ(el_view_get_facing(v, facing.data(), 12), EL_ERR_INVALID_ARGUMENT) << "before any update";
    el_camera cam = perspective(3, 4, 5);
    EXPECT_EQ(el_view_update(nullptr, &cam, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_view_update(v, nullptr, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_view_update(v, &cam, 1u << 7, nullptr), EL_ERR_INVALID_ARGUMENT);
    el_camera bad = cam;
    bad.projection = 5;
    EXPECT_EQ(el_view_update(v, &bad, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_INVALID_ARGUMENT);
    bad = cam;
    bad.eye[1] = std::nanf("");
    EXPECT_EQ(el_view_update(v, &bad, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_NON_FINITE);
    bad = cam;
    bad.object_to_world[5] = std::numeric_limits<float>::infinity();
    EXPECT_EQ(el_view_update(v, &bad, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_NON_FINITE);
    bad = cam;
    bad.object_to_world[0] = 0.0f;  // singular
    EXPECT_EQ(el_view_update(v, &bad, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(el_last_error()).find("invertible"), std::string::npos);
    bad = cam;
    bad.object_to_world[12] = 0.5f;  // projective row
    EXPECT_EQ(el_view_update(v, &bad, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_INVALID_ARGUMENT);
    bad = orthographic(0, 0, 0);
    EXPECT_EQ(el_view_update(v, &bad, EL_VIEW_SILHOUETTES, nullptr), EL_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(el_view_get_stats(v, nullptr), EL_ERR_NULL_POINTER);

    ASSERT_EQ(el_view_update(v, &cam, EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS, nullptr), EL_OK);
    uint32_t n = 0, small[2];
    EXPECT_EQ(el_view_get_silhouettes(v, small, 2, &n), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_view_get_silhouettes(v, small, 2, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_view_get_facing(v, facing.data(), 11), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_view_get_contours(v, nullptr, nullptr, 0, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_view_get_contours(nullptr, nullptr, nullptr, 0, &n), EL_ERR_NULL_POINTER);
    ASSERT_EQ(el_view_get_contours(v, nullptr, nullptr, 0, &n), EL_OK);
    if (n > 0) {
        std::vector<float> pts(6 * n);
        EXPECT_EQ(el_view_get_contours(v, pts.data(), nullptr, n - 1, &n), EL_ERR_BUFFER_TOO_SMALL);
    }
}
