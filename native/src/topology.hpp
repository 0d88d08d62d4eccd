// Unique edges and edge -> face adjacency: built from the triangle list, or taken from the host.
#pragma once

#include "mesh_data.hpp"

namespace el {

// From triangles alone: edges run lower -> higher vertex index, numbered in (lower, higher) order.
// Sides joining a vertex to itself (a repeated corner) map to EL_NO_EDGE.
Topology build_topology(const uint32_t* triangles, uint32_t triangle_count, uint32_t vertex_count);

// From the host's (validated) edges and triangle -> edge map: only the adjacency is built.
Topology adopt_host_topology(const uint32_t* edges, uint32_t edge_count, const uint32_t* triangle_edges,
                             uint32_t triangle_count);

}  // namespace el
