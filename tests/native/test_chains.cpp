// Chains of edges and of contour segments: closed loops, free ends, junctions, arc length.
#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

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
    const double polygon = 2.0 * segments * std::sin(std::numbers::pi / segments);  // perimeter of the inscribed polygon
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
    const double side = 2.0 * std::sin(std::numbers::pi / 8);
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
    EXPECT_NEAR(chains[0].length, 2 * std::numbers::pi * rc, 0.02 * 2 * std::numbers::pi * rc);
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

// ---- Line nodes (el_line_nodes): chains in order, groups of 8, chord trees and their bounds ----

namespace {

struct Nodes {
    std::vector<float> rec;  // EL_LINE_NODE_FLOATS per segment, in chain order
    std::vector<uint32_t> order;
    const float* at(size_t i) const { return rec.data() + EL_LINE_NODE_FLOATS * i; }
};

Nodes line_nodes(const std::vector<float>& p0, const std::vector<float>& p1, const std::vector<el_chain_link>* links,
                 uint32_t flags = 0) {
    const uint32_t n = uint32_t(p0.size() / 3);
    std::vector<float> taper(2 * size_t(n));
    for (uint32_t i = 0; i < n; ++i) {  // taper at p0 and p1: 10 i and 10 i + 1, to tell the ends apart
        taper[2 * i] = float(10 * i);
        taper[2 * i + 1] = float(10 * i + 1);
    }
    Nodes r;
    r.rec.resize(size_t(n) * EL_LINE_NODE_FLOATS);
    r.order.resize(n);
    EXPECT_EQ(el_line_nodes(p0.data(), p1.data(), taper.data(), links ? links->data() : nullptr, n, flags,
                            r.rec.data(), n, r.order.data()),
              EL_OK)
        << el_last_error();
    return r;
}

// A polyline's segments given in `perm` order, with the chain records el_mesh_chain_edges would
// write for one open chain (arc lengths); reversed[i] gives segment i from its far end.
struct Polyline {
    std::vector<float> p0, p1;
    std::vector<el_chain_link> links;
};

Polyline polyline(const std::vector<glm::vec3>& pts, const std::vector<uint32_t>& perm, const std::vector<bool>& reversed,
                  uint32_t chain = 0) {
    Polyline out;
    std::vector<float> s(pts.size(), 0.0f);
    for (size_t k = 1; k < pts.size(); ++k) s[k] = s[k - 1] + glm::distance(pts[k - 1], pts[k]);
    for (uint32_t k : perm) {
        const bool rev = reversed[k];
        const glm::vec3 a = rev ? pts[k + 1] : pts[k], b = rev ? pts[k] : pts[k + 1];
        out.p0.insert(out.p0.end(), {a.x, a.y, a.z});
        out.p1.insert(out.p1.end(), {b.x, b.y, b.z});
        out.links.push_back({chain, rev ? s[k + 1] : s[k], rev ? s[k] : s[k + 1]});
    }
    return out;
}

double distance_to_segment(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::distance(p, a + t * ab);
}

glm::dvec3 point(const float* v) { return glm::dvec3(v[0], v[1], v[2]); }

}  // namespace

