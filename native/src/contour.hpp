// Smooth contours (Hertzmann & Zorin 2000): the zero set of g = n . (eye - p), with g evaluated at
// vertices from vertex normals and interpolated linearly along triangle sides.
#pragma once

#include "mesh_data.hpp"
#include "view_point.hpp"

#include <vector>

namespace el {

// Appends 6 floats per segment (two object-space points) and the triangle of each segment.
void compute_contours(const MeshData& mesh, const ViewPoint& view, std::vector<float>& points,
                      std::vector<uint32_t>& triangles);

}  // namespace el
