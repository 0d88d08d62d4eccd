// C entry points for what the edge pass shades rounded edges with (shading_normals.hpp) and the
// corner patches where three of them meet (corner_patches.hpp) and where their bands end
// (band_ends.hpp).
#include "band_ends.hpp"
#include "capi_common.hpp"
#include "corner_patches.hpp"
#include "edge_rules.hpp"
#include "radius_clamp.hpp"
#include "shading_normals.hpp"

#include <string>

using el::guarded;
using el::require;

namespace {

using el::require_below;
using el::require_finite_array;
using el::require_index_or_none;

// A polygon table's loops: start and total where there are polygons, each polygon's loops
// (at least one) within the loops, each loop's vertex below vertex_count.
void require_polygon_loops(const el_polygons& P, uint32_t vertex_count) {
    if (P.polygon_count) {
        require(P.start, "polys->start");
        require(P.total, "polys->total");
    }
    if (P.loop_count) require(P.loop_vert, "polys->loop_vert");
    for (uint32_t k = 0; k < P.polygon_count; ++k)
        if (P.total[k] < 1 || uint64_t(P.start[k]) + P.total[k] > P.loop_count)
            el::fail(EL_ERR_INDEX_OUT_OF_RANGE, "polygon " + std::to_string(k) + "'s loops " + std::to_string(P.start[k]) +
                                                    " + " + std::to_string(P.total[k]) + " are not within the " +
                                                    std::to_string(P.loop_count) + " loops (at least one each)");
    require_below(P.loop_vert, P.loop_count, vertex_count, "polys->loop_vert", "vertex count");
}

}  // namespace

