// What flattening an imported scene would produce (every mesh once per node that references
// it, n-gons split into triangles), counted before anything is copied, so an instanced or
// inflated scene is refused instead of expanded.
#pragma once

#include <cstdint>

struct aiScene;

namespace el_tools {

struct SceneBudget {
    uint64_t vertices = 0, triangles = 0, bytes = 0;
};

// Needs a scene assimp has validated (aiProcess_ValidateDataStructure). Throws
// std::runtime_error when the flattened scene would exceed MeshLimits.
SceneBudget check_scene_budget(const aiScene& scene);

}  // namespace el_tools
