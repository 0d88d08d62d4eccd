// C entry points for what the edge pass shades rounded edges with (shading_normals.hpp).
#include "capi_common.hpp"
#include "shading_normals.hpp"

#include <string>

using el::guarded;
using el::require;

namespace {

void require_finite_array(const float* a, size_t count, const char* name) {
    for (size_t i = 0; i < count; ++i)
        if (!std::isfinite(a[i])) el::fail(EL_ERR_NON_FINITE, std::string(name) + "[" + std::to_string(i) + "] is not finite");
}

void require_below(const uint32_t* a, size_t count, uint32_t limit, const char* name, const char* what) {
    for (size_t i = 0; i < count; ++i)
        if (a[i] >= limit)
            el::fail(EL_ERR_INDEX_OUT_OF_RANGE, std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(a[i]) +
                                                    " is not below the " + what + " " + std::to_string(limit));
}

}  // namespace

extern "C" {

EL_API el_status el_shading_normals(const float* positions, uint32_t vertex_count, const uint32_t* edges,
                                    const float* edge_normals, const int32_t* edge_faces, uint32_t edge_count,
                                    const uint32_t* tri_verts, const float* corner_normals, uint32_t triangle_count,
                                    const uint32_t* selected, uint32_t count, float max_turn_deg, float* out) {
    return guarded("el_shading_normals", [&] {
        el::require_finite(max_turn_deg, "max_turn_deg");
        if (count == 0) return;
        for (auto [p, name] : {std::pair<const void*, const char*>{positions, "positions"}, {edges, "edges"}, {edge_normals, "edge_normals"}, {edge_faces, "edge_faces"}, {tri_verts, "tri_verts"}, {corner_normals, "corner_normals"}, {selected, "selected"}, {out, "out"}})
            require(p, name);
        require_below(selected, count, edge_count, "selected", "edge count");
        require_below(edges, 2 * size_t(edge_count), vertex_count, "edges", "vertex count");
        for (size_t i = 0; i < 2 * size_t(edge_count); ++i)
            if (edge_faces[i] < -1 || (edge_faces[i] >= 0 && uint32_t(edge_faces[i]) >= triangle_count))
                el::fail(EL_ERR_INDEX_OUT_OF_RANGE, "edge_faces[" + std::to_string(i) + "] = " +
                                                        std::to_string(edge_faces[i]) + " is no triangle (nor -1)");
        require_finite_array(positions, 3 * size_t(vertex_count), "positions");
        require_finite_array(edge_normals, 6 * size_t(edge_count), "edge_normals");
        require_finite_array(corner_normals, 9 * size_t(triangle_count), "corner_normals");
        el::shading_normals(el::ShadingInputs{positions, edges, edge_normals, edge_faces, tri_verts, corner_normals},
                            selected, count, max_turn_deg, out);
    });
}

}  // extern "C"
