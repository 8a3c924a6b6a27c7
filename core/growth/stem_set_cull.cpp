#include "growth/stem_set_cull.h"

#include <algorithm>
#include <cmath>

#include "blade/blade_draw_commands.h"
#include "scene/cull_rules.h"
#include "scene/frustum.h"

namespace grass::core {

std::size_t StemSetCullResult::drawn() const {
    std::size_t n = 0;
    for (const auto& list : visible)
        n += list.size();
    return n;
}

float stemSetBoundRadius(const StemSetInstance& set, int levels) {
    const int n = std::clamp(levels, 1, MAX_STEM_LEVELS);
    const float alpha = std::abs(set.alphaBetaThetaB.x), beta = std::abs(set.alphaBetaThetaB.y);
    const float spreadX = std::abs(set.halfWidthSpread.y), spreadZ = std::abs(set.halfWidthSpread.z);
    // Each level adds β^i along the rotated stem and at most spreadZ to z: the bend plane's
    // point never gets farther than the sum of the steps.
    float reach = 0.0f, power = 1.0f;
    for (int i = 1; i <= n; ++i) {
        power *= beta;
        reach += power + spreadZ;
    }
    const float across = 0.5f * alpha + spreadX;
    const float model = std::sqrt(reach * reach + across * across) + std::abs(set.halfWidthSpread.x);
    return std::abs(set.rootMetresPerUnit.w) * model;
}

int stemSetLod(float distanceM, float lodDistanceM) {
    return bladeLod(distanceM, lodDistanceM);
}

void cullStemSets(std::span<const StemSetInstance> sets, int levels, const glm::mat4& viewProj,
                  glm::vec3 cameraPosition, const StemSetCullSettings& settings,
                  StemSetCullResult& out) {
    for (auto& list : out.visible)
        list.clear();
    out.setsIn = out.culledFrustum = out.culledDistance = 0;
    const FrustumPlanes planes = frustumPlanes(viewProj);
    const auto classes = static_cast<std::uint32_t>(std::max(settings.distanceClasses, 1));
    const auto keepEvery = static_cast<std::uint32_t>(std::max(settings.keepEvery, 1));
    for (std::uint32_t i = 0; i < sets.size(); ++i) {
        const StemSetInstance& set = sets[i];
        if (!(set.rootMetresPerUnit.w > 0.0f))
            continue;  // null: the density map removed its blade
        ++out.setsIn;
        if (keepEvery > 1 && i % keepEvery != 0) {
            ++out.culledDistance;
            continue;
        }
        const glm::vec3 root(set.rootMetresPerUnit);
        const glm::vec3 up(set.upYaw);
        const float radius = stemSetBoundRadius(set, levels);  // about the root
        if (settings.frustum && sphereOutside(planes, root, radius)) {
            ++out.culledFrustum;
            continue;
        }
        const glm::vec3 toSet = root - cameraPosition;
        if (settings.distance && settings.maxDistanceM > 0.0f) {
            const float dproj = projectedDistance(toSet, up);
            if (!keptByDistance(static_cast<std::uint32_t>(i), classes, dproj,
                                settings.maxDistanceM)) {
                ++out.culledDistance;
                continue;
            }
        }
        out.visible[std::size_t(stemSetLod(glm::length(toSet), settings.lodDistanceM))].push_back(i);
    }
}

}  // namespace grass::core
