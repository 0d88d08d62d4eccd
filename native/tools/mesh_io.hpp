// Reads a mesh file (OFF, PLY, OBJ, STL, ... whatever assimp reads) into flat arrays, refusing
// what assimp cannot validate or what exceeds MeshLimits (mesh_limits.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace el_tools {

struct LoadedMesh {
    std::vector<float> positions;     // xyz
    std::vector<uint32_t> triangles;  // 3 per triangle
};

// Throws std::runtime_error "cannot read 'PATH': REASON" (one line) when the file cannot be
// read, fails assimp's validation, exceeds the limits, has an index out of range or a position
// that is not finite.
LoadedMesh load_mesh(const std::string& path);

}  // namespace el_tools
