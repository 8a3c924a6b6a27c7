// The per-blade cull rules of SPEC §6 that are plain formulas, on the CPU: a twin of
// shaders/include/cull_rules.glsl (which shaders/cull.comp runs), same names and argument order,
// so unit tests pin them (tests/core/scene/cull_rules_test.cpp) and a GL test runs the GLSL on
// the same inputs (tests/gl/formula_twins_gl_test.cpp). Directions are unit vectors in one
// space (world); distances metres.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace grass::core {

// ORIENTATION_CULL_COS in shaders/include/cull_rules.glsl: SPEC §6's 0.9. A blade whose width
// direction is within acos(0.9) ≈ 25.8° of the view direction is seen edge-on.
inline constexpr float ORIENTATION_CULL_COS = 0.9f;

// Orientation: true (cull) when |dirView · dirWidth| > ORIENTATION_CULL_COS, a blade seen
// edge-on, thinner than a pixel; it would only alias. dirView: camera to root; dirWidth: the
// blade's width direction (core::widthDirection).
bool seenEdgeOn(glm::vec3 dirView, glm::vec3 dirWidth);

// dproj = |toBlade − up (toBlade · up)|: the camera-to-root vector with its part along the
// blade's unit up removed, so a blade straight below the camera counts as near.
float projectedDistance(glm::vec3 toBlade, glm::vec3 up);

// Distance thinning: of each `classes` (n ≥ 1) blades, ceil(n·max(1 − dproj/maxDistance, 0))
// are kept: all at the camera, at least one until maxDistance, none from there on.
// maxDistance > 0 (the cull pass sends at least 1e-3 m).
std::uint32_t distanceKeptCount(std::uint32_t classes, float dproj, float maxDistance);

// Blade `index` survives distance thinning when index mod n < distanceKeptCount(n, ...).
bool keptByDistance(std::uint32_t index, std::uint32_t classes, float dproj, float maxDistance);

}  // namespace grass::core
