// libFuzzer target for the whole C ABI: bytes become meshes (any counts, indices in and
// out of range, NaN/Inf/huge/denormal positions, degenerate faces, optional host topology), cameras,
// table descriptors and highlight inputs, and every el_* entry point is called with them. The
// library must answer each call with a status, never crash, and never trip ASan or UBSan.
//
// Buffers handed to the library always match the counts and capacities passed with them: a
// caller lying about a buffer's size is outside what any C API can check.
#include <edgelight/edgelight.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

namespace {

float any_float(FuzzedDataProvider& p) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    static const float special[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, 1e-7f, -1e-7f, 1e-38f, 1e-45f,
                                    3e38f, -3e38f, inf, -inf, std::numeric_limits<float>::quiet_NaN(),
                                    1.5707964f, 3.1415927f, 1e4f, 1e5f, 1e-4f, 10001.0f, 1e6f};
    switch (p.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: return p.PickValueInArray(special);
    case 1: return float(p.ConsumeIntegralInRange<int>(-4, 4));
    case 2: return p.ConsumeFloatingPointInRange<float>(-2.0f, 2.0f);
    default: {
        uint32_t bits = p.ConsumeIntegral<uint32_t>();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    }
}

void fill3(FuzzedDataProvider& p, float* v) {
    for (int i = 0; i < 3; ++i) v[i] = any_float(p);
}

uint32_t index_for(FuzzedDataProvider& p, uint32_t count) {
    switch (p.ConsumeIntegralInRange<int>(0, 7)) {
    case 0: return p.ConsumeIntegral<uint32_t>();  // usually out of range
    case 1: return count;                           // one past the end
    case 2: return EL_NO_EDGE;
    default: return count ? p.ConsumeIntegralInRange<uint32_t>(0, count - 1) : 0;
    }
}

// Capacity for a getter: usually enough, sometimes short (must fail cleanly, writing nothing past).
uint32_t capacity_for(FuzzedDataProvider& p, uint32_t needed) {
    return p.ConsumeBool() ? needed : p.ConsumeIntegralInRange<uint32_t>(0, needed + 1);
}

template <class T>
void getter(FuzzedDataProvider& p, uint32_t needed, size_t per, el_status (*fn)(const el_mesh*, T*, uint32_t),
            const el_mesh* mesh) {
    const uint32_t cap = capacity_for(p, needed);
    std::vector<T> out(size_t(cap) * per + 1);
    fn(mesh, p.ConsumeIntegralInRange<int>(0, 15) ? out.data() : nullptr, cap);
}

void fuzz_view(FuzzedDataProvider& p, const el_mesh* mesh, const el_mesh_info& info) {
    el_view* view = nullptr;
    if (el_view_create(mesh, &view) != EL_OK) return;
    const int updates = p.ConsumeIntegralInRange<int>(1, 3);
    for (int u = 0; u < updates; ++u) {
        el_camera cam{};
        cam.projection = p.ConsumeIntegralInRange<int32_t>(-1, 2);
        fill3(p, cam.eye);
        fill3(p, cam.view_dir);
        const bool identity = p.ConsumeBool();
        for (int i = 0; i < 16; ++i)
            cam.object_to_world[i] = identity ? (i % 5 == 0 ? 1.0f : 0.0f) : any_float(p);
        if (identity && p.ConsumeBool()) cam.object_to_world[p.ConsumeIntegralInRange(0, 15)] = any_float(p);
        uint32_t changed = 0;
        el_view_update(view, &cam, p.ConsumeIntegralInRange<uint32_t>(0, 4), p.ConsumeBool() ? &changed : nullptr);

        uint32_t count = 0;
        const uint32_t cap = p.ConsumeIntegralInRange<uint32_t>(0, info.edge_count + 1);
        std::vector<uint32_t> sil(cap + 1);
        el_view_get_silhouettes(view, sil.data(), cap, &count);
        el_view_get_silhouettes(view, nullptr, 0, &count);
        const uint32_t fcap = capacity_for(p, info.triangle_count);
        std::vector<uint8_t> facing(fcap + 1);
        el_view_get_facing(view, facing.data(), fcap);
        const uint32_t ccap = p.ConsumeIntegralInRange<uint32_t>(0, 2 * info.triangle_count + 1);
        std::vector<float> pts(size_t(ccap) * 6 + 1);
        std::vector<uint32_t> tris(ccap + 1);
        el_view_get_contours(view, pts.data(), p.ConsumeBool() ? tris.data() : nullptr, ccap, &count);
        el_view_stats stats{};
        el_view_get_stats(view, &stats);
        // Chains of the contours: exact or short capacities, or NULL arrays.
        const uint32_t lcap = capacity_for(p, stats.contour_segments);
        const uint32_t kcap = capacity_for(p, stats.contour_segments);
        std::vector<el_chain_link> links(lcap + 1);
        std::vector<el_chain> chains(kcap + 1);
        el_view_chain_contours(view, p.ConsumeBool() ? links.data() : nullptr, lcap,
                               p.ConsumeBool() ? chains.data() : nullptr, kcap, &count);
    }
    el_view_update(view, nullptr, EL_VIEW_SILHOUETTES, nullptr);
    el_view_get_stats(view, nullptr);
    el_view_destroy(view);
}

// Many instances' view lines: any transforms (singular ones fail alone), with or without an
// outline of records over the mesh's first vertices, faces and taper.
void fuzz_view_lines(FuzzedDataProvider& p, const el_mesh* mesh, const el_mesh_info& info) {
    std::vector<float> rec(4 * EL_OUTLINE_EDGE_TEXELS * 2 + 1);
    for (auto& x : rec) x = float(p.ConsumeIntegralInRange<int>(-2, 2)) * 0.5f;
    std::vector<uint32_t> rv{0, 1, 1, 2};
    el_outline_desc od{rec.data(), rv.data(), 2, nullptr, nullptr, 0};
    el_outline* outline = nullptr;
    if (p.ConsumeBool()) el_outline_create(&od, &outline);
    const uint32_t n = p.ConsumeIntegralInRange<uint32_t>(0, 5);
    std::vector<el_outline_view> views(n + 1);
    for (auto& v : views) {
        v.projection = p.ConsumeIntegralInRange<int32_t>(-1, 2);
        fill3(p, v.eye);
        fill3(p, v.view_dir);
        for (float* m : {v.object_to_world, v.world_to_view, v.view_to_clip}) {
            const bool identity = p.ConsumeBool();
            for (int i = 0; i < 16; ++i) m[i] = identity ? (i % 5 == 0 ? 1.0f : 0.0f) : any_float(p);
        }
        v.width = p.ConsumeBool() ? 64.0f : any_float(p);
        v.height = 48.0f;
    }
    std::vector<float> faces(2 * size_t(info.edge_count) + 1, 1.0f);
    if (p.ConsumeIntegralInRange<int>(0, 7) == 0) faces[0] = any_float(p);
    el_view_lines_desc d{mesh, outline, p.ConsumeBool() ? faces.data() : nullptr, views.data(), n,
                         p.ConsumeIntegralInRange<uint32_t>(0, 2)};
    el_view_lines* lines = nullptr;
    if (el_view_lines_create(p.ConsumeIntegralInRange<int>(0, 15) ? &d : nullptr, &lines) == EL_OK) {
        std::vector<uint32_t> offsets(n + 2);
        std::vector<int32_t> status(n + 1);
        el_view_lines_get_offsets(lines, offsets.data(), capacity_for(p, n + 1), p.ConsumeBool() ? status.data() : nullptr);
        const char* message = nullptr;
        el_view_lines_get_message(lines, p.ConsumeIntegralInRange<uint32_t>(0, n + 1), &message);
        const uint32_t total = offsets[n];
        const uint32_t cap = capacity_for(p, total);
        std::vector<float> o3(4 * (3 * size_t(cap) + 1)), o2(2 * (2 * size_t(cap) + 1));
        std::vector<el_chain_link> links(cap + 1);
        el_outline_out out{&o3[0], &o3[3 * size_t(cap) + 1], &o3[2 * (3 * size_t(cap) + 1)],
                           &o3[3 * (3 * size_t(cap) + 1)], &o2[0], &o2[2 * size_t(cap) + 1],
                           p.ConsumeIntegralInRange<int>(0, 7) ? links.data() : nullptr, cap};
        el_view_lines_copy(lines, &out);
    }
    el_view_lines_destroy(lines);
    el_outline_destroy(outline);
}

void fuzz_mesh(FuzzedDataProvider& p) {
    const uint32_t vc = p.ConsumeIntegralInRange<uint32_t>(0, 48);
    const uint32_t tc = p.ConsumeIntegralInRange<uint32_t>(0, 48);
    std::vector<float> pos(size_t(vc) * 3 + 1);
    // Mostly small integer grids (shared vertices, real topology), sometimes any float.
    const bool wild = p.ConsumeIntegralInRange<int>(0, 3) == 0;
    for (size_t i = 0; i < size_t(vc) * 3; ++i)
        pos[i] = wild ? any_float(p) : float(p.ConsumeIntegralInRange<int>(-2, 2));
    std::vector<uint32_t> tri(size_t(tc) * 3 + 1);
    const bool bad_indices = p.ConsumeIntegralInRange<int>(0, 3) == 0;
    for (size_t i = 0; i < size_t(tc) * 3; ++i)
        tri[i] = bad_indices ? index_for(p, vc) : (vc ? p.ConsumeIntegralInRange<uint32_t>(0, vc - 1) : 0);

    el_mesh_desc d{};
    d.positions = p.ConsumeIntegralInRange<int>(0, 15) ? pos.data() : nullptr;
    d.vertex_count = vc;
    d.triangles = p.ConsumeIntegralInRange<int>(0, 15) ? tri.data() : nullptr;
    d.triangle_count = tc;

    std::vector<uint32_t> edges, tri_edges, marks, mats;
    std::vector<float> bevel, vnormals, tnormals;
    if (p.ConsumeBool()) {  // host topology
        const uint32_t ec = p.ConsumeIntegralInRange<uint32_t>(0, 64);
        edges.resize(size_t(ec) * 2 + 1);
        for (size_t i = 0; i < size_t(ec) * 2; ++i) edges[i] = index_for(p, vc);
        tri_edges.resize(size_t(tc) * 3 + 1);
        for (size_t i = 0; i < size_t(tc) * 3; ++i) tri_edges[i] = index_for(p, ec);
        d.edges = edges.data();
        d.edge_count = ec;
        d.triangle_edges = p.ConsumeIntegralInRange<int>(0, 7) ? tri_edges.data() : nullptr;
        if (p.ConsumeBool()) {
            marks.resize(ec + 1);
            for (auto& m : marks) m = p.ConsumeIntegral<uint32_t>();
            d.edge_marks = marks.data();
        }
        if (p.ConsumeBool()) {
            bevel.resize(ec + 1);
            for (auto& b : bevel) b = any_float(p);
            d.edge_bevel_weights = bevel.data();
        }
    } else if (p.ConsumeIntegralInRange<int>(0, 7) == 0) {
        // Edge extras without host edges: must be rejected, not read.
        marks.resize(4);
        d.edge_marks = marks.data();
    }
    if (p.ConsumeBool()) {
        mats.resize(tc + 1);
        for (auto& m : mats) m = p.ConsumeIntegral<uint32_t>();
        d.triangle_materials = mats.data();
    }
    if (p.ConsumeBool()) {
        vnormals.resize(size_t(vc) * 3 + 1);
        for (auto& n : vnormals) n = p.ConsumeBool() ? any_float(p) : p.ConsumeFloatingPointInRange(-1.0f, 1.0f);
        d.vertex_normals = vnormals.data();
    }
    if (p.ConsumeBool()) {
        // Unit, zero, non-unit and non-finite face normals: the last two must be refused.
        tnormals.resize(size_t(tc) * 3 + 1);
        for (auto& n : tnormals) n = p.ConsumeBool() ? any_float(p) : p.ConsumeFloatingPointInRange(-1.0f, 1.0f);
        for (size_t t = 0; t + 2 < tnormals.size() && p.ConsumeBool(); t += 3) {
            const float l = std::sqrt(tnormals[t] * tnormals[t] + tnormals[t + 1] * tnormals[t + 1] +
                                      tnormals[t + 2] * tnormals[t + 2]);
            if (l > 0.0f && std::isfinite(l)) for (int k = 0; k < 3; ++k) tnormals[t + k] /= l;
        }
        d.triangle_normals = tnormals.data();
    }

    el_mesh* mesh = nullptr;
    if (el_mesh_create(p.ConsumeIntegralInRange<int>(0, 31) ? &d : nullptr, &mesh) != EL_OK) return;
    el_mesh_classify(mesh, any_float(p));
    el_mesh_info info{};
    if (el_mesh_get_info(mesh, &info) != EL_OK) return el_mesh_destroy(mesh);
    el_mesh_get_info(mesh, nullptr);
    getter<uint32_t>(p, info.edge_count, 2, el_mesh_get_edges, mesh);
    getter<uint32_t>(p, info.edge_count, 1, el_mesh_get_edge_flags, mesh);
    getter<uint32_t>(p, info.edge_count, 1, el_mesh_get_edge_face_counts, mesh);
    getter<float>(p, info.edge_count, 6, el_mesh_get_edge_normals, mesh);
    getter<float>(p, info.edge_count, 1, el_mesh_get_edge_angles, mesh);
    getter<float>(p, info.triangle_count, 3, el_mesh_get_face_normals, mesh);
    getter<uint8_t>(p, info.triangle_count, 1, el_mesh_get_degenerate_triangles, mesh);
    getter<uint8_t>(p, info.triangle_count, 1, el_mesh_get_triangle_flips, mesh);
    uint32_t count = 0;
    const uint32_t fcap = p.ConsumeIntegralInRange<uint32_t>(0, 8);
    std::vector<uint32_t> faces(fcap + 1);
    el_mesh_get_edge_faces(mesh, index_for(p, info.edge_count), faces.data(), fcap, &count);
    const uint32_t scap = capacity_for(p, info.edge_count);
    std::vector<uint32_t> sel(scap + 1);
    const uint32_t all_of = p.ConsumeIntegral<uint32_t>(), any_of = p.ConsumeIntegral<uint32_t>();
    el_mesh_select_edges(mesh, all_of, any_of, sel.data(), scap, &count);
    el_mesh_select_edges(mesh, all_of, any_of, nullptr, 0, &count);
    // Chains of arbitrary edge lists: repeats and out-of-range indices must be refused.
    const uint32_t n_chain = p.ConsumeIntegralInRange<uint32_t>(0, info.edge_count + 2);
    std::vector<uint32_t> chain_edges(n_chain + 1);
    for (uint32_t i = 0; i < n_chain; ++i)
        chain_edges[i] = p.ConsumeBool() ? i : index_for(p, info.edge_count);
    std::vector<el_chain_link> links(n_chain + 1);
    const uint32_t kcap = capacity_for(p, n_chain);
    std::vector<el_chain> chains(kcap + 1);
    el_mesh_chain_edges(mesh, p.ConsumeBool() ? chain_edges.data() : nullptr, n_chain, links.data(),
                        chains.data(), kcap, &count);
    fuzz_view(p, mesh, info);
    fuzz_view_lines(p, mesh, info);
    el_mesh_destroy(mesh);
}

const el_highlight_table* default_table() {
    static el_highlight_table* t = [] {
        el_table_desc d{EL_TABLE_BICUBIC, 16, 16, 10001.0f};
        el_highlight_table* out = nullptr;
        el_highlight_table_create(&d, &out);
        return out;
    }();
    return t;
}

void fill_input(FuzzedDataProvider& p, el_highlight_input& in) {
    // Mostly a sane base with a few wild fields, so that evaluation is reached often.
    in = el_highlight_input{};
    in.edge_dir[2] = 1.0f;
    in.n1[0] = 1.0f;
    in.n2[1] = 1.0f;
    in.eye[0] = 3.0f, in.eye[1] = 2.0f, in.eye[2] = 1.0f;
    in.view_dir[2] = -1.0f;
    in.light[0] = 1.0f, in.light[1] = 1.0f;
    in.shininess = 50.0f, in.radius = 0.01f, in.K = 1000.0f, in.ortho_scale = 2.0f;
    float* fields[] = {in.point, in.edge_dir, in.n1, in.n2, in.eye, in.view_dir, in.light};
    const int changes = p.ConsumeIntegralInRange<int>(0, 8);
    for (int c = 0; c < changes; ++c) {
        const int f = p.ConsumeIntegralInRange<int>(0, 10);
        if (f < 7) {
            fill3(p, fields[f]);
        } else if (f == 7) {
            in.shininess = p.ConsumeBool() ? any_float(p) : p.ConsumeFloatingPointInRange(1.0f, 10000.0f);
        } else if (f == 8) {
            in.radius = any_float(p), in.K = any_float(p);
        } else if (f == 9) {
            in.ortho_scale = any_float(p);
        } else {
            // Near-degenerate arcs: n2 a tiny rotation of +-n1.
            const float a = p.ConsumeFloatingPointInRange(-1e-3f, 1e-3f);
            const float s = p.ConsumeBool() ? 1.0f : -1.0f;
            in.n2[0] = s * std::cos(a), in.n2[1] = s * std::sin(a), in.n2[2] = 0.0f;
        }
    }
    in.projection = p.ConsumeIntegralInRange<int32_t>(-1, 2);
    in.light_is_point = p.ConsumeIntegralInRange<int32_t>(-1, 2);
}

void fuzz_highlight(FuzzedDataProvider& p) {
    el_table_desc desc{};
    desc.layout = p.ConsumeIntegralInRange<int32_t>(-1, 3);
    desc.phi_count = p.ConsumeBool() ? p.ConsumeIntegralInRange<uint32_t>(0, 64) : p.ConsumeIntegral<uint32_t>();
    desc.m_count = p.ConsumeBool() ? p.ConsumeIntegralInRange<uint32_t>(0, 64) : p.ConsumeIntegral<uint32_t>();
    desc.m_max = p.ConsumeBool() ? any_float(p) : p.ConsumeFloatingPointInRange(1.0f, 20000.0f);
    if (std::getenv("EL_FUZZ_VERBOSE"))
        std::fprintf(stderr, "table desc %d %u %u %g\n", desc.layout, desc.phi_count, desc.m_count, desc.m_max);
    // Valid tables beyond 2^16 texels only cost build time (up to the 2^29-float limit, seconds
    // to minutes); past the limit creation must fail before allocating.
    const uint64_t texels = uint64_t(desc.phi_count) * desc.m_count;
    el_highlight_table* own = nullptr;
    if (texels <= (1u << 16) || texels >= (uint64_t(1) << 29))
        el_highlight_table_create(p.ConsumeIntegralInRange<int>(0, 15) ? &desc : nullptr, &own);
    const el_highlight_table* t = own ? own : default_table();

    el_table_info info{};
    el_highlight_table_get_info(t, &info);
    el_highlight_table_get_info(nullptr, &info);
    const uint64_t floats = uint64_t(info.phi_count) * info.m_count;
    const uint64_t cap = p.ConsumeBool() ? floats : p.ConsumeIntegralInRange<uint64_t>(0, floats + 1);
    std::vector<float> data(cap + 1);
    el_highlight_table_copy(t, data.data(), cap);
    float v = 0;
    for (int k = 0; k < 4; ++k) el_highlight_table_lookup(t, any_float(p), any_float(p), &v);
    el_highlight_table_lookup(t, p.ConsumeFloatingPointInRange(-1.5707964f, 1.5707964f),
                              p.ConsumeFloatingPointInRange(1.0f, info.m_max > 1.0f ? info.m_max : 1.0f), &v);

    double out = 0;
    const double a = p.ConsumeFloatingPoint<double>(), b = p.ConsumeFloatingPointInRange(-1.6, 1.6);
    el_cos_power_integral(b, p.ConsumeBool() ? a : p.ConsumeFloatingPointInRange(0.0, 1e9), &out);
    el_cos_power_sin_integral(b, p.ConsumeFloatingPointInRange(-1.6, 1.6),
                              p.ConsumeBool() ? a : p.ConsumeFloatingPointInRange(0.0, 1e6), &out);
    float w = 0;
    el_highlight_weight(any_float(p), any_float(p), any_float(p), any_float(p), &w);

    const uint32_t count = p.ConsumeIntegralInRange<uint32_t>(0, 3);
    std::vector<el_highlight_input> in(count + 1);
    for (auto& x : in) fill_input(p, x);
    std::vector<el_highlight_result> res(count + 1);
    el_highlight_eval(t, in.data(), res.data());
    el_highlight_eval_batch(t, in.data(), count, res.data());
    el_highlight_reference(in.data(), res.data());
    el_highlight_eval(t, nullptr, res.data());
    el_highlight_eval(nullptr, in.data(), res.data());
    el_highlight_reference(in.data(), nullptr);
    el_highlight_table_destroy(own);
}


// Silhouettes on the rounded outline: records and segments over a few vertices (so that keys
// meet and corners join), box-like or any float, any camera, exact or short capacities.
void fuzz_outline(FuzzedDataProvider& p) {
    const bool wild = p.ConsumeIntegralInRange<int>(0, 3) == 0;
    auto value = [&] { return wild ? any_float(p) : float(p.ConsumeIntegralInRange<int>(-2, 2)) * 0.5f; };
    const uint32_t ec = p.ConsumeIntegralInRange<uint32_t>(0, 12), cc = p.ConsumeIntegralInRange<uint32_t>(0, 4);
    std::vector<float> edges(size_t(ec) * 4 * EL_OUTLINE_EDGE_TEXELS + 1), corners(size_t(cc) * 4 * EL_OUTLINE_CORNER_TEXELS + 1);
    for (auto& x : edges) x = value();
    for (auto& x : corners) x = value();
    std::vector<uint32_t> ev(2 * size_t(ec) + 1), cv(cc + 1);
    for (auto& x : ev) x = p.ConsumeIntegralInRange<uint32_t>(0, 7);
    for (auto& x : cv) x = p.ConsumeIntegralInRange<uint32_t>(0, 7);
    el_outline_desc desc{edges.data(), ev.data(), ec, corners.data(), cv.data(), cc};
    if (p.ConsumeIntegralInRange<int>(0, 7) == 0) desc.edges = nullptr;
    if (p.ConsumeIntegralInRange<int>(0, 7) == 0) desc.corner_vertices = nullptr;
    el_outline* outline = nullptr;
    el_outline_create(p.ConsumeIntegralInRange<int>(0, 15) ? &desc : nullptr, &outline);
    el_outline_view view{};
    view.projection = p.ConsumeIntegralInRange<int32_t>(-1, 2);
    fill3(p, view.eye);
    fill3(p, view.view_dir);
    for (float* m : {view.object_to_world, view.world_to_view, view.view_to_clip}) {
        const bool identity = p.ConsumeBool();
        for (int i = 0; i < 16; ++i) m[i] = identity ? (i % 5 == 0 ? 1.0f : 0.0f) : any_float(p);
    }
    view.width = p.ConsumeBool() ? 320.0f : any_float(p);
    view.height = p.ConsumeBool() ? 240.0f : any_float(p);
    const uint32_t n = p.ConsumeIntegralInRange<uint32_t>(0, 12);
    std::vector<uint32_t> verts(2 * size_t(n) + 1);
    for (auto& x : verts) x = p.ConsumeIntegralInRange<uint32_t>(0, 7);
    std::vector<float> p0(3 * size_t(n) + 1), p1(3 * size_t(n) + 1), n1(3 * size_t(n) + 1), n2(3 * size_t(n) + 1);
    std::vector<float> taper(2 * size_t(n) + 1), faces(2 * size_t(n) + 1);
    for (auto* a : {&p0, &p1, &n1, &n2, &taper, &faces})
        for (auto& x : *a) x = value();
    std::vector<el_chain_link> links(n + 1);
    for (auto& l : links) l = el_chain_link{p.ConsumeIntegralInRange<uint32_t>(0, 3), value(), value()};
    el_outline_segments in{verts.data(), p0.data(), p1.data(), n1.data(), n2.data(), taper.data(),
                           p.ConsumeBool() ? faces.data() : nullptr, p.ConsumeBool() ? links.data() : nullptr, n};
    const uint32_t full = (2 + EL_OUTLINE_ARC_MAX_PIECES) * n;
    const uint32_t cap = p.ConsumeBool() ? full : p.ConsumeIntegralInRange<uint32_t>(0, full);
    std::vector<float> o3(4 * (3 * size_t(cap) + 1)), o2(2 * (2 * size_t(cap) + 1));
    std::vector<el_chain_link> olinks(cap + 1);
    el_outline_out out{&o3[0], &o3[3 * size_t(cap) + 1], &o3[2 * (3 * size_t(cap) + 1)], &o3[3 * (3 * size_t(cap) + 1)],
                       &o2[0], p.ConsumeIntegralInRange<int>(0, 7) ? &o2[2 * size_t(cap) + 1] : nullptr,
                       p.ConsumeIntegralInRange<int>(0, 7) ? olinks.data() : nullptr, cap};
    uint32_t count = 0;
    el_outline_lines(outline, p.ConsumeIntegralInRange<int>(0, 15) ? &view : nullptr, &in, &out, &count);
    el_outline_lines(outline, &view, &in, &out, nullptr);
    std::vector<uint8_t> sil(n + 1);
    std::vector<float> c(3 * size_t(n) + 1);
    el_fillet_outline(n1.data(), n2.data(), p0.data(), n, p1.data(), c.data(), sil.data());
    // The wide faces' lists: segments' vertex pairs as triangles, the records' vertices as items.
    const uint32_t per = p.ConsumeIntegralInRange<uint32_t>(0, 9);
    const uint32_t tris = n * 2 / 3;
    std::vector<float> lists(size_t(tris) * per + 1);
    std::vector<int32_t> items(3 * size_t(ec) + 1);  // up to 3 vertices an item
    for (auto& x : items) x = p.ConsumeIntegralInRange<int32_t>(p.ConsumeIntegralInRange<int>(0, 7) ? -1 : -3, 9);
    el_outline_fans(verts.data(), n1.data(), tris, items.data(), p.ConsumeIntegralInRange<uint32_t>(0, 3), edges.data(),
                    p.ConsumeIntegralInRange<uint32_t>(0, 3), ec, p.ConsumeIntegralInRange<uint32_t>(0, 2), value(), per,
                    lists.data());
    // The shading normals of rounded edges: the records' vertex pairs as edges over 8 vertices,
    // faces among the triangles above (or out of range), any selection.
    std::vector<float> pos(24), cn(9 * size_t(tris) + 1);
    for (auto& x : pos) x = value();
    for (auto& x : cn) x = value();
    std::vector<int32_t> ef(2 * size_t(ec) + 1);
    for (auto& x : ef) x = p.ConsumeIntegralInRange<int32_t>(-2, int32_t(tris));
    std::vector<uint32_t> sel(ec + 1);
    for (auto& x : sel) x = p.ConsumeIntegralInRange<uint32_t>(0, ec);
    std::vector<float> normals_out(12 * size_t(ec) + 1);
    el_shading_normals(pos.data(), 8, ev.data(), edges.data(), ef.data(), ec, verts.data(), cn.data(), tris, sel.data(),
                       p.ConsumeIntegralInRange<uint32_t>(0, ec), p.ConsumeBool() ? 20.0f : any_float(p),
                       normals_out.data());
    // Corner patches over the same edges: any flags, radii, exact or short capacities.
    std::vector<uint8_t> convex(ec + 1), chosen(ec + 1), stops(ec + 1);
    for (auto* a : {&convex, &chosen, &stops})
        for (auto& x : *a) x = uint8_t(p.ConsumeIntegralInRange<int>(0, 2));
    std::vector<float> radii(ec + 1);
    for (auto& x : radii) x = value();
    const uint32_t ccap = p.ConsumeIntegralInRange<uint32_t>(0, 8);
    std::vector<uint32_t> cvert(ccap + 1), cedges(3 * size_t(ccap) + 1);
    std::vector<float> cnorm(9 * size_t(ccap) + 1), crad(ccap + 1), ccen(3 * size_t(ccap) + 1), cfold(ccap + 1);
    uint32_t corners_found = 0;
    el_corner_patches(pos.data(), 8, ev.data(), edges.data(), convex.data(), chosen.data(), radii.data(),
                      p.ConsumeBool() ? stops.data() : nullptr, ec, ccap, cvert.data(), cedges.data(), cnorm.data(),
                      crad.data(), ccen.data(), cfold.data(), &corners_found);
    // Band ends: the triangles above as polygons of three loops, their loops' edges among the
    // records' (or out of range), with and without the smooth patches' fans.
    std::vector<uint32_t> pstart(tris + 1), ptotal(tris + 1, 3), ledge(3 * size_t(tris) + 1), tpoly(tris + 1);
    for (uint32_t k = 0; k < tris; ++k) pstart[k] = 3 * k, tpoly[k] = p.ConsumeIntegralInRange<uint32_t>(0, tris);
    for (auto& x : ledge) x = p.ConsumeIntegralInRange<uint32_t>(0, ec);
    std::vector<float> pnorm(3 * size_t(tris) + 1);
    for (auto& x : pnorm) x = value();
    if (tris && p.ConsumeBool()) ptotal[0] = p.ConsumeIntegralInRange<uint32_t>(0, 5);
    const el_polygons polys{pstart.data(), ptotal.data(), tris, verts.data(), ledge.data(), 3 * tris,
                            tpoly.data(), tris, pnorm.data()};
    std::vector<int32_t> epolys(2 * size_t(ec) + 1);
    for (auto& x : epolys) x = p.ConsumeIntegralInRange<int32_t>(-2, int32_t(tris));
    std::vector<float> angles(4 * size_t(ec) + 1);
    const bool fans = p.ConsumeBool();
    el_band_ends(p.ConsumeIntegralInRange<int>(0, 15) ? &polys : nullptr, pos.data(), 8, ev.data(), edges.data(),
                 chosen.data(), fans ? stops.data() : nullptr, fans ? epolys.data() : nullptr, ec, sel.data(),
                 ef.data(), p.ConsumeIntegralInRange<uint32_t>(0, ec), angles.data());
    // The rounding rule over the same edges: any flags, angles, faces, slots and rules.
    std::vector<uint32_t> eflags(ec + 1), tslot(tris + 1);
    for (auto& x : eflags) x = p.ConsumeIntegral<uint32_t>() & 0x3ffu;
    for (auto& x : tslot) x = p.ConsumeIntegralInRange<uint32_t>(0, 3);
    std::vector<float> eangles(ec + 1), ebevel(ec + 1);
    for (auto* a : {&eangles, &ebevel})
        for (auto& x : *a) x = value();
    el_slot_rules srules[3];
    for (auto& r : srules) r = el_slot_rules{p.ConsumeIntegralInRange<uint32_t>(0, 1), value(), value(),
                                             p.ConsumeIntegralInRange<uint32_t>(0, 7), value()};
    std::vector<uint8_t> rchosen(ec + 1), rpa(ec + 1), rpb(ec + 1);
    std::vector<float> rradius(ec + 1), rra(ec + 1), rrb(ec + 1);
    std::vector<uint32_t> rsa(ec + 1), rsb(ec + 1);
    el_edge_rules(eflags.data(), eangles.data(), ef.data(), ef.data() + ec, stops.data(), ebevel.data(), ec,
                  tslot.data(), tris, srules, p.ConsumeIntegralInRange<uint32_t>(0, 3), rchosen.data(), rradius.data(),
                  p.ConsumeBool() ? rsa.data() : nullptr, rsb.data(), rpa.data(), rpb.data(), rra.data(), rrb.data());
    std::vector<double> widths(2 * size_t(ec) + 1);
    el_width_bounds(p.ConsumeIntegralInRange<int>(0, 15) ? &polys : nullptr, pos.data(), 8, ev.data(), epolys.data(),
                    p.ConsumeIntegralInRange<uint32_t>(0, ec), widths.data());
    el_outline_destroy(outline);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider p(data, size);
    el_abi_version();
    el_status_name(el_status(p.ConsumeIntegralInRange<int>(0, 15)));  // any value an enum of 0..9 may hold
    switch (p.ConsumeIntegralInRange<int>(0, 2)) {
    case 0: fuzz_mesh(p); break;
    case 1: fuzz_highlight(p); break;
    default: fuzz_outline(p); break;
    }
    el_last_error();
    el_mesh_destroy(nullptr);
    el_view_destroy(nullptr);
    el_outline_destroy(nullptr);
    el_view_lines_destroy(nullptr);
    el_highlight_table_destroy(nullptr);
    return 0;
}
