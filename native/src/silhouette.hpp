// Silhouettes: manifold edges whose two faces face differently. Facing is one bit per face, so
// a new view first recomputes the bits and touches edges only if a bit flipped.
#pragma once

#include "mesh_data.hpp"
#include "view_point.hpp"

#include <cstdint>
#include <vector>

namespace el {

// 1 bit per face, 64 per word.
void compute_facing(const MeshData& mesh, const ViewPoint& view, std::vector<uint64_t>& bits);

// Number of faces whose bit differs.
uint64_t count_flips(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b);

// Ascending indices of manifold, non-degenerate edges whose faces' bits differ.
void collect_silhouettes(const MeshData& mesh, const std::vector<uint64_t>& bits, std::vector<uint32_t>& out);

inline bool facing_bit(const std::vector<uint64_t>& bits, uint32_t face) {
    return (bits[face >> 6] >> (face & 63)) & 1u;
}

}  // namespace el
