#include "scene_budget.hpp"

#include "mesh_limits.hpp"

#include <assimp/scene.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace el_tools {
namespace {

// One instance of a mesh, roughly as assimp stores it: positions and whatever other vertex
// streams the file has, the faces and their indices.
SceneBudget mesh_cost(const aiMesh& m) {
    SceneBudget c;
    c.vertices = m.mNumVertices;
    uint64_t per_vertex = sizeof(aiVector3D);
    if (m.mNormals) per_vertex += sizeof(aiVector3D);
    if (m.mTangents) per_vertex += 2 * sizeof(aiVector3D);
    for (unsigned k = 0; k < AI_MAX_NUMBER_OF_COLOR_SETS; ++k)
        if (m.mColors[k]) per_vertex += sizeof(aiColor4D);
    for (unsigned k = 0; k < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++k)
        if (m.mTextureCoords[k]) per_vertex += sizeof(aiVector3D);
    c.bytes = c.vertices * per_vertex + uint64_t(m.mNumFaces) * sizeof(aiFace);
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const unsigned n = m.mFaces[f].mNumIndices;
        c.bytes += uint64_t(n) * sizeof(unsigned);
        c.triangles += n >= 3 ? n - 2 : 0;
    }
    return c;
}

}  // namespace

SceneBudget check_scene_budget(const aiScene& scene) {
    std::vector<SceneBudget> per_mesh(scene.mNumMeshes);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) per_mesh[m] = mesh_cost(*scene.mMeshes[m]);

    SceneBudget total;
    uint64_t nodes = 0;
    std::vector<const aiNode*> stack{scene.mRootNode};  // explicit: a deep graph must not overflow
    while (!stack.empty()) {
        const aiNode* node = stack.back();
        stack.pop_back();
        // A tree has no more nodes than this without meshes to show for them.
        if (++nodes > MeshLimits::max_vertices) throw std::runtime_error("scene graph has too many nodes");
        for (unsigned i = 0; i < node->mNumMeshes; ++i) {
            const SceneBudget& c = per_mesh[node->mMeshes[i]];  // index checked by validation
            total.vertices += c.vertices;
            total.triangles += c.triangles;
            total.bytes += c.bytes;
        }
        // Checked as it grows: a node instancing a mesh a billion times stops here early.
        if (total.vertices > MeshLimits::max_vertices || total.triangles > MeshLimits::max_triangles ||
            total.bytes > MeshLimits::max_geometry_bytes) {
            throw std::runtime_error("scene has more than the limit (" + std::string(kMeshLimitsText) +
                                     "): " + std::to_string(total.vertices) + " vertices, " +
                                     std::to_string(total.triangles) + " triangles, " +
                                     std::to_string(total.bytes) + " bytes so far");
        }
        for (unsigned i = 0; i < node->mNumChildren; ++i) stack.push_back(node->mChildren[i]);
    }
    return total;
}

}  // namespace el_tools