extern "C" {

EL_API el_status el_shading_normals(const float* positions, uint32_t vertex_count, const uint32_t* edges,
                                    const float* edge_normals, const int32_t* edge_faces, uint32_t edge_count,
                                    const uint32_t* tri_verts, const float* corner_normals, uint32_t triangle_count,
                                    const uint32_t* selected, uint32_t count, float max_turn_deg, float* out) {
    return guarded("el_shading_normals", [&] {
        el::require_finite(max_turn_deg, "max_turn_deg");
        if (count == 0) return;
        for (auto [p, name] : {std::pair<const void*, const char*>{positions, "positions"}, {edges, "edges"}, {edge_normals, "edge_normals"}, {edge_faces, "edge_faces"}, {tri_verts, "tri_verts"}, {corner_normals, "corner_normals"}, {selected, "selected"}, {out, "out"}})
            require(p, name);
        require_below(selected, count, edge_count, "selected", "edge count");
        require_below(edges, 2 * size_t(edge_count), vertex_count, "edges", "vertex count");
        require_index_or_none(edge_faces, 2 * size_t(edge_count), triangle_count, "edge_faces", "triangle");
        require_finite_array(positions, 3 * size_t(vertex_count), "positions");
        require_finite_array(edge_normals, 6 * size_t(edge_count), "edge_normals");
        require_finite_array(corner_normals, 9 * size_t(triangle_count), "corner_normals");
        el::shading_normals(el::ShadingInputs{positions, edges, edge_normals, edge_faces, tri_verts, corner_normals},
                            selected, count, max_turn_deg, out);
    });
}

EL_API el_status el_corner_patches(const float* positions, uint32_t vertex_count, const uint32_t* edges,
                                   const float* edge_normals, const uint8_t* convex, const uint8_t* chosen,
                                   const float* radius, const uint8_t* stop, uint32_t edge_count, uint32_t capacity,
                                   uint32_t* out_vertex, uint32_t* out_edges, float* out_normals, float* out_radius,
                                   float* out_centre, float* out_fold, uint32_t* out_count) {
    if (out_count) *out_count = 0;
    return guarded("el_corner_patches", [&] {
        require(out_count, "out_count");
        if (edge_count == 0) return;
        for (auto [p, name] : {std::pair<const void*, const char*>{positions, "positions"}, {edges, "edges"}, {edge_normals, "edge_normals"}, {convex, "convex"}, {chosen, "chosen"}, {radius, "radius"}})
            require(p, name);
        require_below(edges, 2 * size_t(edge_count), vertex_count, "edges", "vertex count");
        require_finite_array(positions, 3 * size_t(vertex_count), "positions");
        require_finite_array(edge_normals, 6 * size_t(edge_count), "edge_normals");
        for (uint32_t e = 0; e < edge_count; ++e)  // the others' radii are not read (inf: no radius)
            if (chosen[e] && !std::isfinite(radius[e]))
                el::fail(EL_ERR_NON_FINITE, "radius[" + std::to_string(e) + "] of a chosen edge is not finite");
        const auto corners = el::corner_patches(
            el::CornerInputs{positions, vertex_count, edges, edge_normals, convex, chosen, radius, stop, edge_count});
        *out_count = uint32_t(corners.size());
        el::require_capacity(capacity, corners.size(), "capacity");
        if (corners.empty()) return;
        for (auto [p, name] : {std::pair<const void*, const char*>{out_vertex, "out_vertex"}, {out_edges, "out_edges"}, {out_normals, "out_normals"}, {out_radius, "out_radius"}, {out_centre, "out_centre"}, {out_fold, "out_fold"}})
            require(p, name);
        for (size_t k = 0; k < corners.size(); ++k) {
            const el::CornerPatch& c = corners[k];
            out_vertex[k] = c.vertex;
            std::copy(c.edges, c.edges + 3, out_edges + 3 * k);
            std::copy(c.normals, c.normals + 9, out_normals + 9 * k);
            out_radius[k] = c.radius;
            std::copy(c.centre, c.centre + 3, out_centre + 3 * k);
            out_fold[k] = c.fold;
        }
    });
}

EL_API el_status el_band_ends(const el_polygons* polys, const float* positions, uint32_t vertex_count,
                              const uint32_t* edges, const float* edge_normals, const uint8_t* rounded,
                              const uint8_t* smooth, const int32_t* edge_polys, uint32_t edge_count,
                              const uint32_t* selected, const int32_t* faces, uint32_t count, float* out) {
    return guarded("el_band_ends", [&] {
        if (count == 0) return;
        require(polys, "polys");
        for (auto [p, name] : {std::pair<const void*, const char*>{positions, "positions"}, {edges, "edges"}, {edge_normals, "edge_normals"}, {rounded, "rounded"}, {selected, "selected"}, {faces, "faces"}, {out, "out"}})
            require(p, name);
        const el_polygons& P = *polys;
        require_polygon_loops(P, vertex_count);
        if (P.polygon_count) require(P.normal, "polys->normal");
        if (P.loop_count) require(P.loop_edge, "polys->loop_edge");
        if (P.triangle_count) require(P.tri_poly, "polys->tri_poly");
        require_below(P.loop_edge, P.loop_count, edge_count, "polys->loop_edge", "edge count");
        require_below(P.tri_poly, P.triangle_count, P.polygon_count, "polys->tri_poly", "polygon count");
        require_finite_array(P.normal, 3 * size_t(P.polygon_count), "polys->normal");
        require_below(edges, 2 * size_t(edge_count), vertex_count, "edges", "vertex count");
        require_below(selected, count, edge_count, "selected", "edge count");
        require_finite_array(positions, 3 * size_t(vertex_count), "positions");
        require_finite_array(edge_normals, 6 * size_t(edge_count), "edge_normals");
        require_index_or_none(faces, 2 * size_t(count), P.triangle_count, "faces", "triangle");
        if (edge_polys) require_index_or_none(edge_polys, 2 * size_t(edge_count), P.polygon_count, "edge_polys", "polygon");
        el::band_ends(el::BandEndInputs{polys, positions, vertex_count, edges, edge_normals, rounded, smooth, edge_polys,
                                        edge_count},
                      selected, faces, count, out);
    });
}

EL_API el_status el_width_bounds(const el_polygons* polys, const float* positions, uint32_t vertex_count,
                                 const uint32_t* edges, const int32_t* edge_polys, uint32_t count, double* out) {
    return guarded("el_width_bounds", [&] {
        if (count == 0) return;
        require(polys, "polys");
        for (auto [p, name] : {std::pair<const void*, const char*>{positions, "positions"}, {edges, "edges"}, {edge_polys, "edge_polys"}, {out, "out"}})
            require(p, name);
        const el_polygons& P = *polys;
        require_polygon_loops(P, vertex_count);
        require_below(edges, 2 * size_t(count), vertex_count, "edges", "vertex count");
        require_finite_array(positions, 3 * size_t(vertex_count), "positions");
        require_index_or_none(edge_polys, 2 * size_t(count), P.polygon_count, "edge_polys", "polygon");
        el::width_bounds(P, positions, edges, edge_polys, count, out);
    });
}

EL_API el_status el_edge_rules(const uint32_t* flags, const float* angles, const int32_t* face_a, const int32_t* face_b,
                               const uint8_t* sharp, const float* bevel, uint32_t edge_count, const uint32_t* tri_slot,
                               uint32_t triangle_count, const el_slot_rules* slots, uint32_t slot_count,
                               uint8_t* out_chosen, float* out_radius, uint32_t* out_slot_a, uint32_t* out_slot_b,
                               uint8_t* out_pick_a, uint8_t* out_pick_b, float* out_rad_a, float* out_rad_b) {
    return guarded("el_edge_rules", [&] {
        if (edge_count == 0) return;
        for (auto [p, name] : {std::pair<const void*, const char*>{flags, "flags"}, {angles, "angles"}, {face_a, "face_a"}, {face_b, "face_b"}, {sharp, "sharp"}, {bevel, "bevel"}, {slots, "slots"}, {out_chosen, "out_chosen"}, {out_radius, "out_radius"}})
            require(p, name);
        if (slot_count == 0) el::fail(EL_ERR_INVALID_COUNT, "slot_count is 0 (a mesh has at least one slot)");
        if (triangle_count) require(tri_slot, "tri_slot");
        require_below(tri_slot, triangle_count, slot_count, "tri_slot", "slot count");
        require_index_or_none(face_a, edge_count, triangle_count, "face_a", "triangle");
        require_index_or_none(face_b, edge_count, triangle_count, "face_b", "triangle");
        require_finite_array(angles, edge_count, "angles");
        require_finite_array(bevel, edge_count, "bevel");
        for (uint32_t s = 0; s < slot_count; ++s)
            if (!std::isfinite(slots[s].radius) || !std::isfinite(slots[s].K) || !std::isfinite(slots[s].angle_deg))
                el::fail(EL_ERR_NON_FINITE, "slots[" + std::to_string(s) + "] has a value that is not finite");
        el::edge_rules(el::EdgeRuleInputs{flags, angles, face_a, face_b, sharp, bevel, edge_count, tri_slot, slots},
                       el::EdgeRuleOutputs{out_chosen, out_radius, out_slot_a, out_slot_b, out_pick_a, out_pick_b,
                                           out_rad_a, out_rad_b});
    });
}

}  // extern "C"
