// Builds a MeshData from a validated description: copy, topology, orientation,
// normals, classification.
#pragma once

#include "mesh_data.hpp"

#include <memory>

namespace el {

std::shared_ptr<MeshData> build_mesh(const el_mesh_desc& desc);

}  // namespace el
