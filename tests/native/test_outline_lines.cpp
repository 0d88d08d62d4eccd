// el_outline_lines' checks: every bad input gets a status and a message, a short buffer says how
// many segments are needed, and segments off the rounded edges pass through unchanged. What the
// moves are is held to the numpy reference in tests/addon/test_outline_lines.py.
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

// One convex 90-degree edge (0,0,0)-(1,0,0) between the top (+z) and front (-y) faces, r 0.1.
std::vector<float> edge_record() {
    std::vector<float> r(4 * EL_OUTLINE_EDGE_TEXELS, 0.0f);
    r[2] = 1.0f;   // N1 = +z
    r[3] = 0.1f;   // radius
    r[5] = -1.0f;  // N2 = -y
    r[12] = 1.0f;  // p1.x
    return r;
}

struct Fixture {
    std::vector<float> rec = edge_record();
    std::vector<uint32_t> rec_verts{0, 1};
    el_outline* outline = nullptr;
    el_outline_view view{};
    // Segment 0 along the rounded edge, segment 1 along an edge that is not (1 -> 2).
    std::vector<uint32_t> verts{0, 1, 1, 2};
    std::vector<float> p0{0, 0, 0, 1, 0, 0}, p1{1, 0, 0, 1, 0, -1}, n1{0, 0, 1, 1, 0, 0}, n2{0, -1, 0, 0, -1, 0};
    std::vector<float> taper{0, 1, 2, 3}, faces{1, 2, 3, 4};
    std::vector<el_chain_link> links{{0, 0.0f, 1.0f}, {0, 1.0f, 2.0f}};
    std::vector<float> o_p0, o_p1, o_n1, o_n2, o_taper, o_faces;
    std::vector<el_chain_link> o_links;

    Fixture() {
        el_outline_desc d{rec.data(), rec_verts.data(), 1, nullptr, nullptr, 0};
        EXPECT_EQ(el_outline_create(&d, &outline), EL_OK) << el_last_error();
        view.projection = EL_ORTHOGRAPHIC;
        view.view_dir[1] = -0.6f;  // looking along -(0, 0.6, 0.8): the top faces the eye, the front does not
        view.view_dir[2] = -0.8f;
        for (float* m : {view.object_to_world, view.world_to_view, view.view_to_clip})
            for (int i = 0; i < 16; ++i) m[i] = i % 5 == 0 ? 1.0f : 0.0f;
        view.width = 320.0f;
        view.height = 240.0f;
    }
    ~Fixture() { el_outline_destroy(outline); }

    el_outline_segments in() const {
        return {verts.data(), p0.data(), p1.data(), n1.data(), n2.data(), taper.data(), faces.data(), links.data(), 2};
    }
    el_outline_out out(uint32_t capacity) {
        for (auto* v : {&o_p0, &o_p1, &o_n1, &o_n2}) v->assign(3 * size_t(capacity), -7.0f);
        for (auto* v : {&o_taper, &o_faces}) v->assign(2 * size_t(capacity), -7.0f);
        o_links.assign(capacity, el_chain_link{9, -7.0f, -7.0f});
        return {o_p0.data(), o_p1.data(), o_n1.data(), o_n2.data(), o_taper.data(), o_faces.data(), o_links.data(),
                capacity};
    }
};

void expect_fails(el_status got, el_status want, const char* needle) {
    EXPECT_EQ(got, want) << el_last_error();
    EXPECT_NE(std::string(el_last_error()).find(needle), std::string::npos) << el_last_error();
}

}  // namespace

