// Angle-weighted vertex normals (Thürmer & Wüthrich) for smooth contours, when the host has none.
#pragma once

#include "mesh_data.hpp"

namespace el {

void compute_vertex_normals(const MeshData& mesh, Geometry& geom);

}  // namespace el
