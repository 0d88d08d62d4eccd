// Orientation: classification, normals, facing and silhouettes do not depend on the input winding.
#include "mesh_fixtures.hpp"
#include "off_mesh.hpp"

#include "classify.hpp"
#include "face_normals.hpp"
#include "mesh_build.hpp"
#include "topology.hpp"
#include "vertex_normals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>

using namespace fixtures;

namespace {

// Reverses triangle t as an import would: corner 0 stays, so the library's reversal restores the
// consistent triangle exactly and every result can be compared bit for bit.
void flip(TestMesh& m, uint32_t t) { std::swap(m.triangles[3 * t + 1], m.triangles[3 * t + 2]); }

std::vector<uint8_t> flip_all(TestMesh& m, const std::vector<uint8_t>& pattern) {
    for (uint32_t t = 0; t < m.triangle_count(); ++t)
        if (pattern[t]) flip(m, t);
    return pattern;
}

std::vector<uint8_t> random_half(uint32_t n, uint32_t seed) {
    std::vector<uint8_t> p(n, 0);
    std::fill(p.begin(), p.begin() + n / 2, 1);
    std::shuffle(p.begin(), p.end(), std::mt19937(seed));
    return p;
}

std::vector<uint8_t> triangle_flips(const el_mesh* mesh) {
    std::vector<uint8_t> f(info(mesh).triangle_count);
    EXPECT_EQ(el_mesh_get_triangle_flips(mesh, f.data(), uint32_t(f.size())), EL_OK) << el_last_error();
    return f;
}

// Everything the library says about a mesh that could depend on winding, for two views.
struct Snapshot {
    el_mesh_info info{};
    std::vector<uint32_t> flags;
    std::vector<float> angles, edge_normals, face_normals;
    std::vector<uint32_t> silhouettes[2];
    std::vector<uint8_t> facing[2];
    std::vector<float> contours[2];
};

Snapshot snapshot(const el_mesh* mesh) {
    Snapshot s;
    s.info = info(mesh);
    const uint32_t ne = s.info.edge_count, nt = s.info.triangle_count;
    s.flags = edge_flags(mesh);
    s.angles.resize(ne);
    s.edge_normals.resize(6 * size_t(ne));
    s.face_normals.resize(3 * size_t(nt));
    EXPECT_EQ(el_mesh_get_edge_angles(mesh, s.angles.data(), ne), EL_OK);
    EXPECT_EQ(el_mesh_get_edge_normals(mesh, s.edge_normals.data(), ne), EL_OK);
    EXPECT_EQ(el_mesh_get_face_normals(mesh, s.face_normals.data(), nt), EL_OK);
    const el_camera cams[2] = {perspective(3.1f, 4.3f, 5.2f), orthographic(-0.3f, 0.45f, -1.0f)};
    for (int k = 0; k < 2; ++k) {
        el_view* v = nullptr;
        EXPECT_EQ(el_view_create(mesh, &v), EL_OK);
        ViewPtr view(v);
        EXPECT_EQ(el_view_update(v, &cams[k], EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS, nullptr), EL_OK);
        uint32_t n = 0;
        EXPECT_EQ(el_view_get_silhouettes(v, nullptr, 0, &n), EL_OK);
        s.silhouettes[k].resize(n);
        EXPECT_EQ(el_view_get_silhouettes(v, s.silhouettes[k].data(), n, &n), EL_OK);
        s.facing[k].resize(nt);
        EXPECT_EQ(el_view_get_facing(v, s.facing[k].data(), nt), EL_OK);
        EXPECT_EQ(el_view_get_contours(v, nullptr, nullptr, 0, &n), EL_OK);
        s.contours[k].resize(6 * size_t(n));
        EXPECT_EQ(el_view_get_contours(v, s.contours[k].data(), nullptr, n, &n), EL_OK);
    }
    return s;
}

Snapshot snapshot(const el_mesh_desc& d) { return snapshot(create(d).get()); }

// Bit-identical except the two input-winding counts.
void expect_same(const Snapshot& got, const Snapshot& want) {
    EXPECT_EQ(got.info.edge_count, want.info.edge_count);
    EXPECT_EQ(got.info.manifold_edges, want.info.manifold_edges);
    EXPECT_EQ(got.info.crease_edges, want.info.crease_edges);
    EXPECT_EQ(got.info.convex_edges, want.info.convex_edges);
    EXPECT_EQ(got.info.concave_edges, want.info.concave_edges);
    EXPECT_EQ(got.flags, want.flags);
    EXPECT_EQ(got.angles, want.angles);
    EXPECT_EQ(got.edge_normals, want.edge_normals);
    EXPECT_EQ(got.face_normals, want.face_normals);
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(got.silhouettes[k], want.silhouettes[k]) << "view " << k;
        EXPECT_EQ(got.facing[k], want.facing[k]) << "view " << k;
        EXPECT_EQ(got.contours[k], want.contours[k]) << "view " << k;
    }
}