TEST(OutlineLines, MovesTheRoundedEdgeAndJoinsTheOtherAtTheFoot) {
    Fixture f;
    const el_outline_segments in = f.in();
    el_outline_out out = f.out(20);
    uint32_t count = 0;
    ASSERT_EQ(el_outline_lines(f.outline, &f.view, &in, &out, &count), EL_OK) << el_last_error();
    // The edge's ends move to its fillet's outline point: axis (0, r, -r) + r (0, -0.8, 0.6).
    EXPECT_NEAR(f.o_p0[1], 0.02f, 1e-6);
    EXPECT_NEAR(f.o_p0[2], -0.04f, 1e-6);
    // The unmoved side (1,0,0) -> (1,0,-1) meets it at vertex 1: it ends at the foot, r tan(45)
    // = 0.1 down its own line, and one segment joins the foot to the moved end, seen with the
    // moved one's normals and faces, in the side's chain at the vertex's arc length.
    ASSERT_EQ(count, 3u);
    EXPECT_NEAR(f.o_p0[3 + 2], -0.1f, 1e-6);
    EXPECT_FLOAT_EQ(f.o_p1[3 + 2], -1.0f);
    EXPECT_NEAR(f.o_p1[6 + 2], -0.1f, 1e-6);  // the joint runs foot -> tip, as the chain leaves the vertex
    EXPECT_NEAR(f.o_p0[6 + 2], -0.04f, 1e-6);
    EXPECT_EQ(f.o_faces[4], 1.0f);
    EXPECT_EQ(f.o_n2[6 + 1], -1.0f);
    EXPECT_EQ(f.o_taper[4], 2.0f);  // the side's taper at the vertex
    EXPECT_EQ(f.o_links[2].s0, 1.0f);
    EXPECT_EQ(f.o_links[2].s1, 1.0f);
}

TEST(OutlineLines, ShortBufferSaysHowManyAreNeeded) {
    Fixture f;
    const el_outline_segments in = f.in();
    el_outline_out out = f.out(2);
    uint32_t count = 0;
    expect_fails(el_outline_lines(f.outline, &f.view, &in, &out, &count), EL_ERR_BUFFER_TOO_SMALL, "out->capacity");
    EXPECT_EQ(count, 3u);
    EXPECT_EQ(f.o_p0[0], -7.0f) << "nothing written";
}

TEST(OutlineLines, NoRoundedEdgeNoChange) {
    Fixture f;
    f.verts = {5, 6, 6, 7};
    const el_outline_segments in = f.in();
    el_outline_out out = f.out(20);
    uint32_t count = 0;
    ASSERT_EQ(el_outline_lines(f.outline, &f.view, &in, &out, &count), EL_OK) << el_last_error();
    ASSERT_EQ(count, 2u);
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(f.o_p0[i], f.p0[i]);
        EXPECT_EQ(f.o_p1[i], f.p1[i]);
    }
}

TEST(OutlineLines, BadInputsGetAStatusAndAMessage) {
    Fixture f;
    el_outline_segments in = f.in();
    el_outline_out out = f.out(20);
    uint32_t count = 0;
    expect_fails(el_outline_lines(nullptr, &f.view, &in, &out, &count), EL_ERR_NULL_POINTER, "outline");
    expect_fails(el_outline_lines(f.outline, nullptr, &in, &out, &count), EL_ERR_NULL_POINTER, "view");
    expect_fails(el_outline_lines(f.outline, &f.view, nullptr, &out, &count), EL_ERR_NULL_POINTER, "in");
    expect_fails(el_outline_lines(f.outline, &f.view, &in, nullptr, &count), EL_ERR_NULL_POINTER, "out");
    expect_fails(el_outline_lines(f.outline, &f.view, &in, &out, nullptr), EL_ERR_NULL_POINTER, "out_count");
    el_outline_segments no_p1 = in;
    no_p1.p1 = nullptr;
    expect_fails(el_outline_lines(f.outline, &f.view, &no_p1, &out, &count), EL_ERR_NULL_POINTER, "in->p1");
    el_outline_out no_faces = out;
    no_faces.faces = nullptr;
    expect_fails(el_outline_lines(f.outline, &f.view, &in, &no_faces, &count), EL_ERR_NULL_POINTER, "out->faces");
    f.p0[4] = std::numeric_limits<float>::quiet_NaN();
    expect_fails(el_outline_lines(f.outline, &f.view, &in, &out, &count), EL_ERR_NON_FINITE, "in->p0[4]");
    f.p0[4] = 0.0f;
    el_outline_view v = f.view;
    v.projection = 7;
    expect_fails(el_outline_lines(f.outline, &v, &in, &out, &count), EL_ERR_INVALID_ARGUMENT, "projection");
    v = f.view;
    v.width = 0.0f;
    expect_fails(el_outline_lines(f.outline, &v, &in, &out, &count), EL_ERR_INVALID_ARGUMENT, "width");
    v = f.view;
    v.world_to_view[3] = std::numeric_limits<float>::infinity();
    expect_fails(el_outline_lines(f.outline, &v, &in, &out, &count), EL_ERR_NON_FINITE, "world_to_view");
    v = f.view;
    v.view_dir[1] = v.view_dir[2] = 0.0f;
    expect_fails(el_outline_lines(f.outline, &v, &in, &out, &count), EL_ERR_INVALID_ARGUMENT, "view_dir");
    // A singular transform moves nothing (no fillet to see), and the call succeeds.
    v = f.view;
    v.object_to_world[0] = 0.0f;
    EXPECT_EQ(el_outline_lines(f.outline, &v, &in, &out, &count), EL_OK) << el_last_error();
    EXPECT_EQ(count, 2u);
}

