#include "blade/blade.h"

#include <cmath>
#include <utility>

namespace grass::core {

namespace {

// The tangent-plane basis (t, b) theta is measured in: t from a reference axis not parallel to
// up.
std::pair<glm::vec3, glm::vec3> tangentBasis(glm::vec3 up) {
    const glm::vec3 reference = std::abs(up.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(reference, up));
    return {t, glm::cross(up, t)};
}

}  // namespace

glm::vec3 widthDirection(glm::vec3 up, float theta) {
    const auto [t, b] = tangentBasis(up);
    return std::cos(theta) * t + std::sin(theta) * b;
}

float widthAngle(glm::vec3 up, glm::vec3 direction) {
    const auto [t, b] = tangentBasis(up);
    return std::atan2(glm::dot(direction, b), glm::dot(direction, t));
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
