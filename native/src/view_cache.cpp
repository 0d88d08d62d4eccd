#include "view_cache.hpp"

#include "contour.hpp"
#include "error.hpp"
#include "silhouette.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <string>

namespace el {

ViewPoint object_view_point(const el_camera& cam) {
    if (cam.projection != EL_PERSPECTIVE && cam.projection != EL_ORTHOGRAPHIC)
        fail(EL_ERR_INVALID_ARGUMENT, "camera projection " + std::to_string(cam.projection) +
                                          " is neither EL_PERSPECTIVE nor EL_ORTHOGRAPHIC");
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(cam.object_to_world[i])) fail(EL_ERR_NON_FINITE, "object_to_world is not finite");
    const float* v = cam.projection == EL_PERSPECTIVE ? cam.eye : cam.view_dir;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            fail(EL_ERR_NON_FINITE, cam.projection == EL_PERSPECTIVE ? "eye is not finite" : "view_dir is not finite");

    // Row-major with column vectors is glm's column-major storage transposed.
    const glm::dmat4 m = glm::transpose(glm::dmat4(glm::make_mat4(cam.object_to_world)));
    const double det = glm::determinant(glm::dmat3(m));
    const glm::dmat3 a(m);
    const double scale = glm::length(a[0]) * glm::length(a[1]) * glm::length(a[2]);
    if (!(std::abs(det) > 1e-12 * scale) || m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        fail(EL_ERR_INVALID_ARGUMENT, "object_to_world is not an invertible affine transform");
    const glm::dmat4 inv = glm::inverse(m);

    ViewPoint vp;
    if (cam.projection == EL_PERSPECTIVE) {
        vp.eye = glm::vec3(inv * glm::dvec4(v[0], v[1], v[2], 1.0));
    } else {
        const glm::dvec3 d(inv * glm::dvec4(v[0], v[1], v[2], 0.0));
        const double len = glm::length(d);
        if (!(len > 0.0)) fail(EL_ERR_INVALID_ARGUMENT, "view_dir is zero");
        vp.orthographic = true;
        vp.to_viewer = glm::vec3(-d / len);
    }
    return vp;
}

bool ViewCache::update(const ViewPoint& vp, uint32_t new_what) {
    ++stats.updates;
    if (valid && vp == view && new_what == what) {
        ++stats.cache_hits;
        return false;
    }
    bool changed = false;
    if (new_what & EL_VIEW_SILHOUETTES) {
        compute_facing(*mesh, vp, scratch);
        ++stats.facing_passes;
        const bool had = valid && (what & EL_VIEW_SILHOUETTES);
        const uint64_t flips = had ? count_flips(facing, scratch) : uint64_t(mesh->triangle_count());
        stats.faces_flipped += flips;
        facing.swap(scratch);
        if (!had || flips > 0) {
            collect_silhouettes(*mesh, facing, silhouettes);
            ++stats.silhouette_rebuilds;
            changed = true;
        }
    } else if (!silhouettes.empty() || !facing.empty()) {
        silhouettes.clear();
        facing.clear();
        changed = true;
    }
    if (new_what & EL_VIEW_CONTOURS) {
        const bool had = valid && (what & EL_VIEW_CONTOURS);
        if (!had || !(vp == view)) {
            compute_contours(*mesh, vp, contour_points, contour_triangles, contour_keys);
            ++stats.contour_passes;
            changed = true;
        }
    } else if (!contour_triangles.empty()) {
        contour_points.clear();
        contour_triangles.clear();
        contour_keys.clear();
        changed = true;
    }
    view = vp;
    what = new_what;
    valid = true;
    stats.silhouette_edges = uint32_t(silhouettes.size());
    stats.contour_segments = uint32_t(contour_triangles.size());
    return changed;
}

}  // namespace el
