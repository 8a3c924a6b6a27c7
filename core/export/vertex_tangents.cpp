#include "export/vertex_tangents.h"

#include <cmath>

namespace grass::core {

namespace {

// Any unit vector perpendicular to unit `n`.
glm::vec3 perpendicular(glm::vec3 n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, n));
}

}  // namespace

std::vector<glm::vec4> vertexTangents(const std::vector<glm::vec3>& positions,
                                      const std::vector<glm::vec3>& normals,
                                      const std::vector<glm::vec2>& uvs,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    std::vector<glm::vec3> uDirections(positions.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> vDirections(positions.size(), glm::vec3(0.0f));
    for (const auto& t : triangles) {
        const glm::vec3 e1 = positions[t[1]] - positions[t[0]], e2 = positions[t[2]] - positions[t[0]];
        const glm::vec2 d1 = uvs[t[1]] - uvs[t[0]], d2 = uvs[t[2]] - uvs[t[0]];
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!std::isfinite(det) || std::abs(det) < 1e-20f)
            continue;
        // Solve [e1 e2] = [dp/du dp/dv] · [d1 d2]; scaling by |det| (not 1/det) keeps the sum
        // area-weighted and the sign of each direction.
        const float sign = det > 0.0f ? 1.0f : -1.0f;
        const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) * sign;
        const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) * sign;
        for (const std::uint32_t v : t) {
            uDirections[v] += dpdu;
            vDirections[v] += dpdv;
        }
    }
    std::vector<glm::vec4> tangents(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3 n = normals[i];
        glm::vec3 t = uDirections[i] - n * glm::dot(n, uDirections[i]);
        const float length = glm::length(t);
        if (!(length > 1e-12f) || !std::isfinite(length)) {
            tangents[i] = glm::vec4(perpendicular(n), 1.0f);
            continue;
        }
        t /= length;
        const float w = glm::dot(glm::cross(n, t), vDirections[i]) < 0.0f ? -1.0f : 1.0f;
        tangents[i] = glm::vec4(t, w);
    }
    return tangents;
}

}  // namespace grass::core
