#include "orient.hpp"

#include "big_array.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace el {

namespace {

constexpr uint8_t kUnvisited = 0xFF;

// The side of triangle t on edge e, or -1 when no side or two sides are (a repeated corner runs
// the edge both ways): then the direction t runs e is undefined and nothing propagates across it.
int side_on(const uint32_t* triangle_edges, uint32_t t, uint32_t e) {
    const uint32_t* s = triangle_edges + 3 * size_t(t);
    if ((s[0] == e) + (s[1] == e) + (s[2] == e) != 1) return -1;
    return s[0] == e ? 0 : s[1] == e ? 1 : 2;
}

bool runs(const uint32_t* tris, uint32_t t, uint32_t a, uint32_t b) {
    const uint32_t* v = tris + 3 * size_t(t);
    for (int s = 0; s < 3; ++s)
        if (v[s] == a && v[(s + 1) % 3] == b) return true;
    return false;
}

// Classification's rule for two faces of edge a-b: the face running a -> b (the first if both
// do) needs the other to run b -> a. Only reached for faces with a repeated corner.
bool run_same_way(const uint32_t* tris, uint32_t f0, uint32_t f1, uint32_t a, uint32_t b) {
    if (runs(tris, f0, a, b)) return !runs(tris, f1, b, a);
    if (runs(tris, f1, a, b)) return !runs(tris, f0, b, a);
    return true;
}

constexpr uint32_t kNoSide = 0xFFFFFFFFu;

// For each triangle side that is no edge (a host polygon's diagonal), the side 3u + s of the
// other triangle across it, or kNoSide. The two pieces of a polygon on either side of a diagonal
// share the polygon's winding, so orientation must carry across it as across an edge; otherwise
// a piece joined to the rest only through diagonals would keep the input winding while its
// polygon's other pieces turn.
std::vector<uint32_t> diagonal_neighbours(const uint32_t* tris, const uint32_t* tedges, uint32_t n) {
    std::vector<std::pair<uint64_t, uint32_t>> sides;
    for (uint32_t t = 0; t < n; ++t)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t a = tris[3 * size_t(t) + s], b = tris[3 * size_t(t) + (s + 1) % 3];
            if (tedges[3 * size_t(t) + s] != EL_NO_EDGE || a == b) continue;
            const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            sides.emplace_back(key, 3 * t + s);
        }
    std::vector<uint32_t> out;
    if (sides.empty()) return out;
    out.assign(size_t(n) * 3, kNoSide);
    std::sort(sides.begin(), sides.end());
    for (size_t i = 0; i < sides.size();) {
        size_t j = i + 1;
        while (j < sides.size() && sides[j].first == sides[i].first) ++j;
        if (j - i == 2) {  // exactly two pieces meet there: a diagonal; anything else is not
            out[sides[i].second] = sides[i + 1].second;
            out[sides[i + 1].second] = sides[i].second;
        }
        i = j;
    }
    return out;
}

}  // namespace

