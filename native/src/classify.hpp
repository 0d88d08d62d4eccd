// Static edge classification: face count type, the two face normals, the angle between them,
// convex / concave, host marks, material boundaries, degeneracy; creases by threshold. Reads the
// oriented triangles (orient.hpp).
#pragma once

#include "mesh_data.hpp"

namespace el {

// Everything that does not depend on the crease threshold.
void analyze_edges(const MeshData& mesh, Classification& cls);

// Sets EL_EDGE_CREASE where the angle between the normals exceeds the threshold (degrees).
void apply_crease_threshold(Classification& cls, float crease_angle_deg);

}  // namespace el
