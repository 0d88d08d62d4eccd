#include "mesh_io.hpp"

#include "mesh_precheck.hpp"
#include "scene_budget.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace el_tools {
namespace {

// Assimp's messages may span lines; the tools print one.
std::string one_line(std::string s) {
    std::replace_if(s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

// Appends the triangles of a flattened scene, refusing what the library must never see.
void append_mesh(const aiMesh& mesh, LoadedMesh& out) {
    if (mesh.mNumVertices > 0 && !mesh.mVertices) throw std::runtime_error("a mesh has no positions");
    const uint32_t base = uint32_t(out.positions.size() / 3);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::runtime_error("vertex " + std::to_string(base + v) + " is not finite");
        out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
        for (int k = 0; k < 3; ++k) {
            if (face.mIndices[k] >= mesh.mNumVertices)
                throw std::runtime_error("a face uses vertex " + std::to_string(face.mIndices[k]) + " of a mesh with " +
                                         std::to_string(mesh.mNumVertices));
            out.triangles.push_back(base + face.mIndices[k]);
        }
    }
}

LoadedMesh import(const std::string& path) {
    Assimp::Importer importer;
    precheck_mesh_file(path, importer.IsExtensionSupported(std::filesystem::path(path).extension().string()));

    // Validation first, alone: loaders can leave scenes (null nodes, dangling indices) that
    // crash later steps, and the budget needs a sound scene to count.
    if (!importer.ReadFile(path, aiProcess_ValidateDataStructure)) throw std::runtime_error(importer.GetErrorString());
    const SceneBudget budget = check_scene_budget(*importer.GetScene());

    // Drop what never reaches the library before the copies are made. Then join identical
    // vertices so per-face files (STL) get shared topology, and bake node transforms; never
    // let assimp invent normals or fix winding: the library must see the file as it is.
    // aiProcess_FindInvalidData is left out: it silently deletes a mesh whose positions are
    // not finite, where the file should be refused (append_mesh does).
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_ANIMATIONS | aiComponent_TEXTURES |
                                                            aiComponent_LIGHTS | aiComponent_CAMERAS |
                                                            aiComponent_BONEWEIGHTS);
    const unsigned flags = aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                           aiProcess_PreTransformVertices;
    const aiScene* scene = importer.ApplyPostProcessing(flags);
    if (!scene) throw std::runtime_error(importer.GetErrorString());

    LoadedMesh out;
    out.positions.reserve(3 * budget.vertices);
    out.triangles.reserve(3 * budget.triangles);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) append_mesh(*scene->mMeshes[m], out);
    if (out.positions.empty()) throw std::runtime_error("no vertices");
    return out;
}

}  // namespace

LoadedMesh load_mesh(const std::string& path) {
    try {
        return import(path);
    } catch (const std::bad_alloc&) {
        throw std::runtime_error("cannot read '" + path + "': out of memory");
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot read '" + path + "': " + one_line(e.what()));
    }
}

}  // namespace el_tools
