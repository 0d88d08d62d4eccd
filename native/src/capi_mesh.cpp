// C entry points for meshes: argument checks, then the internals.
#include "capi_common.hpp"
#include "classify.hpp"
#include "handles.hpp"
#include "mesh_build.hpp"

#include <algorithm>
#include <cstring>
#include <string>

using el::guarded;
using el::require;
using el::require_capacity;

namespace {

template <class T, class Getter>
el_status copy_per_edge(const char* fn, const el_mesh* mesh, T* out, uint32_t capacity, int per_edge, Getter get) {
    return guarded(fn, [&] {
        require(mesh, "mesh");
        require(out, "out");
        const uint32_t n = mesh->data->edge_count();
        require_capacity(capacity, n, "capacity_edges");
        for (uint32_t e = 0; e < n; ++e) get(e, out + size_t(e) * per_edge);
    });
}

}  // namespace

extern "C" {

EL_API el_status el_mesh_create(const el_mesh_desc* desc, el_mesh** out_mesh) {
    if (out_mesh) *out_mesh = nullptr;
    return guarded("el_mesh_create", [&] {
        require(desc, "desc");
        require(out_mesh, "out_mesh");
        auto handle = std::make_unique<el_mesh>();
        handle->data = el::build_mesh(*desc);
        *out_mesh = handle.release();
    });
}

EL_API void el_mesh_destroy(el_mesh* mesh) { delete mesh; }

EL_API el_status el_mesh_classify(el_mesh* mesh, float crease_angle_deg) {
    return guarded("el_mesh_classify", [&] {
        require(mesh, "mesh");
        el::require_finite(crease_angle_deg, "crease_angle_deg");
        if (crease_angle_deg < 0.0f || crease_angle_deg > 180.0f)
            el::fail(EL_ERR_INVALID_ARGUMENT,
                     "crease_angle_deg " + std::to_string(crease_angle_deg) + " is outside [0, 180]");
        el::apply_crease_threshold(mesh->data->cls, crease_angle_deg);
    });
}

EL_API el_status el_mesh_get_info(const el_mesh* mesh, el_mesh_info* out) {
    return guarded("el_mesh_get_info", [&] {
        require(mesh, "mesh");
        require(out, "out_info");
        const el::MeshData& m = *mesh->data;
        el_mesh_info info{};
        info.vertex_count = m.vertex_count();
        info.triangle_count = m.triangle_count();
        info.edge_count = m.edge_count();
        for (uint32_t f : m.cls.edge_flags) {
            info.loose_edges += (f & EL_EDGE_LOOSE) != 0;
            info.border_edges += (f & EL_EDGE_BORDER) != 0;
            info.manifold_edges += (f & EL_EDGE_MANIFOLD) != 0;
            info.non_manifold_edges += (f & EL_EDGE_NON_MANIFOLD) != 0;
            info.crease_edges += (f & EL_EDGE_CREASE) != 0;
            info.convex_edges += (f & EL_EDGE_CONVEX) != 0;
            info.concave_edges += (f & EL_EDGE_CONCAVE) != 0;
            info.marked_edges += (f & EL_MARK_ALL) != 0;
            info.material_boundary_edges += (f & EL_EDGE_MATERIAL_BOUNDARY) != 0;
            info.degenerate_edges += (f & EL_EDGE_DEGENERATE) != 0;
        }
        info.flipped_winding_edges = m.orient.input_flipped_edges;
        info.reoriented_triangles = m.orient.reoriented_triangles;
        for (uint8_t d : m.geom.face_degenerate) info.degenerate_triangles += d;
        info.host_edges = m.topo.host_edges ? 1u : 0u;
        info.crease_angle_deg = m.cls.crease_angle_deg;
        *out = info;
    });
}

EL_API el_status el_mesh_get_edges(const el_mesh* mesh, uint32_t* out, uint32_t capacity) {
    return copy_per_edge("el_mesh_get_edges", mesh, out, capacity, 2, [&](uint32_t e, uint32_t* o) {
        o[0] = mesh->data->topo.edge_vertices[2 * e];
        o[1] = mesh->data->topo.edge_vertices[2 * e + 1];
    });
}

EL_API el_status el_mesh_get_edge_flags(const el_mesh* mesh, uint32_t* out, uint32_t capacity) {
    return copy_per_edge("el_mesh_get_edge_flags", mesh, out, capacity, 1,
                         [&](uint32_t e, uint32_t* o) { *o = mesh->data->cls.edge_flags[e]; });
}

EL_API el_status el_mesh_get_edge_face_counts(const el_mesh* mesh, uint32_t* out, uint32_t capacity) {
    return copy_per_edge("el_mesh_get_edge_face_counts", mesh, out, capacity, 1,
                         [&](uint32_t e, uint32_t* o) { *o = mesh->data->topo.face_count(e); });
}

EL_API el_status el_mesh_get_edge_normals(const el_mesh* mesh, float* out, uint32_t capacity) {
    return copy_per_edge("el_mesh_get_edge_normals", mesh, out, capacity, 6, [&](uint32_t e, float* o) {
        std::memcpy(o, &mesh->data->cls.n1[e], 3 * sizeof(float));
        std::memcpy(o + 3, &mesh->data->cls.n2[e], 3 * sizeof(float));
    });
}

EL_API el_status el_mesh_get_edge_angles(const el_mesh* mesh, float* out, uint32_t capacity) {
    return copy_per_edge("el_mesh_get_edge_angles", mesh, out, capacity, 1,
                         [&](uint32_t e, float* o) { *o = mesh->data->cls.angle_deg[e]; });
}

EL_API el_status el_mesh_get_face_normals(const el_mesh* mesh, float* out, uint32_t capacity) {
    return guarded("el_mesh_get_face_normals", [&] {
        require(mesh, "mesh");
        require(out, "out");
        const auto& n = mesh->data->geom.face_normals;
        require_capacity(capacity, n.size(), "capacity_triangles");
        if (!n.empty()) std::memcpy(out, n.data(), n.size() * sizeof(n[0]));
    });
}

EL_API el_status el_mesh_get_degenerate_triangles(const el_mesh* mesh, uint8_t* out, uint32_t capacity) {
    return guarded("el_mesh_get_degenerate_triangles", [&] {
        require(mesh, "mesh");
        require(out, "out");
        const auto& d = mesh->data->geom.face_degenerate;
        require_capacity(capacity, d.size(), "capacity_triangles");
        std::copy(d.begin(), d.end(), out);
    });
}

EL_API el_status el_mesh_get_triangle_flips(const el_mesh* mesh, uint8_t* out, uint32_t capacity) {
    return guarded("el_mesh_get_triangle_flips", [&] {
        require(mesh, "mesh");
        require(out, "out");
        const auto& f = mesh->data->orient.flips;
        require_capacity(capacity, f.size(), "capacity_triangles");
        std::copy(f.begin(), f.end(), out);
    });
}

EL_API el_status el_mesh_get_edge_faces(const el_mesh* mesh, uint32_t edge, uint32_t* out, uint32_t capacity,
                                        uint32_t* out_count) {
    return guarded("el_mesh_get_edge_faces", [&] {
        require(mesh, "mesh");
        require(out_count, "out_count");
        const el::Topology& t = mesh->data->topo;
        if (edge >= t.edge_count())
            el::fail(EL_ERR_INDEX_OUT_OF_RANGE, "edge " + std::to_string(edge) + " but there are " +
                                                    std::to_string(t.edge_count()) + " edges");
        const uint32_t n = t.face_count(edge);
        *out_count = n;
        if (capacity > 0) require(out, "out");
        const uint32_t* faces = t.edge_faces.data() + t.edge_face_offsets[edge];
        std::copy(faces, faces + std::min(n, capacity), out);
    });
}

EL_API el_status el_mesh_select_edges(const el_mesh* mesh, uint32_t all_of, uint32_t any_of, uint32_t* out,
                                      uint32_t capacity, uint32_t* out_count) {
    return guarded("el_mesh_select_edges", [&] {
        require(mesh, "mesh");
        require(out_count, "out_count");
        const auto& flags = mesh->data->cls.edge_flags;
        uint32_t n = 0;
        for (uint32_t e = 0; e < flags.size(); ++e) {
            const uint32_t f = flags[e];
            if ((f & all_of) != all_of || (any_of && !(f & any_of))) continue;
            if (out) {
                if (n >= capacity) require_capacity(capacity, n + 1, "capacity");
                out[n] = e;
            }
            ++n;
        }
        *out_count = n;
    });
}

}  // extern "C"
