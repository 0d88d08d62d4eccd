// Chains of edges and of contour segments: closed loops, free ends, junctions, arc length.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace fixtures;

namespace {

struct Result {
    std::vector<el_chain_link> links;
    std::vector<el_chain> chains;
};

Result chain(const el_mesh* mesh, const std::vector<uint32_t>& edges) {
    Result r;
    r.links.resize(edges.size());
    r.chains.resize(edges.size());
    uint32_t count = 0;
    EXPECT_EQ(el_mesh_chain_edges(mesh, edges.data(), uint32_t(edges.size()), r.links.data(), r.chains.data(),
                                  uint32_t(r.chains.size()), &count),
              EL_OK)
        << el_last_error();
    r.chains.resize(count);
    return r;
}

std::vector<uint32_t> select(const el_mesh* mesh, uint32_t all_of) {
    uint32_t n = 0;
    EXPECT_EQ(el_mesh_select_edges(mesh, all_of, 0, nullptr, 0, &n), EL_OK);
    std::vector<uint32_t> out(n);
    EXPECT_EQ(el_mesh_select_edges(mesh, all_of, 0, out.data(), n, &n), EL_OK);
    return out;
}

}  // namespace

TEST(Chains, OpenCylinderBordersAreTwoClosedCirclesOfKnownLength) {
    const int segments = 32;
    auto mesh = create(open_cylinder(segments).desc());
    const auto borders = select(mesh.get(), EL_EDGE_BORDER);
    ASSERT_EQ(borders.size(), size_t(2 * segments));
    const Result r = chain(mesh.get(), borders);
    ASSERT_EQ(r.chains.size(), 2u);
    const double polygon = 2.0 * segments * std::sin(M_PI / segments);  // perimeter of the inscribed polygon
    for (const el_chain& c : r.chains) {
        EXPECT_EQ(c.flags, EL_CHAIN_CLOSED);
        EXPECT_EQ(c.item_count, uint32_t(segments));
        EXPECT_NEAR(c.length, polygon, 1e-5 * polygon);
    }
    // Arc lengths step by one side length around each loop and end at the loop's length.
    for (const el_chain_link& l : r.links) {
        EXPECT_NEAR(std::abs(l.s1 - l.s0), polygon / segments, 1e-5);
        EXPECT_LE(std::max(l.s0, l.s1), r.chains[l.chain].length * (1 + 1e-6));
    }
}

TEST(Chains, OpenPathHasTwoFreeEndsAndContinuousArcLength) {
    // Three consecutive border edges of the open cylinder's bottom circle: one open chain.
    auto mesh = create(open_cylinder(8).desc());
    const auto e = edges(mesh.get());
    const auto borders = select(mesh.get(), EL_EDGE_BORDER);
    // The bottom circle's vertices are the even ones (open_cylinder): take 0-2, 2-4, 4-6.
    std::vector<uint32_t> path;
    for (uint32_t b : borders) {
        const uint32_t a = e[2 * b], c = e[2 * b + 1];
        if (a % 2 == 0 && c % 2 == 0 && std::max(a, c) <= 6 && std::max(a, c) - std::min(a, c) == 2) path.push_back(b);
    }
    ASSERT_EQ(path.size(), 3u);
    std::reverse(path.begin(), path.end());  // input order must not matter
    const Result r = chain(mesh.get(), path);
    ASSERT_EQ(r.chains.size(), 1u);
    EXPECT_EQ(r.chains[0].flags, EL_CHAIN_START_FREE | EL_CHAIN_END_FREE);
    EXPECT_EQ(r.chains[0].item_count, 3u);
    const double side = 2.0 * std::sin(M_PI / 8);
    EXPECT_NEAR(r.chains[0].length, 3 * side, 1e-5);
    // Each arc length value at a shared vertex is the same from both edges.
    std::vector<float> s;
    for (const auto& l : r.links) s.insert(s.end(), {std::min(l.s0, l.s1), std::max(l.s0, l.s1)});
    std::sort(s.begin(), s.end());
    ASSERT_EQ(s.size(), 6u);
    EXPECT_FLOAT_EQ(s[0], 0.0f);
    EXPECT_NEAR(s[1], s[2], 1e-6);
    EXPECT_NEAR(s[3], s[4], 1e-6);
    EXPECT_NEAR(s[5], 3 * side, 1e-5);
}

