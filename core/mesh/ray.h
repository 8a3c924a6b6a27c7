// Ray: a half-line in world space (metres), for picking meshes under the mouse (issue 8) and
// for snapping points onto surfaces. `direction` is unit length by convention; a point on the
// ray is origin + t·direction with t in metres.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace grass::core {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    glm::vec3 at(float t) const { return origin + t * direction; }
    bool operator==(const Ray&) const = default;
};

// A ray whose origin and direction are finite and whose direction is not zero: the rays the
// intersection routines answer; any other ray misses everything.
inline bool isUsableRay(const Ray& ray) {
    const glm::vec3 o = ray.origin, d = ray.direction;
    const bool finite = std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) &&
                        std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z);
    return finite && (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f);
}

}  // namespace grass::core
