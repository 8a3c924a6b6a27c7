#include "mesh/surface_ring.h"

#include <cmath>

namespace grass::core {

namespace {

// An orthonormal tangent basis without branches on a "least aligned axis" (Duff et al.,
// "Building an Orthonormal Basis, Revisited", JCGT 2017): continuous in n except at one pole,
// so the ring does not spin as the cursor slides over a smooth surface.
void tangentBasis(glm::vec3 n, glm::vec3& tangent, glm::vec3& bitangent) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    tangent = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    bitangent = glm::vec3(b, sign + n.y * n.y * a, -n.y);
}

}  // namespace

std::vector<glm::vec3> surfacePointsOnRing(const TriangleBvh& bvh, glm::vec3 centreWorld,
                                           glm::vec3 normal, float radiusM, int count) {
    if (count <= 0)
        return {};
    const auto pointCount = static_cast<std::size_t>(count);
    const float normalLength = glm::length(normal);
    if (!(radiusM > 0.0f) || !std::isfinite(radiusM) || !(normalLength > 0.0f) ||
        !std::isfinite(normalLength))
        return std::vector<glm::vec3>(pointCount, centreWorld);
    const glm::vec3 n = normal / normalLength;
    glm::vec3 tangent, bitangent;
    tangentBasis(n, tangent, bitangent);
    // (tangent, bitangent, n) is right-handed, so increasing angle turns counter-clockwise
    // seen from the normal's side.
    if (glm::dot(glm::cross(tangent, bitangent), n) < 0.0f)
        bitangent = -bitangent;
    const float probeM = RING_PROBE_HEIGHT * radiusM;
    std::vector<glm::vec3> points;
    points.reserve(pointCount);
    for (int i = 0; i < count; ++i) {
        const float angleRad = 2.0f * float(M_PI) * float(i) / float(count);
        const glm::vec3 onPlane =
            centreWorld + radiusM * (std::cos(angleRad) * tangent + std::sin(angleRad) * bitangent);
        const auto hit = bvh.intersect(Ray{onPlane + probeM * n, -n}, 2.0f * probeM);
        points.push_back(hit ? hit->posWorld : onPlane);
    }
    return points;
}

}  // namespace grass::core