TEST(Chains, CubeCreasesStopAtCornerJunctionsWithoutFreeEnds) {
    auto mesh = create(cube().desc());
    ASSERT_EQ(el_mesh_classify(mesh.get(), 45.0f), EL_OK);
    const auto creases = select(mesh.get(), EL_EDGE_CREASE);
    ASSERT_EQ(creases.size(), 12u);
    const Result r = chain(mesh.get(), creases);
    // Three creases meet at every corner: each edge is a chain of its own, ending at junctions.
    ASSERT_EQ(r.chains.size(), 12u);
    for (const el_chain& c : r.chains) {
        EXPECT_EQ(c.flags, 0u);
        EXPECT_EQ(c.item_count, 1u);
        EXPECT_NEAR(c.length, 1.0f, 1e-6);
    }
}

TEST(Chains, SphereContoursFormOneClosedLoop) {
    auto mesh = create(uv_sphere(48, 24).desc());
    el_view* v = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &v), EL_OK);
    ViewPtr view(v);
    const el_camera cam = perspective(0.3f, -6.0f, 0.8f);
    ASSERT_EQ(el_view_update(v, &cam, EL_VIEW_CONTOURS, nullptr), EL_OK);
    uint32_t n = 0;
    ASSERT_EQ(el_view_get_contours(v, nullptr, nullptr, 0, &n), EL_OK);
    ASSERT_GT(n, 20u);
    std::vector<float> pts(6 * size_t(n));
    ASSERT_EQ(el_view_get_contours(v, pts.data(), nullptr, n, &n), EL_OK);
    std::vector<el_chain_link> links(n);
    std::vector<el_chain> chains(n);
    uint32_t count = 0;
    ASSERT_EQ(el_view_chain_contours(v, links.data(), n, chains.data(), n, &count), EL_OK) << el_last_error();
    ASSERT_EQ(count, 1u);
    EXPECT_EQ(chains[0].flags, EL_CHAIN_CLOSED);
    EXPECT_EQ(chains[0].item_count, n);
    double total = 0;
    for (uint32_t i = 0; i < n; ++i)
        total += std::hypot(pts[6 * i + 3] - pts[6 * i], pts[6 * i + 4] - pts[6 * i + 1], pts[6 * i + 5] - pts[6 * i + 2]);
    EXPECT_NEAR(chains[0].length, total, 1e-4 * total);
    // The contour circle of a unit sphere seen from distance d has radius sqrt(1 - 1/d^2).
    const double d = std::sqrt(0.09 + 36.0 + 0.64), rc = std::sqrt(1.0 - 1.0 / (d * d));
    EXPECT_NEAR(chains[0].length, 2 * M_PI * rc, 0.02 * 2 * M_PI * rc);
}

TEST(Chains, BadInputIsRefusedWithAMessage) {
    auto mesh = create(cube().desc());
    el_chain_link links[2];
    el_chain chains[2];
    uint32_t count = 7;
    const uint32_t out_of_range[] = {0, 99};
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), out_of_range, 2, links, chains, 2, &count), EL_ERR_INDEX_OUT_OF_RANGE);
    EXPECT_NE(std::string(el_last_error()).find("99"), std::string::npos);
    EXPECT_EQ(count, 0u);
    const uint32_t twice[] = {3, 3};
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), twice, 2, links, chains, 2, &count), EL_ERR_INVALID_ARGUMENT);
    const uint32_t ok[] = {0, 1};
    EXPECT_EQ(el_mesh_chain_edges(nullptr, ok, 2, links, chains, 2, &count), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), nullptr, 2, links, chains, 2, &count), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), ok, 2, nullptr, chains, 2, &count), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), ok, 2, links, chains, 2, nullptr), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), ok, 2, links, chains, 0, &count), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_mesh_chain_edges(mesh.get(), ok, 0, nullptr, nullptr, 0, &count), EL_OK);
    EXPECT_EQ(count, 0u);
    el_view* v = nullptr;
    ASSERT_EQ(el_view_create(mesh.get(), &v), EL_OK);
    ViewPtr view(v);
    EXPECT_EQ(el_view_chain_contours(nullptr, links, 2, chains, 2, &count), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_view_chain_contours(v, links, 2, chains, 2, &count), EL_OK);  // no contours yet
    EXPECT_EQ(count, 0u);
}
