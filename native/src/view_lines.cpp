#include "view_lines.hpp"

#include "capi_common.hpp"
#include "chains.hpp"
#include "error.hpp"
#include "view_cache.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <thread>

namespace el {

namespace {

// Instances a thread takes at least; a call of up to this many runs on the caller's thread.
constexpr uint32_t kInstancesPerTask = 64;

Mat4 matrix(const float* m, const char* name) {
    el::require_finite_array(m, 16, name);
    Mat4 r{};
    std::copy(m, m + 16, r.m);
    return r;
}

OutlineSegments instance_lines(const MeshData& mesh, const OutlineRecords* outline, const float* edge_faces,
                               const el_outline_view& v, bool taper, ViewCache& cache) {
    el_camera cam{};
    cam.projection = v.projection;
    std::copy(v.eye, v.eye + 3, cam.eye);
    std::copy(v.view_dir, v.view_dir + 3, cam.view_dir);
    std::copy(v.object_to_world, v.object_to_world + 16, cam.object_to_world);
    cache.update(object_view_point(cam), EL_VIEW_SILHOUETTES);
    const std::vector<uint32_t>& sil = cache.silhouettes;
    const size_t n = sil.size();
    OutlineSegments seg;
    seg.has_faces = edge_faces != nullptr;
    seg.has_links = true;
    std::vector<ChainItem> items(n);
    std::vector<uint32_t> verts(2 * n);
    seg.p0.resize(3 * n);
    seg.p1.resize(3 * n);
    seg.n1.resize(3 * n);
    seg.n2.resize(3 * n);
    if (seg.has_faces) seg.faces.resize(2 * n);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t e = sil[i];
        const uint32_t a = mesh.topo.edge_vertices[2 * size_t(e)], b = mesh.topo.edge_vertices[2 * size_t(e) + 1];
        verts[2 * i] = a;
        verts[2 * i + 1] = b;
        items[i] = ChainItem{{a, b}, {mesh.positions[a], mesh.positions[b]}};
        for (int k = 0; k < 3; ++k) {
            seg.p0[3 * i + size_t(k)] = mesh.positions[a][k];
            seg.p1[3 * i + size_t(k)] = mesh.positions[b][k];
            seg.n1[3 * i + size_t(k)] = mesh.cls.n1[e][k];
            seg.n2[3 * i + size_t(k)] = mesh.cls.n2[e][k];
        }
        if (seg.has_faces) {
            seg.faces[2 * i] = edge_faces[2 * size_t(e)];
            seg.faces[2 * i + 1] = edge_faces[2 * size_t(e) + 1];
        }
    }
    Chains chains = build_chains(items);
    seg.links = std::move(chains.links);
    seg.taper = taper ? taper_values(seg.links, chains.chains) : std::vector<float>(2 * n, EL_NO_TAPER);
    if (outline && !outline->edge_keys.empty() && n) return outline_lines(*outline, outline_camera(v), verts.data(), std::move(seg));
    return seg;
}

}  // namespace

OutlineCamera outline_camera(const el_outline_view& v) {
    OutlineCamera c;
    if (v.projection != EL_PERSPECTIVE && v.projection != EL_ORTHOGRAPHIC)
        fail(EL_ERR_INVALID_ARGUMENT, "view projection " + std::to_string(v.projection) + " is no el_projection");
    c.orthographic = v.projection == EL_ORTHOGRAPHIC;
    el::require_finite_array(v.eye, 3, "view eye");
    el::require_finite_array(v.view_dir, 3, "view view_dir");
    c.eye = glm::dvec3(v.eye[0], v.eye[1], v.eye[2]);
    c.view_dir = glm::dvec3(v.view_dir[0], v.view_dir[1], v.view_dir[2]);
    if (c.orthographic && !(glm::length(c.view_dir) > 0.0))
        fail(EL_ERR_INVALID_ARGUMENT, "view view_dir is zero in an orthographic view");
    c.object_to_world = matrix(v.object_to_world, "view object_to_world");
    c.world_to_view = matrix(v.world_to_view, "view world_to_view");
    c.view_to_clip = matrix(v.view_to_clip, "view view_to_clip");
    if (!(std::isfinite(v.width) && std::isfinite(v.height) && v.width > 0.0f && v.height > 0.0f))
        fail(EL_ERR_INVALID_ARGUMENT, "view width and height must be positive and finite");
    c.width = v.width;
    c.height = v.height;
    return c;
}

std::vector<float> taper_values(const std::vector<el_chain_link>& links, const std::vector<el_chain>& chains) {
    std::vector<float> out(2 * links.size(), EL_NO_TAPER);
    for (size_t i = 0; i < links.size(); ++i) {
        const el_chain& c = chains[links[i].chain];
        const double length = std::max(double(c.length), 1e-30);
        for (int k = 0; k < 2; ++k) {
            const double s = k == 0 ? links[i].s0 : links[i].s1;
            double d = std::numeric_limits<double>::infinity();
            if (c.flags & EL_CHAIN_START_FREE) d = std::min(d, s);
            if (c.flags & EL_CHAIN_END_FREE) d = std::min(d, double(c.length) - s);
            if (std::isfinite(d)) out[2 * i + size_t(k)] = float(std::max(d, 0.0) / length);
        }
    }
    return out;
}

ViewLines view_lines(const MeshData& mesh, const OutlineRecords* outline, const float* edge_faces,
                     const el_outline_view* views, uint32_t view_count, uint32_t flags) {
    ViewLines out;
    out.instances.resize(view_count);
    out.status.assign(view_count, EL_OK);
    out.message.assign(view_count, std::string());
    const bool taper = (flags & EL_VIEW_LINES_TAPER) != 0;
    auto run = [&](uint32_t begin, uint32_t end) {
        ViewCache cache;  // scratch for the facing pass, one per thread
        cache.mesh = std::shared_ptr<const MeshData>(&mesh, [](const MeshData*) {});
        for (uint32_t i = begin; i < end; ++i) {
            try {
                out.instances[i] = instance_lines(mesh, outline, edge_faces, views[i], taper, cache);
            } catch (const Error& e) {
                out.status[i] = e.status();  // this instance has none; the others go on
                out.message[i] = e.what();
            }
        }
    };
    const uint32_t tasks = (view_count + kInstancesPerTask - 1) / kInstancesPerTask;
    const uint32_t threads = std::min<uint32_t>(std::max(1u, std::thread::hardware_concurrency()), tasks);
    if (threads <= 1) {
        run(0, view_count);
        return out;
    }
    std::vector<std::thread> pool;
    pool.reserve(threads);
    std::vector<std::exception_ptr> failed(threads);
    const uint32_t per = (view_count + threads - 1) / threads;
    auto task = [&](uint32_t t) {
        try {
            run(std::min(view_count, t * per), std::min(view_count, (t + 1) * per));
        } catch (...) {
            failed[t] = std::current_exception();  // out of memory, say: the call fails
        }
    };
    uint32_t started = 0;
    try {
        for (; started < threads; ++started) pool.emplace_back(task, started);
    } catch (...) {
        // No more threads to be had: the caller's thread takes the ranges not started.
    }
    for (uint32_t t = started; t < threads; ++t) task(t);
    for (auto& th : pool) th.join();
    for (auto& f : failed)
        if (f) std::rethrow_exception(f);
    return out;
}

}  // namespace el