TEST(OutlineLines, BadRecordsAreRefused) {
    std::vector<float> rec = edge_record();
    std::vector<uint32_t> verts{0, 1};
    el_outline* o = reinterpret_cast<el_outline*>(0x1);
    el_outline_desc d{rec.data(), nullptr, 1, nullptr, nullptr, 0};
    expect_fails(el_outline_create(&d, &o), EL_ERR_NULL_POINTER, "edge_vertices");
    EXPECT_EQ(o, nullptr);
    d.edge_vertices = verts.data();
    rec[3] = std::numeric_limits<float>::infinity();
    expect_fails(el_outline_create(&d, &o), EL_ERR_NON_FINITE, "desc->edges[3]");
    d.edge_count = 0;
    d.corner_count = 1;
    expect_fails(el_outline_create(&d, &o), EL_ERR_NULL_POINTER, "desc->corners");
    expect_fails(el_outline_create(nullptr, &o), EL_ERR_NULL_POINTER, "desc");
}

TEST(OutlineLines, FilletOutlinePointInClosedForm) {
    const float na[3] = {0, 0, 1}, nb[3] = {0, -1, 0}, v[3] = {0, 0.6f, 0.8f};
    float p[3], c[3];
    uint8_t sil = 0;
    ASSERT_EQ(el_fillet_outline(na, nb, v, 1, p, c, &sil), EL_OK) << el_last_error();
    EXPECT_EQ(sil, 1);
    EXPECT_NEAR(p[1], -0.8f, 1e-6);
    EXPECT_NEAR(p[2], 0.6f, 1e-6);
    EXPECT_NEAR(c[1], -1.0f, 1e-6);  // (N1 + N2) / (1 + N1.N2): the sharp edge at (0, -r, r) from the axis
    EXPECT_NEAR(c[2], 1.0f, 1e-6);
    expect_fails(el_fillet_outline(na, nullptr, v, 1, p, c, &sil), EL_ERR_NULL_POINTER, "nb");
}

