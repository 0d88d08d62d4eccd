// The add-on's frame (addon/passes/frame.py) in plain OpenGL: per jittered sample a surface
// pass, on the first sample the edge highlight pass into a premultiplied target, and a composite
// added into the result with weight 1 / samples. Targets, pass state and the table's use come
// from shaders/passes.json, FrameData's layout from frame_data.json, as in the add-on. Needs a
// current GL 4.5 core context (OsmesaContext).
#pragma once

#include "gl_objects.hpp"
#include "mesh_batches.hpp"
#include "render_camera.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace el_tools {

// One material, as addon/extract/materials.py's Shading: Blinn-Phong surface, rounded edges.
struct Material {
    glm::vec3 base_color{0.8f};
    float alpha = 1.0f;
    glm::vec3 spec_color{0.04f};  // F0 (0.08 x Principled's default specular 0.5)
    float shininess = 30.0f;      // Blinn exponent (roughness 0.5)
    glm::vec3 tint{1.0f};
    float K = 1.0f;
    float radius = 0.01f;  // r_e, world units
};

struct Scene {
    SurfaceCorners surface;
    EdgeSet edges;
    Material material;
    std::vector<Sun> suns;
    glm::dvec3 ambient{0.05, 0.05, 0.06};  // world colour of the sample scenes
    // How the edge pass shades bands: 0 per-pixel part of the arc (the add-on's,
    // shaders/edge_band_pixel.glsl); the benchmarks' and tests' variants
    // (bench/shaders/edge_methods.json): 1 the whole visible arc's mean everywhere (what
    // el_highlight_reference computes for one point), 2 the paper's 1-pixel line, 3 as 0 by
    // brute-force quadrature.
    int edge_method = 0;
    // The edge pass depth-tests its quads against the surface pass so hidden pixels skip the
    // fragment shader (its state in shaders/passes.json); off only to check that this rejects
    // nothing the shader's own visibility test keeps.
    bool edge_depth_test = true;
    // Edge quads fitted to the side of the line where the band lies (as the add-on draws them);
    // off only to check that against quads symmetric about the line.
    bool tight_edge_quads = true;
    // Benchmark only: the edge pass with a fragment shader that does next to nothing
    // (EL_EDGE_FLOOR), what its quads cost before any shading.
    bool edge_floor = false;
};

// Float buffers read back after the last sample, rows bottom-up (GL order).
struct Images {
    int width = 0, height = 0;
    std::vector<float> result;     // RGBA, scene-linear
    std::vector<float> surface;    // RGBA of the last sample
    std::vector<float> highlight;  // RGBA premultiplied (W Is, W), first (unjittered) sample
    std::vector<float> inv_depth;  // 1 / view depth of the last sample, 0 = empty
};

class Renderer {
public:
    // Compiles surface, edge_highlight and composite from `shader_dir` (programs.json).
    explicit Renderer(const std::string& shader_dir);
    ~Renderer();
    // Uploads the scene, draws one frame and reads it back.
    Images render(const Scene& scene, const Camera& camera, int samples);

    // A scene's vertex buffers and the render targets of the last size drawn: uploaded once and
    // drawn in many frames, as the add-on's cached batches are (the pass benchmark's frames).
    // Keeps a reference to the scene, which must outlive it.
    class Uploaded;
    struct UploadedDelete {
        void operator()(Uploaded* u) const;
    };
    using UploadedPtr = std::unique_ptr<Uploaded, UploadedDelete>;
    UploadedPtr upload(const Scene& scene);
    // One frame, left in the GPU (glFinish'ed, nothing read back).
    void draw(Uploaded& uploaded, const Camera& camera, int samples);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace el_tools
