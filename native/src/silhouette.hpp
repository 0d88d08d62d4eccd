// Silhouettes: manifold edges whose two faces face differently. Facing is one byte per face, so
// a new view first recomputes the bits and touches edges only if a bit flipped.
#pragma once

#include "mesh_data.hpp"
#include "view_point.hpp"

#include <cstdint>
#include <vector>

namespace el {

// 1 (front) or 0 per face; padding faces are 0.
void compute_facing(const MeshData& mesh, const ViewPoint& view, std::vector<uint8_t>& facing);

// Number of faces whose facing differs.
uint64_t count_flips(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

// Ascending indices of manifold, non-degenerate edges whose faces face differently.
void collect_silhouettes(const MeshData& mesh, const std::vector<uint8_t>& facing, std::vector<uint32_t>& out);

}  // namespace el
