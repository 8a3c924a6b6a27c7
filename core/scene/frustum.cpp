#include "scene/frustum.h"

namespace grass::core {

FrustumPlanes frustumPlanes(const glm::mat4& viewProj) {
    // The rows of the matrix: glm stores columns.
    const glm::mat4 m = glm::transpose(viewProj);
    FrustumPlanes planes = {m[3] + m[0], m[3] - m[0], m[3] + m[1],
                            m[3] - m[1], m[3] + m[2], m[3] - m[2]};
    for (glm::vec4& plane : planes) {
        const float length = glm::length(glm::vec3(plane));
        // A degenerate matrix gives a zero normal: a plane that keeps everything.
        plane = length > 0.0f ? plane / length : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    }
    return planes;
}

bool sphereOutside(const FrustumPlanes& planes, glm::vec3 centre, float radius) {
    for (const glm::vec4& plane : planes)
        if (glm::dot(glm::vec3(plane), centre) + plane.w < -radius)
            return true;
    return false;
}

}  // namespace grass::core
