// Consistent winding per connected component, so classification and facing do not depend on how
// each triangle happened to be wound in the input (imports often flip some faces).
#pragma once

#include "mesh_data.hpp"

namespace el {

// Finds which triangles to reverse; reads positions, triangles and topology, changes nothing.
// Components are connected through manifold edges only. Per component, the kept orientation is
// the one with positive signed volume when it is closed (every side on a manifold edge), else
// the one agreeing with the larger input triangle area (ties keep its lowest triangle as given).
// A non-orientable component keeps the first winding a breadth-first walk gives it.
Orientation find_orientation(const MeshData& mesh);

// Reverses the flagged triangles in place (corners 1 and 2 swap, and with them the sides'
// edges), so everything downstream reads the oriented winding.
void apply_orientation(MeshData& mesh, const Orientation& orientation);

}  // namespace el
