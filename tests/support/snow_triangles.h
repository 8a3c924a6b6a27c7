// Occluder triangles for the snow depth map in tests (core::renderSnowDepthMap's input).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace grass::test {

using SnowTriangle = std::array<glm::vec3, 3>;

// A horizontal rectangle [x0, x1] × [z0, z1] at height y, as two triangles.
inline void addRect(std::vector<SnowTriangle>& out, float x0, float x1, float z0, float z1,
                    float y) {
    out.push_back({glm::vec3(x0, y, z0), glm::vec3(x1, y, z0), glm::vec3(x1, y, z1)});
    out.push_back({glm::vec3(x0, y, z0), glm::vec3(x1, y, z1), glm::vec3(x0, y, z1)});
}

}  // namespace grass::test
