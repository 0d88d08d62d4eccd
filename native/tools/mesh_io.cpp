#include "mesh_io.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <stdexcept>

namespace el_tools {

LoadedMesh load_mesh(const std::string& path) {
    Assimp::Importer importer;
    // Join identical vertices so per-face files (STL) get shared topology; bake node transforms;
    // never let assimp invent normals or fix winding: the library must see the file as it is.
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene) throw std::runtime_error("cannot read '" + path + "': " + importer.GetErrorString());
    LoadedMesh out;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        const uint32_t base = uint32_t(out.positions.size() / 3);
        for (unsigned v = 0; v < mesh->mNumVertices; ++v)
            out.positions.insert(out.positions.end(), {mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z});
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
            for (int k = 0; k < 3; ++k) out.triangles.push_back(base + face.mIndices[k]);
        }
    }
    if (out.positions.empty()) throw std::runtime_error("'" + path + "' has no vertices");
    return out;
}

}  // namespace el_tools
