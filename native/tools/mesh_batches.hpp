// What the passes draw for one mesh, built on the CPU as addon/extract/scene_sync.py and
// addon/passes/batches.py build it: surface corners, the rounded edges the library classifies,
// and their screen-space quads.
#pragma once

#include "mesh_io.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace el_tools {

// Corner arrays of the surface pass (3 corners per triangle; vertex_in "pos", "nor", "uv", "col").
struct SurfaceCorners {
    std::vector<float> pos, nor;  // xyz per corner
    std::vector<float> uv;        // 2 per corner, zero: this renderer draws no image (EL_BASE_TEXTURE)
    std::vector<float> col;       // 4 per corner, zero: nor a node program's colour attribute
    std::vector<float> tan;       // 4 per corner, zero: nor a Normal Map's tangent
};

// Rounded edges: manifold, not degenerate, angle between face normals above the threshold (the
// add-on's default 'ANGLE' rule). N1 is the normal of the face that runs p0 -> p1.
struct EdgeSet {
    std::vector<std::array<float, 3>> p0, p1, n1, n2;
    size_t size() const { return p0.size(); }
};

// One quad per edge, with the edge_highlight program's vertex_in (shaders/programs.json).
struct EdgeQuads {
    std::vector<float> p0, p1, n1, n2;  // 3 per vertex
    std::vector<float> corner;          // 4 per vertex: end, side, radius, shading vertex
    // 2 per vertex: the surface ids of the edge's faces, all 0 here: this renderer writes no id
    // image, and its edge program is built without EL_EDGE_IDS (depth decides visibility).
    std::vector<float> faces;
    // 4 per vertex: where the band ends on each face (the add-on's band_ends.py); square ends
    // (pi / 2) here: this renderer does not read polygons.
    std::vector<float> ends;
    // 3 per vertex each: how N1 and N2 turn along the edge (the add-on's edge_data.mean_and_turn),
    // zero here: this renderer's normals are the faces' own, constant along each edge.
    std::vector<float> turn1, turn2;
    std::vector<float> uv;          // 4 per vertex: an image's UV at p0 and p1, zero: no image here
    std::vector<float> col0, col1;  // 4 per vertex each: a colour attribute at p0 and p1, zero here
    std::vector<uint32_t> indices;  // 6 per edge
};

// Corner normals as Blender's auto smooth gives them: the angle-weighted normals of the faces
// around the corner's vertex that lie within `smooth_deg` of the corner's own face (a cube at
// 30 degrees is flat-shaded, fandisk is smooth between its creases).
SurfaceCorners surface_corners(const LoadedMesh& mesh, float smooth_deg);

// The edges above `crease_deg`, through the library's C ABI (el_mesh_classify). Throws
// std::runtime_error with the library's message.
EdgeSet choose_edges(const LoadedMesh& mesh, float crease_deg);

// Which vertex of a triangle provides its flat outputs. The renderer sets the convention with
// glProvokingVertex; the quads' triangles are ordered so the edge's shading vertex is that one.
enum class Provoking { first, last };

// Quads as passes/batches.py lays them out: every edge's shading corner (corner.w = 1, end 0,
// side -1) first in the buffer, then its other three corners edge by edge; both triangles of a
// quad start (first) or end (last) at the shading corner.
EdgeQuads edge_quads(const EdgeSet& edges, float radius, Provoking provoking);

}  // namespace el_tools
