#include "mesh_validate.hpp"

#include "error.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace el {

namespace {

std::string s(uint64_t v) { return std::to_string(v); }

void check_triangles(const el_mesh_desc& d) {
    const uint32_t* t = d.triangles;
    for (uint64_t i = 0; i < uint64_t(d.triangle_count) * 3; ++i)
        if (t[i] >= d.vertex_count)
            fail(EL_ERR_INDEX_OUT_OF_RANGE, "triangle " + s(i / 3) + " corner " + s(i % 3) +
                                                " refers to vertex " + s(t[i]) + " but there are " +
                                                s(d.vertex_count) + " vertices");
}

void check_host_edges(const el_mesh_desc& d) {
    for (uint32_t e = 0; e < d.edge_count; ++e) {
        const uint32_t a = d.edges[2 * e], b = d.edges[2 * e + 1];
        if (a >= d.vertex_count || b >= d.vertex_count)
            fail(EL_ERR_INDEX_OUT_OF_RANGE, "edge " + s(e) + " refers to vertex " +
                                                s(a >= d.vertex_count ? a : b) + " but there are " +
                                                s(d.vertex_count) + " vertices");
        if (a == b) fail(EL_ERR_INVALID_ARGUMENT, "edge " + s(e) + " joins vertex " + s(a) + " to itself");
    }
    for (uint32_t t = 0; t < d.triangle_count; ++t)
        for (uint32_t side = 0; side < 3; ++side) {
            const uint32_t e = d.triangle_edges[3 * t + side];
            if (e == EL_NO_EDGE) continue;
            if (e >= d.edge_count)
                fail(EL_ERR_INDEX_OUT_OF_RANGE, "triangle " + s(t) + " side " + s(side) +
                                                    " maps to edge " + s(e) + " but there are " +
                                                    s(d.edge_count) + " edges");
            const uint32_t a = d.triangles[3 * t + side], b = d.triangles[3 * t + (side + 1) % 3];
            const uint32_t ea = d.edges[2 * e], eb = d.edges[2 * e + 1];
            if (!((a == ea && b == eb) || (a == eb && b == ea)))
                fail(EL_ERR_INVALID_ARGUMENT, "triangle " + s(t) + " side " + s(side) + " runs " + s(a) +
                                                  "-" + s(b) + " but maps to edge " + s(e) + " (" +
                                                  s(ea) + "-" + s(eb) + ")");
        }
    if (d.edge_marks)
        for (uint32_t e = 0; e < d.edge_count; ++e)
            if (d.edge_marks[e] & ~EL_MARK_ALL)
                fail(EL_ERR_INVALID_ARGUMENT, "edge " + s(e) + " has marks " + s(d.edge_marks[e]) +
                                                  " outside EL_MARK_ALL");
    if (d.edge_bevel_weights)
        for (uint32_t e = 0; e < d.edge_count; ++e) {
            const float w = d.edge_bevel_weights[e];
            if (!std::isfinite(w)) fail(EL_ERR_NON_FINITE, "bevel weight of edge " + s(e) + " is not finite");
            if (w < 0.0f || w > 1.0f)
                fail(EL_ERR_INVALID_ARGUMENT, "bevel weight of edge " + s(e) + " is " +
                                                  std::to_string(w) + ", outside [0, 1]");
        }
}

void check_finite(const float* v, uint32_t count, const char* what) {
    for (uint64_t i = 0; i < uint64_t(count) * 3; ++i)
        if (!std::isfinite(v[i]))
            fail(EL_ERR_NON_FINITE, std::string(what) + " of vertex " + s(i / 3) + " is not finite");
}

void check_within(const float* v, uint32_t count) {
    for (uint64_t i = 0; i < uint64_t(count) * 3; ++i)
        if (!(std::fabs(double(v[i])) <= EL_MAX_COORDINATE)) {
            char num[32];
            std::snprintf(num, sizeof num, "%g", double(v[i]));
            fail(EL_ERR_NON_FINITE, "position of vertex " + s(i / 3) + " has a coordinate " + num +
                                        ", farther than EL_MAX_COORDINATE (1e15) from the origin");
        }
}

void check_face_normals(const float* n, uint32_t count) {
    for (uint32_t t = 0; t < count; ++t) {
        const float x = n[3 * t], y = n[3 * t + 1], z = n[3 * t + 2];
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            fail(EL_ERR_NON_FINITE, "normal of triangle " + s(t) + " is not finite");
        const float l2 = x * x + y * y + z * z;
        // Unit, or zero for a face without a normal; float normals are unit to ~1e-6.
        if (l2 != 0.0f && std::fabs(l2 - 1.0f) > 1e-3f)
            fail(EL_ERR_INVALID_ARGUMENT, "normal of triangle " + s(t) + " has length " +
                                              std::to_string(std::sqrt(l2)) + ", not 1 (or 0)");
    }
}

}  // namespace

void validate_mesh_desc(const el_mesh_desc& d) {
    if (d.vertex_count == 0) fail(EL_ERR_INVALID_COUNT, "vertex_count is 0");
    if (!d.positions) fail(EL_ERR_NULL_POINTER, "positions is NULL");
    const bool has_edges = d.edges != nullptr || d.triangle_edges != nullptr || d.edge_count != 0;
    if (d.triangle_count == 0 && !has_edges)
        fail(EL_ERR_INVALID_COUNT, "the mesh has no triangles and no edges");
    if (d.triangle_count > 0 && !d.triangles) fail(EL_ERR_NULL_POINTER, "triangles is NULL");
    // Corners and half-edges are indexed with 32 bits.
    if (d.triangle_count > (UINT32_MAX - 1) / 3)
        fail(EL_ERR_OVERFLOW, "triangle_count " + s(d.triangle_count) + " exceeds 32-bit corner indices");
    if (d.edge_count > (UINT32_MAX - 1) / 2)
        fail(EL_ERR_OVERFLOW, "edge_count " + s(d.edge_count) + " exceeds 32-bit indices");
    if (has_edges) {
        if (!d.edges) fail(EL_ERR_NULL_POINTER, "edges is NULL but edge_count or triangle_edges is given");
        if (d.edge_count == 0) fail(EL_ERR_INVALID_COUNT, "edges given with edge_count 0");
        if (d.triangle_count > 0 && !d.triangle_edges)
            fail(EL_ERR_NULL_POINTER, "triangle_edges is NULL but edges are given");
    } else if (d.edge_marks || d.edge_bevel_weights) {
        fail(EL_ERR_INVALID_ARGUMENT, "edge_marks / edge_bevel_weights need host edges");
    }
    check_finite(d.positions, d.vertex_count, "position");
    check_within(d.positions, d.vertex_count);
    if (d.vertex_normals) check_finite(d.vertex_normals, d.vertex_count, "normal");
    if (d.triangle_normals) check_face_normals(d.triangle_normals, d.triangle_count);
    if (d.triangle_count > 0) check_triangles(d);
    if (has_edges) check_host_edges(d);
}

}  // namespace el
