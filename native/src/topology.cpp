#include "topology.hpp"


namespace el {

namespace {

// True when side s of triangle t maps to the same edge as an earlier side of t (only possible in
// a triangle with a repeated corner): such a face is listed once per edge.
bool repeats_earlier_side(const std::vector<uint32_t>& triangle_edges, size_t t, uint32_t s) {
    const uint32_t e = triangle_edges[3 * t + s];
    for (uint32_t k = 0; k < s; ++k)
        if (triangle_edges[3 * t + k] == e) return true;
    return false;
}

// Edge -> face CSR from a complete triangle -> edge map, by counting sort (faces ascending).
void build_edge_faces(Topology& t, uint32_t triangle_count) {
    const uint32_t edge_count = t.edge_count();
    std::vector<uint32_t>& offsets = t.edge_face_offsets;
    offsets.assign(size_t(edge_count) + 1, 0);
    for (size_t tri = 0; tri < triangle_count; ++tri)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t e = t.triangle_edges[3 * tri + s];
            if (e != EL_NO_EDGE && !repeats_earlier_side(t.triangle_edges, tri, s)) ++offsets[e + 1];
        }
    for (uint32_t e = 0; e < edge_count; ++e) offsets[e + 1] += offsets[e];
    t.edge_faces.resize(offsets[edge_count]);
    // Fill using offsets[e] as the cursor of edge e, then shift back by one slot.
    for (size_t tri = 0; tri < triangle_count; ++tri)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t e = t.triangle_edges[3 * tri + s];
            if (e != EL_NO_EDGE && !repeats_earlier_side(t.triangle_edges, tri, s)) t.edge_faces[offsets[e]++] = uint32_t(tri);
        }
    for (uint32_t e = edge_count; e > 0; --e) offsets[e] = offsets[e - 1];
    offsets[0] = 0;
}

}  // namespace

Topology build_topology(const uint32_t* tris, uint32_t triangle_count, uint32_t vertex_count) {
    Topology t;
    const size_t sides = size_t(triangle_count) * 3;
    // One pass over the sides: each vertex keeps a short linked list of the edges whose lower
    // vertex it is, so a side finds its edge in a few steps (no hashing, no sort). Edges are
    // numbered in order of first use, which keeps neighbouring edges close in memory.
    std::vector<uint32_t> head(vertex_count, EL_NO_EDGE);
    std::vector<uint32_t> next;
    next.reserve(sides / 2 + 16);
    t.edge_vertices.reserve(sides + 32);
    t.triangle_edges.resize(sides);
    for (size_t i = 0; i < sides; i += 3) {
        const uint32_t c[3] = {tris[i], tris[i + 1], tris[i + 2]};
        if (i + 8 < sides) {
            // Scanned meshes jump around the vertex array: start the next triangle's loads now.
            __builtin_prefetch(&head[tris[i + 6]]);
            __builtin_prefetch(&head[tris[i + 7]]);
            __builtin_prefetch(&head[tris[i + 8]]);
        }
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t a = c[s], b = c[s == 2 ? 0 : s + 1];
            if (a == b) {
                t.triangle_edges[i + s] = EL_NO_EDGE;
                continue;
            }
            const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
            uint32_t e = head[lo];
            while (e != EL_NO_EDGE && t.edge_vertices[2 * size_t(e) + 1] != hi) e = next[e];
            if (e == EL_NO_EDGE) {
                e = uint32_t(next.size());
                next.push_back(head[lo]);
                head[lo] = e;
                t.edge_vertices.push_back(lo);
                t.edge_vertices.push_back(hi);
            }
            t.triangle_edges[i + s] = e;
        }
    }
    t.edge_vertices.shrink_to_fit();
    build_edge_faces(t, triangle_count);
    return t;
}

Topology adopt_host_topology(const uint32_t* edges, uint32_t edge_count, const uint32_t* triangle_edges,
                             uint32_t triangle_count) {
    Topology t;
    t.host_edges = true;
    t.edge_vertices.assign(edges, edges + size_t(edge_count) * 2);
    if (triangle_count > 0)
        t.triangle_edges.assign(triangle_edges, triangle_edges + size_t(triangle_count) * 3);
    build_edge_faces(t, triangle_count);
    return t;
}

}  // namespace el