TEST(OutlineLines, FansListOwnSidesFirstAndCheckTheirInputs) {
    // Triangles (0 1 2) and (0 2 3) of the unit square in z = 0; edge items 0-1 (its own side
    // for the first), 2-5 (at corner 2, flat with both) and 0-7 (at corner 0, standing up).
    const uint32_t tris[6] = {0, 1, 2, 0, 2, 3};
    const float tri_n[6] = {0, 0, 1, 0, 0, 1};
    const int32_t items[6] = {2, 5, 0, 7, 0, 1};
    const float item_n[18] = {0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, -1, 0, 1, 0};
    float out[8];
    ASSERT_EQ(el_outline_fans(tris, tri_n, 2, items, 2, item_n, 2, 3, EL_OUTLINE_FANS_OWN_SIDES, 0.866f, 4, out), EL_OK)
        << el_last_error();
    // The first: its own side 0-1 (item 2) first, then 2-5 (item 0), flat at its corner 2; the
    // second: 0-1 and 2-5 both flat at its corners 0 and 1, in that order; 0-7 nowhere.
    const float want[8] = {3, 1, 0, 0, 3, 1, 0, 0};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], want[i]) << i;
    expect_fails(el_outline_fans(tris, tri_n, 2, items, 1, item_n, 2, 3, EL_OUTLINE_FANS_OWN_SIDES, 0.866f, 4, out),
                 EL_ERR_INVALID_ARGUMENT, "verts_per_item");
    const int32_t bad[6] = {2, 5, -4, 7, 0, 1};
    expect_fails(el_outline_fans(tris, tri_n, 2, bad, 2, item_n, 2, 3, 0, 0.866f, 4, out), EL_ERR_INVALID_ARGUMENT,
                 "item_verts[2]");
    const float nan_n[6] = {0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 1};
    expect_fails(el_outline_fans(tris, nan_n, 2, items, 2, item_n, 2, 3, 0, 0.866f, 4, out), EL_ERR_NON_FINITE,
                 "tri_normals[2]");
    expect_fails(el_outline_fans(tris, tri_n, 2, items, 2, item_n, 2, 3, 8, 0.866f, 4, out), EL_ERR_INVALID_ARGUMENT,
                 "flags");
}

TEST(OutlineLines, FansIgnoreItemsAtVerticesNoTriangleHas) {
    // An item at vertex 2^31 - 1 (no triangle's): listed nowhere, and no index over it is made.
    const uint32_t tris[3] = {0, 1, 2};
    const float tri_n[3] = {0, 0, 1};
    const int32_t items[2] = {2147483647, 1};
    const float item_n[6] = {0, 0, 1, 0, 0, 1};
    float out[2] = {-1, -1};
    ASSERT_EQ(el_outline_fans(tris, tri_n, 1, items, 1, item_n, 1, 2, 0, 0.866f, 2, out), EL_OK) << el_last_error();
    EXPECT_EQ(out[0], 2.0f);  // item 1, at the triangle's corner 1
    EXPECT_EQ(out[1], 0.0f);
}

TEST(BandEnds, PolygonArraysAreRequiredWhereTheirCountsSayTheyHaveElements) {
    const float positions[6] = {0, 0, 0, 1, 0, 0};
    const uint32_t edges[2] = {0, 1};
    const float normals[6] = {0, 0, 1, 0, -1, 0};
    const uint8_t rounded[1] = {1};
    const uint32_t selected[1] = {0};
    const int32_t faces[2] = {-1, -1};
    float out[4];
    el_polygons polys{};
    polys.polygon_count = 1;  // no start, total or normal for it
    expect_fails(el_band_ends(&polys, positions, 2, edges, normals, rounded, nullptr, nullptr, 1, selected, faces, 1, out),
                 EL_ERR_NULL_POINTER, "polys->start");
    polys.polygon_count = 0;
    polys.triangle_count = 1;
    expect_fails(el_band_ends(&polys, positions, 2, edges, normals, rounded, nullptr, nullptr, 1, selected, faces, 1, out),
                 EL_ERR_NULL_POINTER, "polys->tri_poly");
    polys.triangle_count = 0;  // no polygons at all: every band ends square
    ASSERT_EQ(el_band_ends(&polys, positions, 2, edges, normals, rounded, nullptr, nullptr, 1, selected, faces, 1, out),
              EL_OK)
        << el_last_error();
    for (float a : out) EXPECT_FLOAT_EQ(a, 1.5707964f);
}