Orientation find_orientation(const MeshData& m) {
    Orientation o;
    const uint32_t n = m.triangle_count();
    // Holds the parity relative to the component's seed while walking, then the flips.
    o.flips.assign(n, kUnvisited);
    if (n == 0) return o;
    uint8_t* parity = o.flips.data();
    const uint32_t* tris = m.triangles.data();
    const uint32_t* tedges = m.topo.triangle_edges.data();
    const uint32_t* offsets = m.topo.edge_face_offsets.data();
    const uint32_t* faces = m.topo.edge_faces.data();
    const uint32_t* ev = m.topo.edge_vertices.data();
    // Breadth-first over faces with an explicit queue (no recursion: millions of triangles). Each
    // face enters it once, so one array of n holds every component's faces in turn.
    const std::vector<uint32_t> diagonal = m.topo.triangle_edges.size() == size_t(n) * 3
                                               ? diagonal_neighbours(tris, tedges, n)
                                               : std::vector<uint32_t>();
    UnsetBigArray<uint32_t> queue(n);
    uint32_t tail = 0;
    for (uint32_t seed = 0; seed < n; ++seed) {
        if (parity[seed] != kUnvisited) continue;
        const uint32_t first = tail;
        parity[seed] = 0;
        queue[tail++] = seed;
        // Relative to one of its points, so a mesh far from the origin keeps its volume's sign.
        const glm::dvec3 origin(m.positions[tris[3 * size_t(seed)]]);
        double area[2] = {0.0, 0.0};  // twice the input area of faces at parity 0 and 1
        double volume = 0.0;          // six times the signed volume in the seed's winding
        bool closed = true;
        for (uint32_t head = first; head < tail; ++head) {
            const uint32_t t = queue[head];
            const uint8_t p = parity[t];
            const uint32_t* c = tris + 3 * size_t(t);
            const glm::dvec3 a = glm::dvec3(m.positions[c[0]]) - origin;
            const glm::dvec3 b = glm::dvec3(m.positions[c[1]]) - origin;
            const glm::dvec3 d = glm::dvec3(m.positions[c[2]]) - origin;
            area[p] += glm::length(glm::cross(b - a, d - a));
            const double v = glm::dot(a, glm::cross(b, d));
            volume += p ? -v : v;
            for (uint32_t s = 0; s < 3; ++s) {
                const uint32_t e = tedges[3 * size_t(t) + s];
                if (e == EL_NO_EDGE) {  // a polygon's diagonal (or a repeated corner: no neighbour)
                    const uint32_t across = diagonal.empty() ? kNoSide : diagonal[3 * size_t(t) + s];
                    if (across == kNoSide) continue;
                    const uint32_t u = across / 3;
                    const bool same = c[s] == tris[across];
                    if (parity[u] == kUnvisited) {
                        parity[u] = uint8_t(p ^ same);
                        queue[tail++] = u;
                    }
                    continue;
                }
                const uint32_t begin = offsets[e];
                if (offsets[e + 1] - begin != 2) {  // border and non-manifold edges do not propagate
                    closed = false;
                    continue;
                }
                const uint32_t u = faces[begin] == t ? faces[begin + 1] : faces[begin];
                const int su = side_on(tedges, u, e), st = side_on(tedges, t, e);
                if (su < 0 || st < 0) {
                    // Count the edge once: from its lower face, at that face's first side on it.
                    bool first_side = true;
                    for (uint32_t k = 0; k < s; ++k) first_side &= tedges[3 * size_t(t) + k] != e;
                    if (t < u && first_side)
                        o.input_flipped_edges += run_same_way(tris, faces[begin], faces[begin + 1], ev[2 * size_t(e)],
                                                              ev[2 * size_t(e) + 1]);
                    continue;
                }
                // Consistent neighbours run their shared edge in opposite directions.
                const bool same = c[s] == tris[3 * size_t(u) + uint32_t(su)];
                if (t < u) o.input_flipped_edges += same;
                if (parity[u] == kUnvisited) {
                    parity[u] = uint8_t(p ^ same);
                    queue[tail++] = u;
                }
                // A visited neighbour with the other parity is a non-orientable component's
                // conflict: it stays, and classification flags that edge.
            }
        }
        // Closed: outward normals (positive volume). Open, or a closed volume of exactly zero:
        // the winding of the larger input area; a tie keeps the seed as given.
        const bool reverse = closed && volume != 0.0 ? volume < 0.0 : area[1] > area[0];
        if (reverse)
            for (uint32_t k = first; k < tail; ++k) parity[queue[k]] ^= 1u;
    }
    for (uint8_t f : o.flips) o.reoriented_triangles += f;
    return o;
}

void apply_orientation(MeshData& m, const Orientation& o) {
    // Corner 0 stays, so a reversed triangle's normal is the exact negation of its input one.
    // Sides: 0 = c0->c1, 1 = c1->c2, 2 = c2->c0 become 2, 1, 0 of (c0, c2, c1) reversed.
    const uint32_t n = m.triangle_count();
    const bool has_sides = m.topo.triangle_edges.size() == size_t(n) * 3;
    for (uint32_t t = 0; t < n; ++t) {
        if (!o.flips[t]) continue;
        std::swap(m.triangles[3 * size_t(t) + 1], m.triangles[3 * size_t(t) + 2]);
        if (has_sides) std::swap(m.topo.triangle_edges[3 * size_t(t)], m.topo.triangle_edges[3 * size_t(t) + 2]);
    }
}

}  // namespace el
