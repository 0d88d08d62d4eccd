// Smooth contours (Hertzmann & Zorin 2000): the zero set of g = n . (eye - p), with g evaluated at
// vertices from vertex normals and interpolated linearly along triangle sides.
#pragma once

#include "mesh_data.hpp"
#include "view_point.hpp"

#include <vector>

namespace el {

// Writes 6 floats per segment (two object-space points), the triangle of each segment, and per
// endpoint a key naming the triangle side it lies on (lower vertex << 32 | higher), for chaining.
void compute_contours(const MeshData& mesh, const ViewPoint& view, std::vector<float>& points,
                      std::vector<uint32_t>& triangles, std::vector<uint64_t>& keys);

}  // namespace el