uint32_t count_flagged(const std::vector<uint32_t>& flags, uint32_t bit) {
    return uint32_t(std::count_if(flags.begin(), flags.end(), [&](uint32_t f) { return (f & bit) != 0; }));
}

// The strip's centre line is a circle of radius 2; its cross-section turns half a turn.
TestMesh moebius(int segments) {
    TestMesh m;
    const float pi = 3.14159265358979f;
    for (int i = 0; i < segments; ++i) {
        const float t = 2.0f * pi * float(i) / float(segments), h = 0.5f * t;
        const float rx = std::cos(t), ry = std::sin(t);
        for (float w : {-0.5f, 0.5f})
            m.add_vertex((2.0f + w * std::cos(h)) * rx, (2.0f + w * std::cos(h)) * ry, w * std::sin(h));
    }
    for (int i = 0; i < segments; ++i) {
        const uint32_t b0 = 2 * i, t0 = 2 * i + 1;
        // After a full turn the section has turned half a turn: bottom and top swap.
        const uint32_t b1 = i + 1 < segments ? 2 * (i + 1) : 1, t1 = i + 1 < segments ? 2 * (i + 1) + 1 : 0;
        m.add_quad(b0, b1, t1, t0);
    }
    return m;
}

TestMesh translated(TestMesh m, float dx) {
    for (size_t i = 0; i < m.positions.size(); i += 3) m.positions[i] += dx;
    return m;
}

TestMesh joined(const TestMesh& a, const TestMesh& b) {
    TestMesh m = a;
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (uint32_t v : b.triangles) m.triangles.push_back(v + a.vertex_count());
    return m;
}

struct FlipCase {
    const char* name;
    std::vector<uint8_t> (*pattern)(uint32_t n);
};

void PrintTo(const FlipCase& c, std::ostream* os) { *os << c.name; }

class HalfFlippedCube : public ::testing::TestWithParam<FlipCase> {};

}  // namespace

