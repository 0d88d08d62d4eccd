// Checks every pointer, count, index and value of an el_mesh_desc before anything is built.
#pragma once

#include <edgelight/edgelight.h>

namespace el {

// Throws el::Error naming the first problem found.
void validate_mesh_desc(const el_mesh_desc& desc);

}  // namespace el
