// Reads an OFF file (the libcgal-demo meshes the library's tests use) into flat arrays without
// assimp, so the library's tests build where assimp is not (the Windows DLL's tests under wine):
// polygons fanned into triangles, equal positions welded as the tools' assimp reader welds them
// (mesh_io.cpp), indices checked.
#pragma once

#include "mesh_io.hpp"

#include <string>

namespace el_tools {

// Throws std::runtime_error "cannot read 'PATH': REASON" (one line) when the file cannot be read
// or is not an OFF file of in-range indices and finite positions.
LoadedMesh read_off(const std::string& path);

}  // namespace el_tools
