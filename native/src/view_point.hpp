// The camera as seen from the object: an eye point (perspective) or a direction towards the
// viewer (orthographic), in object space. Facing tests there equal the world-space ones because
// normals transform by the inverse transpose (also under mirroring).
#pragma once

#include <glm/vec3.hpp>

namespace el {

struct ViewPoint {
    bool orthographic = false;
    glm::vec3 eye{0.0f};        // perspective
    glm::vec3 to_viewer{0.0f};  // orthographic, unit

    bool operator==(const ViewPoint&) const = default;

    // Positive where a surface with normal n at point p faces the viewer.
    float facing(const glm::vec3& n, const glm::vec3& p) const;
};

}  // namespace el
