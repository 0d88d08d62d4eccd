#include "corner_patches.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace el {

namespace {

// Two sides of one sector turn by at most this (degrees): a patch's facets, each folded under
// 30 degrees, may add up to more than one fold, but no further.
constexpr double kSectorTurnDeg = 40.0;
// |det| of the three unit sector normals below this: a shallow corner, its mitres stand.
constexpr float kMinDet = 0.05f;
// The ball's centre further than this many radii from the vertex: a needle-sharp corner.
constexpr double kMaxReach = 4.0;

struct V3 {
    float x, y, z;
};

V3 add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 u, V3 v) { return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x}; }

V3 normal_of(const float* edge_normals, uint32_t e, int side) {
    const float* n = edge_normals + 6 * size_t(e) + 3 * side;
    return {n[0], n[1], n[2]};
}

}  // namespace

std::vector<CornerPatch> corner_patches(const CornerInputs& in) {
    const size_t nv = in.vertex_count;
    std::vector<uint8_t> count_all(nv, 0), count_conv(nv, 0), count_stop(nv, 0);
    auto bump = [](uint8_t& c) { c = uint8_t(std::min(int(c) + 1, 255)); };
    for (uint32_t e = 0; e < in.edge_count; ++e) {
        const bool stop = in.stop ? in.stop[e] != 0 : in.chosen[e] != 0;
        for (int k = 0; k < 2; ++k) {
            const uint32_t v = in.edges[2 * size_t(e) + size_t(k)];
            if (in.chosen[e]) {
                bump(count_all[v]);
                if (in.convex[e]) bump(count_conv[v]);
            }
            if (stop) bump(count_stop[v]);
        }
    }
    // Three convex edges (the ball inside the solid) or three concave ones (in the air), and no
    // other patch boundary round the vertex.
    std::vector<std::array<uint32_t, 3>> trio(nv);
    std::vector<uint8_t> filled(nv, 0);
    auto at = [&](uint32_t v) {
        return count_all[v] == 3 && (count_conv[v] == 3 || count_conv[v] == 0) && count_stop[v] == 3;
    };
    for (uint32_t e = 0; e < in.edge_count; ++e)
        if (in.chosen[e])
            for (int k = 0; k < 2; ++k) {
                const uint32_t v = in.edges[2 * size_t(e) + size_t(k)];
                if (at(v) && filled[v] < 3) trio[v][filled[v]++] = e;
            }
    const float cos_max = float(std::cos(kSectorTurnDeg * 3.14159265358979323846 / 180.0));
    std::vector<CornerPatch> out;
    for (uint32_t v = 0; v < nv; ++v) {
        if (!at(v)) continue;
        const auto& t = trio[v];
        V3 n[3][2];
        for (int j = 0; j < 3; ++j)
            for (int s = 0; s < 2; ++s) n[j][s] = normal_of(in.edge_normals, t[size_t(j)], s);
        // Each choice (sA, sB, sC) of the sides facing the next edge round; its worst sector
        // (AB: A[sA] with B[1 - sB], BC: B[sB] with C[1 - sC], CA: C[sC] with A[1 - sA]).
        int best = 0;
        float best_cos = -INFINITY;
        for (int c = 0; c < 8; ++c) {
            const int s[3] = {(c >> 2) & 1, (c >> 1) & 1, c & 1};
            float score = INFINITY;
            for (int j = 0; j < 3; ++j) score = std::min(score, dot(n[j][s[j]], n[(j + 1) % 3][1 - s[(j + 1) % 3]]));
            if (score > best_cos) {
                best_cos = score;
                best = c;
            }
        }
        const int s[3] = {(best >> 2) & 1, (best >> 1) & 1, best & 1};
        V3 sector[3];
        for (int j = 0; j < 3; ++j) {
            const V3 m = add(n[j][s[j]], n[(j + 1) % 3][1 - s[(j + 1) % 3]]);
            const float len = std::max(std::sqrt(dot(m, m)), 1e-30f);
            sector[j] = {m.x / len, m.y / len, m.z / len};
        }
        const V3 a = sector[0], b = sector[1], c = sector[2];
        const V3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
        const float det = dot(a, bc);
        const float r = std::min({in.radius[t[0]], in.radius[t[1]], in.radius[t[2]]});
        if (!(best_cos >= cos_max && std::abs(det) > kMinDet && r > 0.0f)) continue;
        // The ball touches each sector's plane from inside: N (c - v) = -r (1, 1, 1), by Cramer's
        // rule (the rows' cross products are the inverse's columns times det).
        const double fold = in.convex[t[0]] ? 1.0 : -1.0;
        const V3 sum = add(add(bc, ca), ab);
        const double k = -(fold * double(r)) / double(det);
        const double off[3] = {k * sum.x, k * sum.y, k * sum.z};
        if (!(off[0] * off[0] + off[1] * off[1] + off[2] * off[2] <= (kMaxReach * r) * (kMaxReach * r))) continue;
        CornerPatch p{};
        p.vertex = v;
        std::copy(t.begin(), t.end(), p.edges);
        for (int j = 0; j < 3; ++j) {
            p.normals[3 * j] = sector[j].x;
            p.normals[3 * j + 1] = sector[j].y;
            p.normals[3 * j + 2] = sector[j].z;
            p.centre[j] = float(double(in.positions[3 * size_t(v) + size_t(j)]) + off[j]);
        }
        p.radius = r;
        p.fold = float(fold);
        out.push_back(p);
    }
    return out;
}

}  // namespace el
