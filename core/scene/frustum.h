// The view frustum as six planes, for culling on the CPU (the billboards' clusters, the stem
// sets): Gribb and Hartmann's extraction from an OpenGL view-projection matrix.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace grass::core {

// Left, right, bottom, top, near, far; each normalised so that dot(plane.xyz, p) + plane.w is
// the signed distance of p, positive inside.
using FrustumPlanes = std::array<glm::vec4, 6>;

FrustumPlanes frustumPlanes(const glm::mat4& viewProj);

// True when the sphere lies wholly outside one of the planes (conservative: a sphere outside
// the frustum only near a corner is kept).
bool sphereOutside(const FrustumPlanes& planes, glm::vec3 centre, float radius);

}  // namespace grass::core
