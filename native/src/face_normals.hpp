// Face normals and planes; zero-area triangles are flagged and get a zero normal, never NaN.
#pragma once

#include "mesh_data.hpp"

namespace el {

void compute_face_normals(const MeshData& mesh, Geometry& geom);

}  // namespace el
