#include "mesh_io.hpp"

#include "mesh_precheck.hpp"
#include "scene_budget.hpp"

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <edgelight/edgelight.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unordered_map>

namespace el_tools {
namespace {

// Assimp's messages may span lines; the tools print one.
std::string one_line(std::string s) {
    std::replace_if(s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

struct KeyHash {
    size_t operator()(const std::array<uint32_t, 3>& k) const {
        return (size_t(k[0]) * 73856093u) ^ (size_t(k[1]) * 19349663u) ^ (size_t(k[2]) * 83492791u);
    }
};

// Loaders that meet an index out of range clamp it and say so only in assimp's log (OFF:
// "Vertex index is out of range"): the file is refused instead, as a face that uses a vertex
// the file does not have. Other logged errors (a missing material file, an unsupported chunk)
// are no reason to refuse a mesh.
class RangeErrors : public Assimp::LogStream {
public:
    RangeErrors() {
        Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
        Assimp::DefaultLogger::get()->attachStream(this, Assimp::Logger::Err);
    }
    ~RangeErrors() override {
        Assimp::DefaultLogger::get()->detachStream(this, Assimp::Logger::Err);
        Assimp::DefaultLogger::kill();
    }
    void write(const char* message) override {
        if (!first.empty() || !std::strstr(message, "out of range")) return;
        first = one_line(message);
        const size_t tag = first.rfind("Error, T", 0) == 0 ? first.find(": ") : std::string::npos;
        if (tag != std::string::npos) first.erase(0, tag + 2);  // "Error, T0: OFF: ..." -> "OFF: ..."
    }
    std::string first;
};

// Appends the triangles of a flattened scene, refusing what the library must never see, and
// welds equal positions across the scene's meshes (a per-face STL, an OBJ split by material).
void append_mesh(const aiMesh& mesh, LoadedMesh& out, std::unordered_map<std::array<uint32_t, 3>, uint32_t, KeyHash>& welded) {
    if (mesh.mNumVertices > 0 && !mesh.mVertices) throw std::runtime_error("a mesh has no positions");
    std::vector<uint32_t> index(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::runtime_error("a vertex is not finite");
        if (!(std::fabs(p.x) <= EL_MAX_COORDINATE && std::fabs(p.y) <= EL_MAX_COORDINATE &&
              std::fabs(p.z) <= EL_MAX_COORDINATE))
            throw std::runtime_error("a vertex lies farther than EL_MAX_COORDINATE (1e15) from the origin");
        const float xyz[3] = {p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};  // + 0: -0 and 0 weld
        std::array<uint32_t, 3> key;
        std::memcpy(key.data(), xyz, sizeof xyz);
        const auto [at, added] = welded.try_emplace(key, uint32_t(out.positions.size() / 3));
        if (added) out.positions.insert(out.positions.end(), {xyz[0], xyz[1], xyz[2]});
        index[v] = at->second;
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
        for (int k = 0; k < 3; ++k) {
            if (face.mIndices[k] >= mesh.mNumVertices)
                throw std::runtime_error("a face uses vertex " + std::to_string(face.mIndices[k]) + " of a mesh with " +
                                         std::to_string(mesh.mNumVertices));
            out.triangles.push_back(index[face.mIndices[k]]);
        }
    }
}

LoadedMesh import(const std::string& path) {
    Assimp::Importer importer;
    precheck_mesh_file(path, importer.IsExtensionSupported(std::filesystem::path(path).extension().string()));

    // Validation first, alone: loaders can leave scenes (null nodes, dangling indices) that
    // crash later steps, and the budget needs a sound scene to count.
    RangeErrors range_errors;
    if (!importer.ReadFile(path, aiProcess_ValidateDataStructure)) throw std::runtime_error(importer.GetErrorString());
    if (!range_errors.first.empty()) throw std::runtime_error(range_errors.first);
    const SceneBudget budget = check_scene_budget(*importer.GetScene());

    // Drop what never reaches the library before the copies are made (normals, colours and
    // texture coordinates too: joining identical vertices compares them, and a file with
    // per-corner normals would keep every corner apart); join identical vertices, and bake
    // node transforms; never let assimp invent normals or fix winding: the library must see
    // the file as it is. append_mesh welds equal positions across meshes.
    // aiProcess_FindInvalidData is left out: it silently deletes a mesh whose positions are
    // not finite, where the file should be refused (append_mesh does).
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                                aiComponent_ANIMATIONS | aiComponent_TEXTURES | aiComponent_LIGHTS | aiComponent_CAMERAS |
                                    aiComponent_BONEWEIGHTS | aiComponent_NORMALS | aiComponent_COLORS |
                                    aiComponent_TEXCOORDS | aiComponent_TANGENTS_AND_BITANGENTS);
    const unsigned flags = aiProcess_RemoveComponent | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                           aiProcess_PreTransformVertices;
    const aiScene* scene = importer.ApplyPostProcessing(flags);
    if (!scene) throw std::runtime_error(importer.GetErrorString());

    LoadedMesh out;
    out.positions.reserve(3 * budget.vertices);
    out.triangles.reserve(3 * budget.triangles);
    std::unordered_map<std::array<uint32_t, 3>, uint32_t, KeyHash> welded;
    welded.reserve(budget.vertices);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) append_mesh(*scene->mMeshes[m], out, welded);
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
