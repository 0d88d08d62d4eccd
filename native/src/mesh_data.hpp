// What the library knows about one mesh: inputs copied at create time, topology, geometry and
// static classification. Built once by el_mesh_create; views share it read-only.
#pragma once

#include "big_array.hpp"

#include <edgelight/edgelight.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace el {

// Its builders write every element they size, so resize() leaves new elements unset.
struct Topology {
    UnsetBigArray<uint32_t> edge_vertices;      // 2 per edge
    UnsetBigArray<uint32_t> triangle_edges;     // 3 per triangle, side s = corner s -> s+1; EL_NO_EDGE
    UnsetBigArray<uint32_t> edge_face_offsets;  // CSR: edge_count + 1
    UnsetBigArray<uint32_t> edge_faces;         // triangle indices
    bool host_edges = false;

    uint32_t edge_count() const { return uint32_t(edge_vertices.size() / 2); }
    uint32_t face_count(uint32_t e) const { return edge_face_offsets[e + 1] - edge_face_offsets[e]; }
};

struct Geometry {
    std::vector<glm::vec3> face_normals;  // unit, or zero for degenerate faces
    std::vector<float> face_offsets;      // dot(normal, first corner): plane of each face
    // The same planes as structure-of-arrays, padded with zero planes to a multiple of 64 faces,
    // so the facing pass runs 4 faces per SSE instruction and 16 per output store.
    std::vector<float> plane_x, plane_y, plane_z, plane_d;
    std::vector<uint8_t> face_degenerate;
    std::vector<glm::vec3> vertex_normals;  // unit (host's or angle-weighted), zero if undefined
};

// The library's consistent winding per connected component (orient.hpp).
struct Orientation {
    std::vector<uint8_t> flips;         // per triangle: 1 where the input winding was reversed
    uint32_t reoriented_triangles = 0;  // number of flips
    uint32_t input_flipped_edges = 0;   // manifold edges both faces ran the same way as given
};

struct Classification {
    std::vector<uint32_t> edge_flags;    // EL_EDGE_* | EL_MARK_*, crease bit per threshold
    std::vector<glm::vec3> n1, n2;       // the two face normals the highlight pass needs
    std::vector<float> angle_deg;        // angle between n1 and n2
    std::vector<uint32_t> face1, face2;  // the two faces of manifold edges (else EL_NO_EDGE)
    // Edges that can be silhouettes (manifold, not degenerate) and their faces packed f1 | f2 << 32:
    // one sequential stream for the per-view edge pass.
    std::vector<uint32_t> silhouette_candidates;
    std::vector<uint64_t> candidate_faces;
    float crease_angle_deg = 30.0f;
};

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;           // 3 per triangle, in the oriented winding
    std::vector<uint32_t> edge_marks;          // host marks per edge (empty if none)
    std::vector<float> bevel_weights;          // per edge (empty if none)
    std::vector<uint32_t> triangle_materials;  // per triangle (empty if none)
    std::vector<glm::vec3> host_face_normals;  // per triangle, input winding (empty if none)
    Topology topo;                             // triangle_edges follow the oriented winding
    Orientation orient;
    Geometry geom;
    Classification cls;

    uint32_t vertex_count() const { return uint32_t(positions.size()); }
    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
    uint32_t edge_count() const { return topo.edge_count(); }
};

}  // namespace el
