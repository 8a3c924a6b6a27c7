#include "scene/motion_edit.h"

#include <algorithm>

namespace grass::core {

bool onlyMotionChanged(const Project& before, const Project& after) {
    // `after` with its motion put back as it was: any other difference is a field's.
    Project unmoved = after;
    unmoved.wind = before.wind;
    unmoved.colliders = before.colliders;
    unmoved.physics = before.physics;
    unmoved.physics.gravity = after.physics.gravity;
    unmoved.physics.gravityMode = after.physics.gravityMode;
    return unmoved == before;
}

bool sameProps(const std::vector<ColliderDesc>& before, const std::vector<ColliderDesc>& after) {
    if (before.size() != after.size())
        return false;
    for (std::size_t i = 0; i < before.size(); ++i) {
        const ColliderDesc& a = before[i];
        const ColliderDesc& b = after[i];
        if (a.shape != b.shape || a.file != b.file || a.sphereCount != b.sphereCount ||
            a.packingResolution != b.packingResolution)
            return false;
    }
    return true;
}

bool placementFollowsColliders(const Project& project) {
    return std::any_of(project.layers.begin(), project.layers.end(),
                       [](const GrassLayer& layer) { return layer.rules.clearColliders; });
}

}  // namespace grass::core
