// What one mesh file may ask of the tools. Importers allocate what a file claims before they
// find out it lies (assimp's OFF reader sizes its arrays from the header), so these caps are
// checked before import where a header states counts, and on the imported scene before any
// post-processing copies it. They keep a hostile or broken file to a few GB, well under a
// workstation's memory, while leaving room for scanned meshes of tens of millions of triangles.
#pragma once

#include <cstdint>

namespace el_tools {

struct MeshLimits {
    static constexpr uint64_t max_file_bytes = 2ull << 30;      // 2 GiB on disk
    static constexpr uint64_t max_vertices = 20'000'000;        // after instancing, all meshes
    static constexpr uint64_t max_triangles = 40'000'000;       // after triangulation, likewise
    static constexpr uint64_t max_geometry_bytes = 1ull << 30;  // 1 GiB of vertex + face data
};

// For --help and error messages.
inline constexpr const char* kMeshLimitsText =
    "2 GiB per file, 20 million vertices, 40 million triangles, 1 GiB of geometry";

}  // namespace el_tools
