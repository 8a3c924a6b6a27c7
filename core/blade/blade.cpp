#include "blade/blade.h"

#include <cmath>

namespace grass::core {

glm::vec3 widthDirection(glm::vec3 up, float theta) {
    // A reference axis not parallel to up, then the tangent plane basis (t, b) and the rotation.
    const glm::vec3 reference = std::abs(up.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(reference, up));
    const glm::vec3 b = glm::cross(up, t);
    return std::cos(theta) * t + std::sin(theta) * b;
}

Blade makeRestBlade(glm::vec3 v0, glm::vec3 up, float h, float w, float s, float theta) {
    Blade blade;
    const glm::vec3 tip = v0 + h * up;
    blade.v0Theta = glm::vec4(v0, theta);
    blade.v1H = glm::vec4(tip, h);
    blade.v2W = glm::vec4(tip, w);
    blade.upS = glm::vec4(up, s);
    return blade;
}

}  // namespace grass::core
