#include "mesh_build.hpp"

#include "classify.hpp"
#include "face_normals.hpp"
#include "mesh_validate.hpp"
#include "orient.hpp"
#include "topology.hpp"
#include "vertex_normals.hpp"

#include <glm/geometric.hpp>

namespace el {

std::shared_ptr<MeshData> build_mesh(const el_mesh_desc& d) {
    validate_mesh_desc(d);
    auto m = std::make_shared<MeshData>();
    const auto* p = reinterpret_cast<const glm::vec3*>(d.positions);
    m->positions.assign(p, p + d.vertex_count);
    if (d.triangle_count > 0) m->triangles.assign(d.triangles, d.triangles + size_t(d.triangle_count) * 3);
    if (d.edges) {
        m->topo = adopt_host_topology(d.edges, d.edge_count, d.triangle_edges, d.triangle_count);
        if (d.edge_marks) m->edge_marks.assign(d.edge_marks, d.edge_marks + d.edge_count);
        if (d.edge_bevel_weights)
            m->bevel_weights.assign(d.edge_bevel_weights, d.edge_bevel_weights + d.edge_count);
    } else {
        m->topo = build_topology(d.triangles, d.triangle_count, d.vertex_count);
    }
    // Everything below reads the oriented winding; the caller keeps drawing its own triangles.
    m->orient = find_orientation(*m);
    apply_orientation(*m, m->orient);
    if (d.triangle_materials)
        m->triangle_materials.assign(d.triangle_materials, d.triangle_materials + d.triangle_count);
    if (d.triangle_normals && d.triangle_count > 0) {
        const auto* n = reinterpret_cast<const glm::vec3*>(d.triangle_normals);
        m->host_face_normals.assign(n, n + d.triangle_count);
    }

    compute_face_normals(*m, m->geom);
    if (d.vertex_normals) {
        const auto* n = reinterpret_cast<const glm::vec3*>(d.vertex_normals);
        m->geom.vertex_normals.assign(n, n + d.vertex_count);
    } else {
        compute_vertex_normals(*m, m->geom);
    }
    analyze_edges(*m, m->cls);
    apply_crease_threshold(m->cls, 30.0f);
    return m;
}

}  // namespace el
