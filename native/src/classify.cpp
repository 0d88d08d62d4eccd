#include "classify.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace el {

namespace {

// True when triangle t runs from vertex a to vertex b along one of its sides.
bool runs(const MeshData& m, uint32_t t, uint32_t a, uint32_t b) {
    const uint32_t* v = &m.triangles[3 * size_t(t)];
    for (int s = 0; s < 3; ++s)
        if (v[s] == a && v[(s + 1) % 3] == b) return true;
    return false;
}

constexpr float kRadToDeg = 57.29577951308232f;
// Below this the faces are coplanar for convexity purposes (float noise in normals).
constexpr float kFlatDeg = 1e-3f;

}  // namespace

void analyze_edges(const MeshData& m, Classification& cls) {
    const Topology& topo = m.topo;
    const Geometry& geom = m.geom;
    const uint32_t edge_count = topo.edge_count();
    cls.edge_flags.assign(edge_count, 0u);
    cls.n1.assign(edge_count, glm::vec3(0.0f));
    cls.n2.assign(edge_count, glm::vec3(0.0f));
    cls.angle_deg.assign(edge_count, 0.0f);
    cls.face1.assign(edge_count, EL_NO_EDGE);
    cls.face2.assign(edge_count, EL_NO_EDGE);

    for (uint32_t e = 0; e < edge_count; ++e) {
        const uint32_t va = topo.edge_vertices[2 * e], vb = topo.edge_vertices[2 * e + 1];
        const uint32_t begin = topo.edge_face_offsets[e], count = topo.face_count(e);
        const uint32_t* faces = topo.edge_faces.data() + begin;
        uint32_t flags = m.edge_marks.empty() ? 0u : m.edge_marks[e];
        if (!m.bevel_weights.empty() && m.bevel_weights[e] > 0.0f) flags |= EL_MARK_BEVEL;
        if (m.positions[va] == m.positions[vb]) flags |= EL_EDGE_DEGENERATE;

        if (count == 0) flags |= EL_EDGE_LOOSE;
        else if (count == 1) flags |= EL_EDGE_BORDER;
        else if (count == 2) flags |= EL_EDGE_MANIFOLD;
        else flags |= EL_EDGE_NON_MANIFOLD;

        bool any_degenerate = false;
        for (uint32_t i = 0; i < count; ++i) any_degenerate |= geom.face_degenerate[faces[i]] != 0;
        if (any_degenerate) flags |= EL_EDGE_DEGENERATE;

        if (!m.triangle_materials.empty())
            for (uint32_t i = 1; i < count; ++i)
                if (m.triangle_materials[faces[i]] != m.triangle_materials[faces[0]]) {
                    flags |= EL_EDGE_MATERIAL_BOUNDARY;
                    break;
                }

        if (count >= 1) {
            // N1 belongs to the face that runs the edge first -> second vertex, so the arc from
            // N1 to N2 has a fixed orientation relative to the edge direction.
            uint32_t f1 = faces[0];
            for (uint32_t i = 0; i < count; ++i)
                if (runs(m, faces[i], va, vb)) { f1 = faces[i]; break; }
            uint32_t f2 = f1;
            for (uint32_t i = 0; i < count; ++i)
                if (faces[i] != f1) { f2 = faces[i]; break; }
            cls.n1[e] = geom.face_normals[f1];
            cls.n2[e] = geom.face_normals[f2];
            if (count == 2) {
                cls.face1[e] = f1;
                cls.face2[e] = f2;
                // Triangles are oriented per component, so this is left only where the surface
                // is non-orientable (or a repeated corner hides a face's direction).
                const bool consistent = runs(m, f1, va, vb) && runs(m, f2, vb, va);
                if (!consistent) flags |= EL_EDGE_FLIPPED_WINDING;
                if (!any_degenerate) {
                    const glm::vec3 c = glm::cross(cls.n1[e], cls.n2[e]);
                    const float angle = std::atan2(glm::length(c), glm::dot(cls.n1[e], cls.n2[e])) * kRadToDeg;
                    cls.angle_deg[e] = angle;
                    if (consistent && angle > kFlatDeg) {
                        // f1 runs a -> b: the surface turns away from its outside (convex) when
                        // n1 x n2 points along a -> b.
                        const float along = glm::dot(c, m.positions[vb] - m.positions[va]);
                        flags |= along > 0.0f ? EL_EDGE_CONVEX : EL_EDGE_CONCAVE;
                    }
                }
            }
        }
        cls.edge_flags[e] = flags;
    }
    cls.silhouette_candidates.clear();
    cls.candidate_faces.clear();
    // Faces that disagree on a side have no front / back relation to compare.
    for (uint32_t e = 0; e < edge_count; ++e)
        if (cls.face1[e] != EL_NO_EDGE && !(cls.edge_flags[e] & (EL_EDGE_DEGENERATE | EL_EDGE_FLIPPED_WINDING))) {
            cls.silhouette_candidates.push_back(e);
            cls.candidate_faces.push_back(uint64_t(cls.face1[e]) | uint64_t(cls.face2[e]) << 32);
        }
}

void apply_crease_threshold(Classification& cls, float crease_angle_deg) {
    cls.crease_angle_deg = crease_angle_deg;
    const size_t n = cls.edge_flags.size();
    for (size_t e = 0; e < n; ++e) {
        uint32_t f = cls.edge_flags[e] & ~EL_EDGE_CREASE;
        const bool eligible = (f & EL_EDGE_MANIFOLD) && !(f & (EL_EDGE_DEGENERATE | EL_EDGE_FLIPPED_WINDING));
        if (eligible && cls.angle_deg[e] > crease_angle_deg) f |= EL_EDGE_CREASE;
        cls.edge_flags[e] = f;
    }
}

}  // namespace el
