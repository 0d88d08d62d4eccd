// The camera, lights and the FrameData uniform block: its members as shaders/frame_data.json
// lays them out, filled as addon/passes/frame.py's frame_data() fills them (column-major
// matrices).
#pragma once

#include "typedef_spec.hpp"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace el_tools {

// A perspective camera looking from `eye` at `target` with +Z up (Blender's to_track_quat('-Z',
// 'Y') on a camera aimed at a point). fov_deg spans the larger image side (Blender's sensor fit
// AUTO: a 50 mm lens on its 36 mm sensor is 39.6 degrees).
struct Camera {
    glm::dvec3 eye{0.0}, target{0.0};
    double fov_deg = 39.5977;
    int width = 640, height = 480;
    double clip_start = 0.1, clip_end = 100.0;

    glm::dmat4 view() const;        // world -> view
    glm::dmat4 projection() const;  // view -> clip (OpenGL, depth -1..1)
    glm::dvec3 view_dir() const;    // unit, where the camera looks
    // Pixels per world unit at distance 1: FrameData.camera.x, and the K that gives true pixel
    // coverage in the reference (docs/highlight_math.md).
    double px_per_unit() const;
};

// A sun: `to_light` points towards it (the reference's el_highlight_input.light); `color` is
// colour x strength (irradiance, as Cycles).
struct Sun {
    glm::dvec3 to_light{0.0, 0.0, 1.0};
    glm::dvec3 color{3.0};
};

// Sub-pixel offset of sample s (Halton 2, 3; sample 0 is the pixel centre), as passes/camera.py's jitter().
glm::dvec2 jitter(int sample);
// projection moved by (dx, dy) pixels, as passes/camera.py's jittered_projection().
glm::dmat4 jittered_projection(const glm::dmat4& projection, int width, int height, glm::dvec2 d);

// Axis-aligned bounds of xyz triples (what cameras frame).
struct Box {
    glm::dvec3 lo, hi;
    glm::dvec3 centre() const { return 0.5 * (lo + hi); }
    double diagonal() const { return glm::length(hi - lo); }
};
Box bounding_box(const std::vector<float>& xyz);

// The FrameData block's floats; `layout` is shaders/frame_data.json's. Throws past its
// EL_MAX_LIGHTS lights.
std::vector<float> frame_data(const Block& layout, const Camera& camera, const glm::dmat4& projection,
                              const std::vector<Sun>& suns, const glm::dvec3& ambient);

}  // namespace el_tools