TEST(LineNodes, ChainOrderGroupsOfEightAndCountsOfTheChordsASegmentStarts) {
    // 20 collinear segments, listed scrambled and some reversed: one run, groups of 8, 8 and 4.
    std::vector<glm::vec3> pts;
    for (int k = 0; k <= 20; ++k) pts.emplace_back(float(k), 0.0f, 0.0f);
    std::vector<uint32_t> perm(20);
    std::iota(perm.begin(), perm.end(), 0u);
    std::reverse(perm.begin(), perm.begin() + 13);
    std::vector<bool> reversed(20, false);
    reversed[3] = reversed[11] = reversed[19] = true;
    const Polyline line = polyline(pts, perm, reversed);
    const Nodes r = line_nodes(line.p0, line.p1, &line.links);
    for (uint32_t k = 0; k < 20; ++k) {
        const float* v = r.at(k);
        EXPECT_EQ(perm[r.order[k]], k);        // place k holds segment k of the polyline
        EXPECT_FLOAT_EQ(v[0], float(k)) << k;  // a: its start along the chain, whichever way it was given
        EXPECT_FLOAT_EQ(v[4], float(k + 1)) << k;
        const uint32_t in = r.order[k];  // taper values follow their ends
        EXPECT_FLOAT_EQ(v[3], float(10 * in + (reversed[k] ? 1 : 0))) << k;
        EXPECT_FLOAT_EQ(v[7], float(10 * in + (reversed[k] ? 0 : 1))) << k;
        for (int l = 0; l < 3; ++l) EXPECT_LE(v[8 + l], 0.0f);  // collinear: no error (or no ancestor)
        EXPECT_FLOAT_EQ(v[19], -1.0f);                          // no chain spheres asked for
    }
    // Counts of the chords each segment starts: groups [0, 8), [8, 16) halve to 4, 2, 1; the
    // last group [16, 20) to 2, 1.
    auto code = [&](uint32_t k) { return uint32_t(r.at(k)[11]); };
    EXPECT_EQ(code(0), 2u + 4u * 16 + 8u * 256);
    EXPECT_EQ(code(2), 2u);
    EXPECT_EQ(code(4), 2u + 4u * 16);
    EXPECT_EQ(code(1), 0u);
    EXPECT_EQ(code(8), 2u + 4u * 16 + 8u * 256);
    EXPECT_EQ(code(16), 2u + 4u * 16);
    EXPECT_EQ(code(18), 2u);
    EXPECT_LT(r.at(16)[10], 0.0f);       // a group of 4 has two levels above its segments
    EXPECT_FLOAT_EQ(r.at(0)[15], 4.0f);  // the sphere of [0, 8]: centre 4, radius 4
    EXPECT_FLOAT_EQ(r.at(0)[12], 4.0f);
}

TEST(LineNodes, ErrorsBoundEverySegmentOfTheChordAndNeverShrinkUpwards) {
    // A zigzag of 8 segments with known heights: each chord's error is the farthest vertex of
    // the segments under it from the chord, or its children's if larger ([0, 2]'s vertex 1 lies
    // 0.25 off its chord, 0.2 off [0, 4]'s).
    std::vector<glm::vec3> pts;
    const float h[9] = {0.0f, -0.2f, 0.1f, 0.0f, 0.0f, 0.7f, 0.0f, 0.2f, 0.0f};
    for (int k = 0; k <= 8; ++k) pts.emplace_back(float(k), h[k], 0.5f * float(k));
    std::vector<uint32_t> perm(8);
    std::iota(perm.begin(), perm.end(), 0u);
    const Polyline line = polyline(pts, perm, std::vector<bool>(8, false));
    const Nodes r = line_nodes(line.p0, line.p1, &line.links, EL_LINE_NODES_CHAIN_SPHERES);
    for (uint32_t k = 0; k < 8; ++k) {
        const float* v = r.at(k);
        for (int l = 0; l < 3; ++l) {
            const uint32_t span = 2u << l, first = k / span * span;
            double worst = 0.0;
            for (uint32_t j = first + 1; j < first + span; ++j)
                worst = std::max(worst, distance_to_segment(glm::dvec3(pts[j]), glm::dvec3(pts[first]), glm::dvec3(pts[first + span])));
            EXPECT_GE(v[8 + l], worst * (1 - 1e-6)) << k << " " << l;
            if (l > 0) EXPECT_GE(v[8 + l], v[7 + l]);
        }
        // The group's and the chain's spheres hold every point.
        for (const glm::vec3& p : pts) {
            EXPECT_LE(glm::distance(glm::dvec3(p), point(v + 12)), v[15] * (1 + 1e-6));
            EXPECT_LE(glm::distance(glm::dvec3(p), point(v + 16)), v[19] * (1 + 1e-6));
        }
    }
    EXPECT_NEAR(r.at(0)[10], 0.7, 1e-6);  // the root: the 0.7 peak, straight off the chord
}

