#include "scene/motion_edit.h"

#include <algorithm>

namespace grass::core {

bool onlyMotionChanged(const Project& before, const Project& after) {
    if (before.colliders.size() != after.colliders.size())
        return false;
    // `after` with its motion put back as it was: any other difference is a field's.
    Project unmoved = after;
    unmoved.wind = before.wind;
    for (std::size_t i = 0; i < unmoved.colliders.size(); ++i) {
        ColliderDesc& collider = unmoved.colliders[i];
        const ColliderDesc& was = before.colliders[i];
        collider.name = was.name;
        collider.position = was.position;
        collider.radiusM = was.radiusM;
        collider.scale = was.scale;
        collider.path = was.path;
        collider.color = was.color;
    }
    return unmoved == before;
}

bool placementFollowsColliders(const Project& project) {
    return std::any_of(project.layers.begin(), project.layers.end(),
                       [](const GrassLayer& layer) { return layer.rules.clearColliders; });
}

}  // namespace grass::core
