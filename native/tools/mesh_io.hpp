// Reads a mesh file (OFF, PLY, OBJ, STL, ... whatever assimp reads) into flat arrays.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace el_tools {

struct LoadedMesh {
    std::vector<float> positions;    // xyz
    std::vector<uint32_t> triangles; // 3 per triangle
};

// Throws std::runtime_error with assimp's message when the file cannot be read.
LoadedMesh load_mesh(const std::string& path);

}  // namespace el_tools
