#include "topology.hpp"

#include <algorithm>

namespace el {

namespace {

// Edge -> face CSR from a complete triangle -> edge map, by counting sort (faces ascending).
// A triangle with a repeated corner can map two sides to one edge: its face is listed once.
void build_edge_faces(Topology& t, uint32_t triangle_count) {
    const uint32_t edge_count = t.edge_count();
    auto repeats_earlier_side = [&](size_t tri, uint32_t s) {
        for (uint32_t k = 0; k < s; ++k)
            if (t.triangle_edges[3 * tri + k] == t.triangle_edges[3 * tri + s]) return true;
        return false;
    };
    auto& offsets = t.edge_face_offsets;
    offsets.assign(size_t(edge_count) + 1, 0);
    for (size_t tri = 0; tri < triangle_count; ++tri)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t e = t.triangle_edges[3 * tri + s];
            if (e != EL_NO_EDGE && !repeats_earlier_side(tri, s)) ++offsets[e + 1];
        }
    for (uint32_t e = 0; e < edge_count; ++e) offsets[e + 1] += offsets[e];
    t.edge_faces.resize(offsets[edge_count]);
    // Fill using offsets[e] as the cursor of edge e, then shift back by one slot.
    for (size_t tri = 0; tri < triangle_count; ++tri)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t e = t.triangle_edges[3 * tri + s];
            if (e != EL_NO_EDGE && !repeats_earlier_side(tri, s)) t.edge_faces[offsets[e]++] = uint32_t(tri);
        }
    for (uint32_t e = edge_count; e > 0; --e) offsets[e] = offsets[e - 1];
    offsets[0] = 0;
}

// A bucket holds the sides whose lower vertex is one vertex, as (higher vertex << 32 | side); a
// closed mesh averages six. Keys are distinct (each carries its side), so a short bucket is
// rank-sorted: each key's place is the count of smaller keys, with no data-dependent branch
// (insertion sort mispredicts about once per key on scanned meshes). Buckets already in order
// (meshes whose triangles follow their vertices) are left alone; a fan's apex can own thousands
// of sides, which std::sort takes.
void sort_bucket(uint64_t* first, uint64_t* last) {
    const ptrdiff_t n = last - first;
    if (n > 16) {
        std::sort(first, last);
        return;
    }
    bool sorted = true;
    for (ptrdiff_t k = 1; k < n; ++k) sorted &= first[k - 1] < first[k];
    if (sorted) return;
    uint64_t copy[16];
    for (ptrdiff_t k = 0; k < n; ++k) copy[k] = first[k];
    for (ptrdiff_t k = 0; k < n; ++k) {
        ptrdiff_t rank = 0;
        for (ptrdiff_t j = 0; j < n; ++j) rank += copy[j] < copy[k];
        first[rank] = copy[k];
    }
}

}  // namespace

Topology build_topology(const uint32_t* tris, uint32_t triangle_count, uint32_t vertex_count) {
    // Counting sort of the sides by lower vertex, then one sequential walk of the buckets. Every
    // pass is a stream plus independent scattered writes, so the CPU overlaps its cache misses;
    // a search per side (hash or per-vertex list) waits on a chain of dependent misses when the
    // triangle order does not follow the vertex order, as in scanned meshes. The caller has
    // checked that 3 * triangle_count fits in 32 bits.
    Topology t;
    const uint32_t sides = triangle_count * 3;
    t.triangle_edges.resize(sides);

    BigArray<uint32_t> cursor(size_t(vertex_count) + 1, 0);
    for (uint32_t i = 0; i < sides; i += 3)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t a = tris[i + s], b = tris[s == 2 ? i : i + s + 1];
            if (a != b) ++cursor[(a < b ? a : b) + 1];
        }
    for (uint32_t v = 0; v < vertex_count; ++v) cursor[v + 1] += cursor[v];
    const uint32_t keyed = cursor[vertex_count];

    // Scatter: cursor[v] runs from the start of v's bucket to its end, which is where bucket
    // v + 1 starts; sides arrive in increasing order, so within a bucket they stay in that order.
    UnsetBigArray<uint64_t> keys(keyed);
    for (uint32_t i = 0; i < sides; i += 3)
        for (uint32_t s = 0; s < 3; ++s) {
            const uint32_t a = tris[i + s], b = tris[s == 2 ? i : i + s + 1];
            if (a == b) {
                t.triangle_edges[i + s] = EL_NO_EDGE;
                continue;
            }
            const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
            keys[cursor[lo]++] = uint64_t(hi) << 32 | (i + s);
        }

    // Walk the buckets: equal higher vertices make one edge, numbered in (lower, higher) order;
    // its sides come out in increasing order, so its faces are written ascending, each once (a
    // triangle with a repeated corner maps two sides to one edge). Raw cursors keep the loop
    // lean; a closed manifold has keyed / 2 edges, open meshes grow the arrays now and then.
    size_t capacity = keyed / 2 + 64;
    t.edge_vertices.resize(capacity * 2);
    t.edge_face_offsets.resize(capacity + 1);
    t.edge_faces.resize(keyed);
    uint32_t* edge_vertices = t.edge_vertices.data();
    uint32_t* offsets = t.edge_face_offsets.data();
    uint32_t* faces = t.edge_faces.data();
    uint32_t* triangle_edges = t.triangle_edges.data();
    uint32_t e = 0, f = 0, begin = 0;
    for (uint32_t v = 0; v < vertex_count; ++v) {
        const uint32_t end = cursor[v];
        sort_bucket(keys.data() + begin, keys.data() + end);
        for (uint32_t k = begin; k < end; ++e) {
            if (e == capacity) {
                capacity += capacity / 4 + 64;
                t.edge_vertices.resize(capacity * 2);
                t.edge_face_offsets.resize(capacity + 1);
                edge_vertices = t.edge_vertices.data();
                offsets = t.edge_face_offsets.data();
            }
            const uint32_t hi = uint32_t(keys[k] >> 32);
            offsets[e] = f;
            edge_vertices[2 * size_t(e)] = v;
            edge_vertices[2 * size_t(e) + 1] = hi;
            uint32_t last_face = EL_NO_EDGE;
            for (; k < end && uint32_t(keys[k] >> 32) == hi; ++k) {
                const uint32_t side = uint32_t(keys[k]), face = side / 3;
                triangle_edges[side] = e;
                faces[f] = face;
                f += face != last_face;
                last_face = face;
            }
        }
        begin = end;
    }
    offsets[e] = f;
    t.edge_vertices.resize(size_t(e) * 2);
    t.edge_face_offsets.resize(size_t(e) + 1);
    t.edge_faces.resize(f);
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
