#include "scatter/collider_interior.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

namespace {

// More crossings than any collider a field grows under has: a bound on the search, not a limit
// a real mesh meets.
constexpr int MAX_CROSSINGS = 256;

}  // namespace

ColliderInteriors::ColliderInteriors(std::span<const ClearanceGrid::Triangle> triangles,
                                     std::span<const std::size_t> solidEnds) {
    std::size_t first = 0;
    for (const std::size_t listedEnd : solidEnds) {
        const std::size_t end = std::min(listedEnd, triangles.size());
        if (end <= first)
            continue;
        TriangleSoup soup;
        soup.positions.reserve(3 * (end - first));
        for (std::size_t t = first; t < end; ++t) {
            const auto base = static_cast<std::uint32_t>(soup.positions.size());
            soup.positions.insert(soup.positions.end(), triangles[t].begin(), triangles[t].end());
            soup.triangles.push_back({base, base + 1, base + 2});
        }
        first = end;
        TriangleBvh bvh(std::move(soup));
        const Bounds box = bvh.bounds();
        // Past the crossing's rounding (a few float steps of the coordinates), short of any
        // other wall (a hundredth of a millimetre on a metre-sized rock).
        const glm::vec3 far = glm::max(glm::abs(box.min), glm::abs(box.max));
        const float stepM = std::max(1e-5f * glm::length(box.size()),
                                     1e-6f * std::max({far.x, far.y, far.z, 1.0f}));
        mSolids.push_back({box, std::move(bvh), stepM});
    }
}

bool ColliderInteriors::inside(glm::vec3 p, glm::vec3 up) const {
    const float length = glm::length(up);
    if (!(length > 0.0f) || !std::isfinite(length))
        return false;
    const glm::vec3 direction = up / length;
    for (const Solid& solid : mSolids) {
        if (!solid.box.contains(p))
            continue;
        // Crossings one after another: the closest hit, then the closest past it. The hit test
        // is watertight (bvh.h): a ray through a shared edge meets the surface there once.
        int crossings = 0;
        Ray ray{p, direction};
        while (crossings < MAX_CROSSINGS) {
            const auto hit = solid.bvh.intersect(ray);
            if (!hit)
                break;
            ++crossings;
            ray.origin = hit->posWorld + solid.stepM * direction;
        }
        if (crossings % 2 == 1)
            return true;
    }
    return false;
}

}  // namespace grass::core
