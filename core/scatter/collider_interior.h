// Whether a point lies under a collider's surface: inside a closed one, or under one open at the
// bottom (a scanned rock sunk into the ground has no underside). The clearance rule
// (placement_rules.h) clears such roots at any distance from the surface: before, a collider
// wider than twice the clearance kept grass growing inside it, hidden, crushed for good by the
// physics (it never let the editor's field rest) and drawn by every runtime the field went to.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/bvh.h"
#include "scatter/clearance_grid.h"

namespace grass::core {

class ColliderInteriors {
public:
    ColliderInteriors() = default;  // no collider: nothing is inside
    // `triangles` in world space, collider after collider; solidEnds[k] is where collider k's
    // triangles end (ascending, the last at most triangles.size()).
    ColliderInteriors(std::span<const ClearanceGrid::Triangle> triangles,
                      std::span<const std::size_t> solidEnds);

    // Within some collider's bounding box, and the half-line from `p` along `up` crosses that
    // collider's surface an odd number of times. `up` need not be unit length; zero or
    // non-finite: nothing is inside.
    bool inside(glm::vec3 p, glm::vec3 up) const;
    bool empty() const { return mSolids.empty(); }

private:
    struct Solid {
        Bounds box;
        TriangleBvh bvh;
        float stepM = 0.0f;  // how far past a crossing the next search starts
    };
    std::vector<Solid> mSolids;
};

}  // namespace grass::core
