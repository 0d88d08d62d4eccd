#include "render_camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace el_tools {
namespace {

std::vector<float> floats(const glm::dmat4& m) {
    std::vector<float> out;
    for (int c = 0; c < 4; ++c) {  // glm is column-major, as std140 wants
        for (int r = 0; r < 4; ++r) out.push_back(float(m[c][r]));
    }
    return out;
}

std::vector<float> floats(double x, double y, double z, double w) { return {float(x), float(y), float(z), float(w)}; }

double halton(int i, int base) {
    double f = 1.0, r = 0.0;
    while (i > 0) {
        f /= base;
        r += f * (i % base);
        i /= base;
    }
    return r;
}

}  // namespace

glm::dvec3 Camera::view_dir() const { return glm::normalize(target - eye); }

glm::dmat4 Camera::view() const {
    glm::dvec3 up(0.0, 0.0, 1.0);
    if (glm::length(glm::cross(view_dir(), up)) < 1e-6) up = glm::dvec3(0.0, 1.0, 0.0);  // looking straight down
    return glm::lookAt(eye, target, up);
}

glm::dmat4 Camera::projection() const {
    const double f = 1.0 / std::tan(glm::radians(fov_deg) * 0.5);
    const double aspect = double(width) / double(height);
    glm::dmat4 p = glm::perspective(glm::radians(fov_deg), aspect, clip_start, clip_end);
    // Sensor fit AUTO: the field of view spans the larger side.
    p[0][0] = width >= height ? f : f / aspect;
    p[1][1] = width >= height ? f * aspect : f;
    return p;
}

double Camera::px_per_unit() const { return projection()[0][0] * width / 2.0; }

glm::dvec2 jitter(int sample) {
    if (sample == 0) return {0.0, 0.0};
    return {halton(sample, 2) - 0.5, halton(sample, 3) - 0.5};
}

glm::dmat4 jittered_projection(const glm::dmat4& projection, int width, int height, glm::dvec2 d) {
    glm::dmat4 t(1.0);
    t[3][0] = 2.0 * d.x / width;
    t[3][1] = 2.0 * d.y / height;
    return t * projection;
}

std::vector<float> frame_data(const Block& layout, const Camera& camera, const glm::dmat4& projection,
                              const std::vector<Sun>& suns, const glm::dvec3& ambient) {
    const int max_lights = layout.define("EL_MAX_LIGHTS");
    if (suns.size() > size_t(max_lights)) throw std::invalid_argument("at most " + std::to_string(max_lights) + " lights");
    std::vector<float> out = layout.zeros();
    layout.set(out, "view", floats(camera.view()));
    layout.set(out, "projection", floats(projection));
    layout.set(out, "eye", floats(camera.eye.x, camera.eye.y, camera.eye.z, 1.0));  // w = 1: perspective
    const glm::dvec3 d = camera.view_dir();
    layout.set(out, "view_dir", floats(d.x, d.y, d.z, 0.0));
    layout.set(out, "viewport", floats(camera.width, camera.height, 1.0 / camera.width, 1.0 / camera.height));
    layout.set(out, "ambient", floats(ambient.x, ambient.y, ambient.z, 1.0));
    layout.set(out, "camera", floats(camera.px_per_unit(), double(suns.size()), 0.0, 0.0));
    const double sun = layout.define("EL_LIGHT_SUN");
    for (size_t i = 0; i < suns.size(); ++i) {
        const glm::dvec3 dir = -glm::normalize(suns[i].to_light);  // where the light points
        layout.set(out, "light_color", floats(suns[i].color.x, suns[i].color.y, suns[i].color.z, sun), i);
        layout.set(out, "light_direction", floats(dir.x, dir.y, dir.z, 0.0), i);
    }
    return out;
}

Box bounding_box(const std::vector<float>& xyz) {
    Box b{glm::dvec3(std::numeric_limits<double>::infinity()), glm::dvec3(-std::numeric_limits<double>::infinity())};
    for (size_t i = 0; i < xyz.size(); ++i) {
        b.lo[int(i % 3)] = std::min(b.lo[int(i % 3)], double(xyz[i]));
        b.hi[int(i % 3)] = std::max(b.hi[int(i % 3)], double(xyz[i]));
    }
    return b;
}

}  // namespace el_tools
