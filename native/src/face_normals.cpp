#include "face_normals.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

namespace el {

void compute_face_normals(const MeshData& mesh, Geometry& geom) {
    const uint32_t n = mesh.triangle_count();
    geom.face_normals.resize(n);
    geom.face_offsets.resize(n);
    geom.face_degenerate.resize(n);
    for (uint32_t t = 0; t < n; ++t) {
        // Double: float inputs make exact differences and products, so a triangle that is
        // collinear in float gives a cross product of (nearly) exactly zero.
        const glm::dvec3 a(mesh.positions[mesh.triangles[3 * t]]);
        const glm::dvec3 b(mesh.positions[mesh.triangles[3 * t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.triangles[3 * t + 2]]);
        const glm::dvec3 e1 = b - a, e2 = c - a, e3 = c - b;
        const glm::dvec3 cr = glm::cross(e1, e2);
        const double len = glm::length(cr);
        const double scale = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
        // Relative to the longest side: below ~float epsilon the normal is noise.
        bool degenerate = !(len > 1e-7 * scale);
        glm::dvec3 nrm = degenerate ? glm::dvec3(0.0) : cr / len;
        if (!mesh.host_face_normals.empty()) {
            // The face the triangle was cut from decides: a sliver's own normal is noise, and a
            // zero-area piece of a proper polygon still lies in that polygon's plane.
            const glm::dvec3 h(mesh.host_face_normals[t]);
            degenerate = glm::dot(h, h) == 0.0;
            nrm = degenerate ? glm::dvec3(0.0) : glm::normalize(mesh.orient.flips[t] ? -h : h);
        }
        geom.face_normals[t] = glm::vec3(nrm);
        geom.face_offsets[t] = degenerate ? 0.0f : float(glm::dot(nrm, a));
        geom.face_degenerate[t] = degenerate ? 1 : 0;
    }
    const size_t padded = (size_t(n) + 63) / 64 * 64;
    geom.plane_x.assign(padded, 0.0f);
    geom.plane_y.assign(padded, 0.0f);
    geom.plane_z.assign(padded, 0.0f);
    geom.plane_d.assign(padded, 0.0f);
    for (uint32_t t = 0; t < n; ++t) {
        geom.plane_x[t] = geom.face_normals[t].x;
        geom.plane_y[t] = geom.face_normals[t].y;
        geom.plane_z[t] = geom.face_normals[t].z;
        geom.plane_d[t] = geom.face_offsets[t];
    }
}

}  // namespace el
