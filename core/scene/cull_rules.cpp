#include "scene/cull_rules.h"

#include <algorithm>
#include <cmath>

#include "util/assert.h"

namespace grass::core {

// Each function transcribes its GLSL namesake; keep them so, or the GL test fails.

bool seenEdgeOn(glm::vec3 dirView, glm::vec3 dirWidth) {
    return std::abs(glm::dot(dirView, dirWidth)) > ORIENTATION_CULL_COS;
}

float projectedDistance(glm::vec3 toBlade, glm::vec3 up) {
    return glm::length(toBlade - up * glm::dot(toBlade, up));
}

std::uint32_t distanceKeptCount(std::uint32_t classes, float dproj, float maxDistance) {
    GRASS_ASSERT(classes >= 1 && maxDistance > 0.0f);
    const float n = static_cast<float>(classes);
    return static_cast<std::uint32_t>(std::ceil(n * std::max(1.0f - dproj / maxDistance, 0.0f)));
}

bool keptByDistance(std::uint32_t index, std::uint32_t classes, float dproj, float maxDistance) {
    return index % classes < distanceKeptCount(classes, dproj, maxDistance);
}

}  // namespace grass::core
