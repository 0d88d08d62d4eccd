// C entry points for per-view results.
#include "capi_common.hpp"
#include "handles.hpp"
#include "silhouette.hpp"

#include <algorithm>
#include <cstring>
#include <string>

using el::guarded;
using el::require;
using el::require_capacity;

extern "C" {

EL_API el_status el_view_create(const el_mesh* mesh, el_view** out_view) {
    if (out_view) *out_view = nullptr;
    return guarded("el_view_create", [&] {
        require(mesh, "mesh");
        require(out_view, "out_view");
        auto v = std::make_unique<el_view>();
        v->cache.mesh = mesh->data;
        *out_view = v.release();
    });
}

EL_API void el_view_destroy(el_view* view) { delete view; }

EL_API el_status el_view_update(el_view* view, const el_camera* camera, uint32_t what, uint32_t* out_changed) {
    return guarded("el_view_update", [&] {
        require(view, "view");
        require(camera, "camera");
        if (what & ~(EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS))
            el::fail(EL_ERR_INVALID_ARGUMENT, "what has unknown bits " + std::to_string(what));
        const bool changed = view->cache.update(el::object_view_point(*camera), what);
        if (out_changed) *out_changed = changed ? 1u : 0u;
    });
}

EL_API el_status el_view_get_silhouettes(const el_view* view, uint32_t* out, uint32_t capacity, uint32_t* out_count) {
    return guarded("el_view_get_silhouettes", [&] {
        require(view, "view");
        require(out_count, "out_count");
        const auto& s = view->cache.silhouettes;
        *out_count = uint32_t(s.size());
        if (!out) return;  // count only
        require_capacity(capacity, s.size(), "capacity");
        std::copy(s.begin(), s.end(), out);
    });
}

EL_API el_status el_view_get_facing(const el_view* view, uint8_t* out, uint32_t capacity) {
    return guarded("el_view_get_facing", [&] {
        require(view, "view");
        require(out, "out");
        const el::ViewCache& c = view->cache;
        if (!(c.valid && (c.what & EL_VIEW_SILHOUETTES)))
            el::fail(EL_ERR_INVALID_ARGUMENT, "no facing yet: call el_view_update with EL_VIEW_SILHOUETTES");
        const uint32_t n = c.mesh->triangle_count();
        require_capacity(capacity, n, "capacity_triangles");
        std::copy(c.facing.begin(), c.facing.begin() + n, out);
    });
}

EL_API el_status el_view_get_contours(const el_view* view, float* out_points, uint32_t* out_triangles,
                                      uint32_t capacity, uint32_t* out_count) {
    return guarded("el_view_get_contours", [&] {
        require(view, "view");
        require(out_count, "out_count");
        const el::ViewCache& c = view->cache;
        const size_t n = c.contour_triangles.size();
        *out_count = uint32_t(n);
        if (!out_points && !out_triangles) return;  // count only
        require_capacity(capacity, n, "capacity_segments");
        if (out_points && n) std::memcpy(out_points, c.contour_points.data(), n * 6 * sizeof(float));
        if (out_triangles) std::copy(c.contour_triangles.begin(), c.contour_triangles.end(), out_triangles);
    });
}

EL_API el_status el_view_get_stats(const el_view* view, el_view_stats* out) {
    return guarded("el_view_get_stats", [&] {
        require(view, "view");
        require(out, "out_stats");
        *out = view->cache.stats;
    });
}

}  // extern "C"
