#include "band_ends.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace el {

namespace {

using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;
constexpr float kSquare = float(kPi / 2);
constexpr double kMin = 0.02;                   // rad: a cut along the edge itself would remove the whole band
constexpr float kMaxMitre = float(0.75 * kPi);  // a mitre leans past its vertex by at most the band's width
constexpr int kMaxFan = 32;                     // facets round one vertex a cut looks across at most

dvec3 at(const float* a, size_t i) { return dvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]); }

struct Walker {
    const el_polygons& p;

    uint32_t next(uint32_t loop, uint32_t poly) const {
        const uint32_t s = p.start[poly], t = p.total[poly];
        return s + (loop - s + 1) % t;
    }
    uint32_t prev(uint32_t loop, uint32_t poly) const {
        const uint32_t s = p.start[poly], t = p.total[poly];
        return s + (loop - s + t - 1) % t;
    }
    // Polygon `poly`'s loop along `edge` (its first), or -1.
    int64_t loop_of(uint32_t edge, uint32_t poly) const {
        const uint32_t s = p.start[poly];
        for (uint32_t l = s; l < s + p.total[poly]; ++l)
            if (p.loop_edge[l] == edge) return l;
        return -1;
    }
    // The other side at `vert` of `poly`, whose loop `loop` has `vert` at one end: (its edge,
    // its far vertex).
    void side_at(uint32_t loop, uint32_t poly, uint32_t vert, uint32_t& side, uint32_t& far) const {
        const uint32_t nxt = next(loop, poly), prv = prev(loop, poly), nxt2 = next(nxt, poly);
        if (p.loop_vert[loop] == vert) {
            side = p.loop_edge[prv];
            far = p.loop_vert[prv];
        } else {
            side = p.loop_edge[nxt];
            far = p.loop_vert[nxt2];
        }
    }
};

}  // namespace

void band_ends(const BandEndInputs& in, const uint32_t* selected, const int32_t* faces, uint32_t count, float* out) {
    std::fill(out, out + 4 * size_t(count), kSquare);
    const el_polygons& polys = *in.polys;
    if (polys.loop_count == 0) return;
    const Walker w{polys};
    // A chain's joint: exactly two rounded edges at the vertex.
    std::vector<uint32_t> rounded_at(in.vertex_count, 0);
    for (uint32_t e = 0; e < in.edge_count; ++e)
        if (in.rounded[e])
            for (int k = 0; k < 2; ++k) ++rounded_at[in.edges[2 * size_t(e) + size_t(k)]];
    const bool fans = in.smooth && in.edge_polys;
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t edge = selected[i];
        const uint32_t ends[2] = {in.edges[2 * size_t(edge)], in.edges[2 * size_t(edge) + 1]};
        const dvec3 p[2] = {at(in.positions, ends[0]), at(in.positions, ends[1])};
        dvec3 e = p[1] - p[0];
        e /= std::max(glm::length(e), 1e-30);
        const dvec3 n1 = at(in.edge_normals, 2 * size_t(edge)), n2 = at(in.edge_normals, 2 * size_t(edge) + 1);
        const dvec3 inside[2] = {glm::cross(n1, e), glm::cross(e, n2)};
        for (int side = 0; side < 2; ++side) {
            const int32_t face = faces[2 * size_t(i) + size_t(side)];
            if (face < 0) continue;
            const uint32_t poly = polys.tri_poly[face];
            const int64_t loop = w.loop_of(edge, poly);
            if (loop < 0) continue;
            // N1's face or N2's: by normal, not by winding (the library orients faces the host
            // may have flipped; the polygons keep the host's winding).
            const dvec3 n_poly = at(polys.normal, poly);
            const int col = std::abs(glm::dot(n_poly, n1)) >= std::abs(glm::dot(n_poly, n2)) ? 0 : 1;
            for (int end = 0; end < 2; ++end) {
                const uint32_t v = ends[end];
                uint32_t other_edge = 0, other_vert = 0;
                w.side_at(uint32_t(loop), poly, v, other_edge, other_vert);
                bool closed = false;
                if (fans) {
                    // On round the vertex across the smooth patch's facets to its own side.
                    uint32_t q_poly = poly;
                    for (int step = 0; step < kMaxFan && in.smooth[other_edge] && other_edge != edge; ++step) {
                        const int32_t* ep = in.edge_polys + 2 * size_t(other_edge);
                        const int32_t q = ep[0] == int32_t(q_poly) ? ep[1] : ep[0];
                        if (q < 0 || uint32_t(q) == q_poly) break;
                        const int64_t l = w.loop_of(other_edge, uint32_t(q));
                        if (l < 0) break;
                        w.side_at(uint32_t(l), uint32_t(q), v, other_edge, other_vert);
                        q_poly = uint32_t(q);
                    }
                    closed = other_edge == edge;  // the band's edge ends inside a smooth patch
                }
                const dvec3 u = end == 0 ? e : -e;
                const dvec3 g = at(in.positions, other_vert) - p[end];
                dvec3 n_in = inside[col];
                n_in /= std::max(glm::length(n_in), 1e-30);
                // The face's corner angle at this end, from the edge towards its inside.
                double theta = std::atan2(glm::dot(g, n_in), glm::dot(g, u));
                theta -= std::floor(theta / (2.0 * kPi)) * (2.0 * kPi);
                const bool mitre = in.rounded[other_edge] != 0;
                const double lean = rounded_at[v] == 2 ? kMaxMitre : kSquare;
                double phi = mitre ? std::min(0.5 * theta, lean) : std::min(theta, double(kSquare));
                phi = closed ? double(kSquare) : std::max(phi, kMin);
                out[4 * size_t(i) + 2 * size_t(end) + size_t(col)] = float(phi);
            }
        }
    }
}

}  // namespace el