TEST(LineNodes, GapsJunctionsAndChainsOfTheirOwnStartNewGroups) {
    // Two chains, the first with a gap (a segment left out): three runs, no chord spans a gap or
    // two chains; without chain records every segment is its own.
    std::vector<glm::vec3> pts;
    for (int k = 0; k <= 6; ++k) pts.emplace_back(float(k), 0.0f, 0.0f);
    std::vector<uint32_t> all(6);
    std::iota(all.begin(), all.end(), 0u);
    Polyline line = polyline(pts, all, std::vector<bool>(6, false), 3);
    line.p0.erase(line.p0.begin() + 9, line.p0.begin() + 12);  // drop segment 3
    line.p1.erase(line.p1.begin() + 9, line.p1.begin() + 12);
    line.links.erase(line.links.begin() + 3);
    const Polyline other = polyline(pts, {0, 1}, {false, false}, 1);
    line.p0.insert(line.p0.end(), other.p0.begin(), other.p0.end());
    line.p1.insert(line.p1.end(), other.p1.begin(), other.p1.end());
    line.links.insert(line.links.end(), other.links.begin(), other.links.end());
    const Nodes r = line_nodes(line.p0, line.p1, &line.links);
    // Chain 1 first (2 segments), then chain 3: [0, 3) and [4, 6).
    ASSERT_EQ(r.order.size(), 7u);
    EXPECT_EQ(r.order[0], 5u);
    EXPECT_EQ(uint32_t(r.at(0)[11]), 2u);
    EXPECT_EQ(uint32_t(r.at(2)[11]), 3u);  // [0, 3) halves to [0, 1) and [1, 3): its first segment's parent
    EXPECT_EQ(uint32_t(r.at(3)[11]), 2u);  // [1, 3)
    EXPECT_EQ(uint32_t(r.at(5)[11]), 2u);  // [4, 6): a group of its own
    EXPECT_LT(r.at(5)[9], 0.0f);
    const Nodes alone = line_nodes(line.p0, line.p1, nullptr);
    for (uint32_t k = 0; k < 7; ++k) {
        EXPECT_EQ(alone.order[k], k);
        EXPECT_LT(alone.at(k)[8], 0.0f);
        EXPECT_EQ(alone.at(k)[11], 0.0f);
    }
}

TEST(LineNodes, BadInputIsRefusedWithAMessage) {
    const float p[6] = {0, 0, 0, 1, 0, 0}, q[6] = {1, 0, 0, 2, 0, 0}, t[4] = {0, 0, 0, 0};
    float out[2 * EL_LINE_NODE_FLOATS];
    uint32_t order[2];
    EXPECT_EQ(el_line_nodes(p, q, t, nullptr, 2, 0, out, 2, order), EL_OK);
    EXPECT_EQ(el_line_nodes(nullptr, q, t, nullptr, 2, 0, out, 2, order), EL_ERR_NULL_POINTER);
    EXPECT_EQ(el_line_nodes(p, q, t, nullptr, 2, 0, out, 1, order), EL_ERR_BUFFER_TOO_SMALL);
    EXPECT_EQ(el_line_nodes(p, q, t, nullptr, 2, 8, out, 2, order), EL_ERR_INVALID_ARGUMENT);
    const float nan[6] = {0, 0, 0, std::nanf(""), 0, 0};
    EXPECT_EQ(el_line_nodes(nan, q, t, nullptr, 2, 0, out, 2, order), EL_ERR_NON_FINITE);
    EXPECT_NE(std::string(el_last_error()).find("p0"), std::string::npos);
    EXPECT_EQ(el_line_nodes(nullptr, nullptr, nullptr, nullptr, 0, 0, nullptr, 0, nullptr), EL_OK);
}
