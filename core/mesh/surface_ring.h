// The brush cursor's outline lying on the surface (issue 8): a circle of radius r in the tangent
// plane at a surface point, each point snapped onto the mesh along the normal. World space,
// metres.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "mesh/bvh.h"

namespace grass::core {

// How far above and below the tangent plane a ring point looks for the surface, as a multiple
// of the radius: the surface may bend away from the tangent plane by about that much within
// the ring (hills, the bunny's back) before a point falls back to the plane.
constexpr float RING_PROBE_HEIGHT = 1.0f;

// `count` points at equal angles (the first along an arbitrary but fixed tangent direction,
// counter-clockwise seen from the normal's side). Point i lies on the circle in the tangent
// plane, then is replaced by the first surface hit of a ray from point + normal·r·k towards
// −normal (k = RING_PROBE_HEIGHT, hits up to 2·r·k away); on a miss it stays in the tangent
// plane. `normal` need not be normalized; count ≤ 0 gives no points; a zero or non-finite
// normal or radius gives `count` copies of the centre.
std::vector<glm::vec3> surfacePointsOnRing(const TriangleBvh& bvh, glm::vec3 centreWorld,
                                           glm::vec3 normal, float radiusM, int count);

}  // namespace grass::core