TEST_P(HalfFlippedCube, ClassifiesLikeTheConsistentCube) {
    const TestMesh good = cube();
    TestMesh bad = good;
    const auto pattern = flip_all(bad, GetParam().pattern(good.triangle_count()));
    auto mesh = create(bad.desc());
    const Snapshot got = snapshot(mesh.get()), want = snapshot(good.desc());
    expect_same(got, want);
    EXPECT_EQ(got.info.convex_edges, 12u);
    EXPECT_EQ(got.info.crease_edges, 12u);
    EXPECT_EQ(count_flagged(got.flags, EL_EDGE_FLIPPED_WINDING), 0u);
    EXPECT_EQ(triangle_flips(mesh.get()), pattern) << "closed: outward, so exactly the flipped ones";
    EXPECT_EQ(got.info.reoriented_triangles, uint32_t(std::count(pattern.begin(), pattern.end(), 1)));
    EXPECT_GT(got.info.flipped_winding_edges, 0u) << "the input's inconsistent edges are still counted";
    EXPECT_EQ(want.info.flipped_winding_edges, 0u);
    EXPECT_EQ(want.info.reoriented_triangles, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Patterns, HalfFlippedCube,
    ::testing::Values(
        FlipCase{"FirstHalf", [](uint32_t n) { std::vector<uint8_t> p(n, 0); std::fill(p.begin(), p.begin() + n / 2, 1); return p; }},
        FlipCase{"EveryOther", [](uint32_t n) { std::vector<uint8_t> p(n); for (uint32_t t = 0; t < n; ++t) p[t] = t % 2; return p; }},
        FlipCase{"RandomHalf", [](uint32_t n) { return random_half(n, 7); }},
        FlipCase{"AnotherRandomHalf", [](uint32_t n) { return random_half(n, 1234); }},
        FlipCase{"AllButOne", [](uint32_t n) { std::vector<uint8_t> p(n, 1); p[5] = 0; return p; }}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Orient, InsideOutClosedMeshIsTurnedOutward) {
    for (const TestMesh& good : {cube(), icosphere(2), tetrahedron()}) {
        TestMesh bad = good;
        for (uint32_t t = 0; t < bad.triangle_count(); ++t) flip(bad, t);
        auto mesh = create(bad.desc());
        expect_same(snapshot(mesh.get()), snapshot(good.desc()));
        EXPECT_EQ(info(mesh.get()).reoriented_triangles, good.triangle_count());
        EXPECT_EQ(info(mesh.get()).flipped_winding_edges, 0u) << "consistent, only inside out";
        EXPECT_EQ(info(mesh.get()).concave_edges, 0u);
    }
}

TEST(Orient, OpenGridKeepsTheMajorityWinding) {
    const TestMesh good = grid(8);  // 128 triangles of similar area
    const uint32_t n = good.triangle_count();
    std::vector<uint8_t> minority(n, 0);
    for (uint32_t t = 0; t < n; t += 3) minority[t] = 1;  // 43 of 128, triangle 0 among them
    TestMesh bad = good;
    flip_all(bad, minority);
    auto mesh = create(bad.desc());
    expect_same(snapshot(mesh.get()), snapshot(good.desc()));
    EXPECT_EQ(triangle_flips(mesh.get()), minority) << "the minority is reversed, not the first triangle's side";

    // The flipped triangles as the majority: the grid turns over, keeping them.
    TestMesh over = good;
    std::vector<uint8_t> majority(n);
    for (uint32_t t = 0; t < n; ++t) majority[t] = minority[t] ^ 1u;
    flip_all(over, majority);
    auto turned = create(over.desc());
    EXPECT_EQ(triangle_flips(turned.get()), minority);
    const Snapshot s = snapshot(turned.get()), g = snapshot(good.desc());
    for (size_t i = 0; i < s.face_normals.size(); ++i) EXPECT_EQ(s.face_normals[i], -g.face_normals[i]);
    EXPECT_EQ(s.info.convex_edges, g.info.concave_edges);
    EXPECT_EQ(s.info.concave_edges, g.info.convex_edges);
    EXPECT_EQ(s.info.crease_edges, g.info.crease_edges);
    EXPECT_EQ(s.angles, g.angles);
    EXPECT_EQ(count_flagged(s.flags, EL_EDGE_FLIPPED_WINDING), 0u);
}

TEST(Orient, ComponentsAreOrientedSeparately) {
    // An outward cube, an inside-out cube, and an open grid mostly wound one way; then half of
    // every triangle flipped at random. Each component must come back to its own answer.
    TestMesh inside_out = translated(cube(), 3.0f);
    for (uint32_t t = 0; t < inside_out.triangle_count(); ++t) flip(inside_out, t);
    const TestMesh good = joined(joined(cube(), translated(cube(), 3.0f)), translated(grid(4), -6.0f));
    const TestMesh given = joined(joined(cube(), inside_out), translated(grid(4), -6.0f));
    auto plain = create(given.desc());
    std::vector<uint8_t> want(given.triangle_count(), 0);
    std::fill(want.begin() + 12, want.begin() + 24, 1);
    EXPECT_EQ(triangle_flips(plain.get()), want);
    expect_same(snapshot(plain.get()), snapshot(good.desc()));

    TestMesh bad = given;
    auto pattern = random_half(bad.triangle_count(), 99);
    std::fill(pattern.begin() + 24, pattern.end(), 0);
    for (uint32_t t = 24; t < bad.triangle_count(); t += 4) pattern[t] = 1;  // a grid minority
    flip_all(bad, pattern);
    for (uint32_t t = 0; t < bad.triangle_count(); ++t) want[t] ^= pattern[t];
    auto mesh = create(bad.desc());
    EXPECT_EQ(triangle_flips(mesh.get()), want);
    expect_same(snapshot(mesh.get()), snapshot(good.desc()));
}

TEST(Orient, MoebiusStripFlagsItsOneConflictEdge) {
    const TestMesh strip = moebius(24);
    for (uint32_t seed : {0u, 5u, 11u}) {
        TestMesh m = strip;
        if (seed) flip_all(m, random_half(m.triangle_count(), seed));
        auto mesh = create(m.desc());
        const Snapshot s = snapshot(mesh.get());
        EXPECT_EQ(s.info.non_manifold_edges, 0u);
        // The triangles form one cycle through manifold edges: the walk's two fronts meet once.
        EXPECT_EQ(count_flagged(s.flags, EL_EDGE_FLIPPED_WINDING), 1u) << "seed " << seed;
        for (uint32_t e = 0; e < s.flags.size(); ++e) {
            if (!(s.flags[e] & EL_EDGE_FLIPPED_WINDING)) continue;
            EXPECT_TRUE(s.flags[e] & EL_EDGE_MANIFOLD);
            EXPECT_FALSE(s.flags[e] & (EL_EDGE_CONVEX | EL_EDGE_CONCAVE | EL_EDGE_CREASE)) << "edge " << e;
            for (int k = 0; k < 2; ++k)
                EXPECT_EQ(std::count(s.silhouettes[k].begin(), s.silhouettes[k].end(), e), 0) << "edge " << e;
        }
        for (float a : s.angles) EXPECT_TRUE(std::isfinite(a));
        for (float v : s.face_normals) EXPECT_TRUE(std::isfinite(v));
        ASSERT_EQ(el_mesh_classify(mesh.get(), 0.0f), EL_OK);
        for (uint32_t f : edge_flags(mesh.get()))
            if (f & EL_EDGE_FLIPPED_WINDING) EXPECT_FALSE(f & EL_EDGE_CREASE) << "not even at a 0 degree threshold";
    }
}

TEST(Orient, HostTopologyWithPolygonDiagonals) {
    // Blender's side of the cube: quads whose diagonal is no edge, so triangles join only across
    // the quads' own edges. Whole quads flipped, as an import flips polygons, and single triangles.
    const TestMesh good = cube();
    std::set<std::pair<uint32_t, uint32_t>> diagonals;
    for (uint32_t t = 0; t < good.triangle_count(); t += 2)
        diagonals.insert(ordered(good.triangles[3 * t], good.triangles[3 * t + 2]));
    // One edge list for every variant, so edge indices compare.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> ids;
    std::vector<uint32_t> edges;
    for (uint32_t t = 0; t < good.triangle_count(); ++t)
        for (uint32_t s = 0; s < 3; ++s) {
            const auto key = ordered(good.triangles[3 * t + s], good.triangles[3 * t + (s + 1) % 3]);
            if (!diagonals.count(key) && ids.try_emplace(key, uint32_t(ids.size())).second)
                edges.insert(edges.end(), {key.second, key.first});  // Blender's order may be either
        }
    auto host_desc = [&](const TestMesh& m, std::vector<uint32_t>& tri_edges) {
        tri_edges.clear();
        for (uint32_t t = 0; t < m.triangle_count(); ++t)
            for (uint32_t s = 0; s < 3; ++s) {
                const auto key = ordered(m.triangles[3 * t + s], m.triangles[3 * t + (s + 1) % 3]);
                tri_edges.push_back(diagonals.count(key) ? EL_NO_EDGE : ids.at(key));
            }
        el_mesh_desc d = m.desc();
        d.edges = edges.data();
        d.edge_count = uint32_t(edges.size() / 2);
        d.triangle_edges = tri_edges.data();
        return d;
    };
    std::vector<uint32_t> gt;
    const Snapshot want = snapshot(host_desc(good, gt));
    EXPECT_EQ(want.info.crease_edges, 12u);
    const std::vector<uint8_t> patterns[] = {{1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1},
                                             {0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0}};
    for (const auto& p : patterns) {
        TestMesh bad = good;
        flip_all(bad, p);
        std::vector<uint32_t> bt;
        auto mesh = create(host_desc(bad, bt));
        expect_same(snapshot(mesh.get()), want);
        EXPECT_EQ(triangle_flips(mesh.get()), p);
    }
}

TEST(Orient, ConsistentMeshesAreUnchanged) {
    // The pipeline without orientation, straight from the internals, is the reference.
    const TestMesh meshes[] = {cube(), icosphere(2), uv_sphere(16, 8), tetrahedron(), open_box(),
                               grid(6), open_cylinder(12), hinge(135.0f), hinge(250.0f), fin()};
    for (const TestMesh& m : meshes) {
        const auto built = el::build_mesh(m.desc());
        EXPECT_EQ(built->orient.reoriented_triangles, 0u);
        EXPECT_EQ(built->orient.input_flipped_edges, 0u);
        EXPECT_EQ(std::count(built->orient.flips.begin(), built->orient.flips.end(), 1), 0);
        el::MeshData ref;
        const auto* p = reinterpret_cast<const glm::vec3*>(m.positions.data());
        ref.positions.assign(p, p + m.vertex_count());
        ref.triangles = m.triangles;
        ref.topo = el::build_topology(m.triangles.data(), m.triangle_count(), m.vertex_count());
        el::compute_face_normals(ref, ref.geom);
        el::compute_vertex_normals(ref, ref.geom);
        el::analyze_edges(ref, ref.cls);
        el::apply_crease_threshold(ref.cls, 30.0f);
        EXPECT_EQ(built->triangles, ref.triangles);
        EXPECT_EQ(built->geom.face_normals, ref.geom.face_normals);
        EXPECT_EQ(built->geom.face_offsets, ref.geom.face_offsets);
        EXPECT_EQ(built->geom.vertex_normals, ref.geom.vertex_normals);
        EXPECT_EQ(built->cls.edge_flags, ref.cls.edge_flags);
        EXPECT_EQ(built->cls.n1, ref.cls.n1);
        EXPECT_EQ(built->cls.n2, ref.cls.n2);
        EXPECT_EQ(built->cls.angle_deg, ref.cls.angle_deg);
        EXPECT_EQ(built->cls.silhouette_candidates, ref.cls.silhouette_candidates);
        auto mesh = create(m.desc());
        EXPECT_EQ(info(mesh.get()).reoriented_triangles, 0u);
        EXPECT_EQ(triangle_flips(mesh.get()), std::vector<uint8_t>(m.triangle_count(), 0));
    }
}

TEST(Orient, RealMeshWithARandomHalfFlipped) {
    for (const char* name : {"fandisk", "armadillo"}) {
        const std::string path = std::string(EDGELIGHT_TEST_MESH_DIR) + "/" + name + ".off";
        el_tools::LoadedMesh l;
        ASSERT_NO_THROW(l = el_tools::read_off(path)) << path << " (apt-get install libcgal-demo)";
        TestMesh good;
        good.positions = l.positions;
        good.triangles = l.triangles;
        TestMesh bad = good;
        const auto pattern = flip_all(bad, random_half(good.triangle_count(), 2024));
        auto mesh = create(bad.desc());
        const Snapshot got = snapshot(mesh.get()), want = snapshot(good.desc());
        expect_same(got, want);
        EXPECT_EQ(want.info.reoriented_triangles, 0u) << name << " is given outward";
        EXPECT_EQ(triangle_flips(mesh.get()), pattern) << name;
        EXPECT_GT(got.info.flipped_winding_edges, got.info.edge_count / 3) << name;
        EXPECT_EQ(count_flagged(got.flags, EL_EDGE_FLIPPED_WINDING), 0u) << name;
        EXPECT_GT(want.info.crease_edges, 0u);
    }
}
