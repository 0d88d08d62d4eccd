#include "topology.hpp"

#include <algorithm>

namespace el {

namespace {

// Edge -> face CSR from a complete triangle -> edge map, by counting sort (faces ascending).
void build_edge_faces(Topology& t, uint32_t triangle_count) {
    const uint32_t edge_count = t.edge_count();
    t.edge_face_offsets.assign(size_t(edge_count) + 1, 0);
    for (uint32_t e : t.triangle_edges)
        if (e != EL_NO_EDGE) ++t.edge_face_offsets[e + 1];
    for (uint32_t e = 0; e < edge_count; ++e) t.edge_face_offsets[e + 1] += t.edge_face_offsets[e];
    t.edge_faces.resize(t.edge_face_offsets[edge_count]);
    std::vector<uint32_t> cursor(t.edge_face_offsets.begin(), t.edge_face_offsets.end() - 1);
    for (uint32_t tri = 0; tri < triangle_count; ++tri)
        for (uint32_t side = 0; side < 3; ++side) {
            const uint32_t e = t.triangle_edges[3 * tri + side];
            // A degenerate triangle may use one edge on two sides: list the face once.
            if (e == EL_NO_EDGE) continue;
            const uint32_t begin = t.edge_face_offsets[e];
            if (cursor[e] > begin && t.edge_faces[cursor[e] - 1] == tri) continue;
            t.edge_faces[cursor[e]++] = tri;
        }
    // Close the holes left by skipped duplicates.
    uint32_t write = 0;
    for (uint32_t e = 0; e < edge_count; ++e) {
        const uint32_t begin = t.edge_face_offsets[e], end = cursor[e];
        t.edge_face_offsets[e] = write;
        for (uint32_t i = begin; i < end; ++i) t.edge_faces[write++] = t.edge_faces[i];
    }
    t.edge_face_offsets[edge_count] = write;
    t.edge_faces.resize(write);
}

}  // namespace

Topology build_topology(const uint32_t* tris, uint32_t triangle_count, uint32_t vertex_count) {
    Topology t;
    const size_t sides = size_t(triangle_count) * 3;
    // Bucket every side by its lower vertex; a vertex has few edges, so each bucket is tiny and
    // unique edges are found by a short linear scan (no hashing, no global sort).
    std::vector<uint32_t> offsets(size_t(vertex_count) + 1, 0);
    for (size_t i = 0; i < sides; ++i) {
        const uint32_t a = tris[i], b = tris[i - i % 3 + (i % 3 + 1) % 3];
        if (a != b) ++offsets[std::min(a, b) + 1];
    }
    for (uint32_t v = 0; v < vertex_count; ++v) offsets[v + 1] += offsets[v];
    std::vector<uint32_t> bucket_hi(offsets[vertex_count]), bucket_side(offsets[vertex_count]);
    {
        std::vector<uint32_t> fill(offsets.begin(), offsets.end() - 1);
        for (size_t i = 0; i < sides; ++i) {
            const uint32_t a = tris[i], b = tris[i - i % 3 + (i % 3 + 1) % 3];
            if (a == b) continue;
            const uint32_t slot = fill[std::min(a, b)]++;
            bucket_hi[slot] = std::max(a, b);
            bucket_side[slot] = uint32_t(i);
        }
    }
    t.triangle_edges.assign(sides, EL_NO_EDGE);
    t.edge_vertices.reserve(sides);  // ~sides/2 for closed meshes; reserve the bound once
    std::vector<uint32_t> bucket_edge(offsets[vertex_count]);
    for (uint32_t v = 0; v < vertex_count; ++v) {
        const uint32_t begin = offsets[v], end = offsets[v + 1];
        for (uint32_t i = begin; i < end; ++i) {
            uint32_t e = EL_NO_EDGE;
            for (uint32_t j = begin; j < i; ++j)
                if (bucket_hi[j] == bucket_hi[i]) { e = bucket_edge[j]; break; }
            if (e == EL_NO_EDGE) {
                e = t.edge_count();
                t.edge_vertices.push_back(v);
                t.edge_vertices.push_back(bucket_hi[i]);
            }
            bucket_edge[i] = e;
            t.triangle_edges[bucket_side[i]] = e;
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
