// Host-supplied topology (Blender's edges and loop-triangle -> edge map), marks and weights.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <map>

using namespace fixtures;

namespace {

// Blender's view of a quad mesh built by add_quad: the quad diagonal a-c is no edge.
struct HostTopology {
    std::vector<uint32_t> edges, triangle_edges;
};

HostTopology quad_topology(const TestMesh& m) {
    HostTopology h;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> ids;
    for (uint32_t t = 0; t < m.triangle_count(); ++t)
        for (uint32_t s = 0; s < 3; ++s) {
            const bool diagonal = (t % 2 == 0 && s == 2) || (t % 2 == 1 && s == 0);
            if (diagonal) {
                h.triangle_edges.push_back(EL_NO_EDGE);
                continue;
            }
            const auto key = ordered(m.triangles[3 * t + s], m.triangles[3 * t + (s + 1) % 3]);
            auto [it, inserted] = ids.try_emplace(key, uint32_t(ids.size()));
            if (inserted) h.edges.insert(h.edges.end(), {key.second, key.first});  // Blender order may be either
            h.triangle_edges.push_back(it->second);
        }
    return h;
}

}  // namespace

TEST(HostEdges, CubeQuadsHave12EdgesAllCreases) {
    const TestMesh m = cube();
    const HostTopology h = quad_topology(m);
    el_mesh_desc d = m.desc();
    d.edges = h.edges.data();
    d.edge_count = uint32_t(h.edges.size() / 2);
    d.triangle_edges = h.triangle_edges.data();
    auto mesh = create(d);
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.host_edges, 1u);
    EXPECT_EQ(i.edge_count, 12u);
    EXPECT_EQ(i.crease_edges, 12u);
    EXPECT_EQ(i.convex_edges, 12u);
    EXPECT_EQ(i.border_edges, 0u);
    EXPECT_EQ(edges(mesh.get()), h.edges) << "host edge order and numbering are kept";
}

TEST(HostEdges, MarksWeightsAndLooseEdges) {
    TestMesh m = cube();
    HostTopology h = quad_topology(m);
    const uint32_t loose_a = m.add_vertex(3, 3, 3), loose_b = m.add_vertex(4, 3, 3);
    h.edges.insert(h.edges.end(), {loose_a, loose_b});
    const uint32_t n = uint32_t(h.edges.size() / 2);
    std::vector<uint32_t> marks(n, 0);
    std::vector<float> weights(n, 0.0f);
    marks[0] = EL_MARK_SHARP;
    marks[1] = EL_MARK_SEAM | EL_MARK_FREESTYLE;
    weights[2] = 0.5f;
    el_mesh_desc d = m.desc();
    d.edges = h.edges.data();
    d.edge_count = n;
    d.triangle_edges = h.triangle_edges.data();
    d.edge_marks = marks.data();
    d.edge_bevel_weights = weights.data();
    auto mesh = create(d);
    const el_mesh_info i = info(mesh.get());
    EXPECT_EQ(i.loose_edges, 1u);
    EXPECT_EQ(i.marked_edges, 3u);
    const auto f = edge_flags(mesh.get());
    EXPECT_EQ(f[0] & EL_MARK_ALL, EL_MARK_SHARP);
    EXPECT_EQ(f[1] & EL_MARK_ALL, EL_MARK_SEAM | EL_MARK_FREESTYLE);
    EXPECT_EQ(f[2] & EL_MARK_ALL, EL_MARK_BEVEL) << "bevel weight > 0 sets the bevel mark";
    EXPECT_TRUE(f[n - 1] & EL_EDGE_LOOSE);
    uint32_t count = 0;
    ASSERT_EQ(el_mesh_select_edges(mesh.get(), EL_EDGE_CREASE, EL_MARK_SHARP | EL_MARK_BEVEL, nullptr, 0, &count), EL_OK);
    EXPECT_EQ(count, 2u);
    std::vector<uint32_t> sel(count);
    ASSERT_EQ(el_mesh_select_edges(mesh.get(), EL_EDGE_CREASE, EL_MARK_SHARP | EL_MARK_BEVEL, sel.data(), count, &count), EL_OK);
    EXPECT_EQ(sel, (std::vector<uint32_t>{0, 2}));
}

TEST(HostEdges, EdgesOnlyMeshIsAllLoose) {
    const float pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
    const uint32_t e[] = {0, 1, 1, 2};
    el_mesh_desc d{};
    d.positions = pos;
    d.vertex_count = 3;
    d.edges = e;
    d.edge_count = 2;
    auto mesh = create(d);
    EXPECT_EQ(info(mesh.get()).loose_edges, 2u);
    EXPECT_EQ(info(mesh.get()).triangle_count, 0u);
}

TEST(HostEdges, SilhouettesSkipQuadDiagonals) {
    const TestMesh m = uv_sphere(32, 16);
    const HostTopology h = [&] {
        // Caps are triangles with no diagonals: only the quad bands use add_quad.
        HostTopology t;
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> ids;
        const uint32_t caps = 32, quads_end = m.triangle_count() - 32;
        for (uint32_t tri = 0; tri < m.triangle_count(); ++tri)
            for (uint32_t s = 0; s < 3; ++s) {
                const bool in_band = tri >= caps && tri < quads_end;
                const uint32_t local = tri - caps;
                if (in_band && ((local % 2 == 0 && s == 2) || (local % 2 == 1 && s == 0))) {
                    t.triangle_edges.push_back(EL_NO_EDGE);
                    continue;
                }
                const auto key = ordered(m.triangles[3 * tri + s], m.triangles[3 * tri + (s + 1) % 3]);
                auto [it, inserted] = ids.try_emplace(key, uint32_t(ids.size()));
                if (inserted) t.edges.insert(t.edges.end(), {key.first, key.second});
                t.triangle_edges.push_back(it->second);
            }
        return t;
    }();
    el_mesh_desc d = m.desc();
    d.edges = h.edges.data();
    d.edge_count = uint32_t(h.edges.size() / 2);
    d.triangle_edges = h.triangle_edges.data();
    auto mesh = create(d);
    EXPECT_EQ(info(mesh.get()).edge_count, 32u * 15u + 32u * 16u);  // rings + meridians
    el_view* v = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &v), EL_OK);
    ViewPtr view(v);
    const el_camera cam = orthographic(0, 0, -1);
    ASSERT_EQ(el_view_update(v, &cam, EL_VIEW_SILHOUETTES, nullptr), EL_OK);
    uint32_t n = 0;
    ASSERT_EQ(el_view_get_silhouettes(v, nullptr, 0, &n), EL_OK);
    EXPECT_EQ(n, 32u);
}
