#include "shading_normals.hpp"

#include <glm/glm.hpp>

#include <cmath>

namespace el {

namespace {

using glm::dvec3;

dvec3 at(const float* a, size_t i) { return dvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

}  // namespace

void shading_normals(const ShadingInputs& in, const uint32_t* selected, uint32_t count, double max_turn_deg, float* out) {
    const double cos_max = std::cos(max_turn_deg * 3.14159265358979323846 / 180.0);
    for (uint32_t k = 0; k < count; ++k) {
        const size_t e = selected[k];
        const dvec3 lib[2] = {at(in.edge_normals, 2 * e), at(in.edge_normals, 2 * e + 1)};
        const uint32_t ends[2] = {in.edges[2 * e], in.edges[2 * e + 1]};
        const dvec3 along = at(in.positions, ends[1]) - at(in.positions, ends[0]);
        const double before = glm::dot(glm::cross(lib[0], lib[1]), along);
        dvec3 shaded[2][2] = {};  // [end][side]
        bool kept = true;
        for (int end = 0; end < 2; ++end) {
            for (int f = 0; f < 2; ++f) {
                const int32_t face = in.edge_faces[2 * e + size_t(f)];
                if (face < 0) continue;
                dvec3 nrm(0.0);
                for (int c = 0; c < 3; ++c)
                    if (in.tri_verts[3 * size_t(face) + size_t(c)] == ends[end])
                        nrm += at(in.corner_normals, 3 * size_t(face) + size_t(c));
                const double length = glm::length(nrm);
                if (!(length > 1e-6)) continue;
                nrm /= length;
                // Which of N1 / N2 this side is, and its sign: the library may have re-oriented the face.
                const int col = std::abs(glm::dot(nrm, lib[0])) >= std::abs(glm::dot(nrm, lib[1])) ? 0 : 1;
                const double cos = glm::dot(nrm, lib[col]);
                if (std::abs(cos) >= cos_max) shaded[end][col] = nrm * sign(cos);
            }
            bool keep = glm::length(shaded[end][0]) > 0.5 && glm::length(shaded[end][1]) > 0.5;
            // The same turn from N1 to N2 about the edge, so the fold's sign and the arc's order stand.
            const double after = glm::dot(glm::cross(shaded[end][0], shaded[end][1]), along);
            keep = keep && sign(before) == sign(after) && std::abs(after) > 1e-6 * glm::length(along);
            kept = kept && keep;
        }
        // Both ends or neither: one end falling back alone would add a turn Blender never shades.
        float* o = out + 12 * size_t(k);
        for (int end = 0; end < 2; ++end)
            for (int side = 0; side < 2; ++side) {
                const dvec3 n = kept ? shaded[end][side] : lib[side];
                for (int j = 0; j < 3; ++j) o[6 * end + 3 * side + j] = float(n[j]);
            }
    }
}

}  // namespace el
