#include "scene/sun_shadow.h"

#include <algorithm>
#include <cmath>

#include "scene/scene_snow.h"

namespace grass::core {

namespace {

constexpr float BIAS_TEXELS = 2.0f;

// The snow's view machinery with the light for the fall.
SnowParams alongTheSun(const SunDesc& sun) {
    SnowParams params;
    params.fallDirection =
        glm::length(sun.direction) > 0.0f ? sun.direction : glm::vec3(0.0f, -1.0f, 0.0f);
    params.mapResolution = std::max(sun.shadowResolution, 1);
    return params;
}

}  // namespace

OrthoSnowView sceneSunView(const Scene& scene, const SunDesc& sun, float timeS) {
    return sceneSnowView(scene, alongTheSun(sun), timeS);
}

SnowDepthMap sceneSunDepthMap(const Scene& scene, const SunDesc& sun, float timeS) {
    return sceneSnowDepthMap(scene, alongTheSun(sun), timeS);
}

float sunShadowBiasM(const OrthoSnowView& view, int resolution) {
    return BIAS_TEXELS * view.sizeM / static_cast<float>(std::max(resolution, 1));
}

void enableSunShadows(LightingBlock& block, const OrthoSnowView& view, int resolution) {
    block.sunShadowOrigin = view.origin;
    block.sunShadowSizeM = view.sizeM;
    block.sunShadowRight = view.right;
    block.sunShadowDepthRangeM = view.depthRangeM;
    block.sunShadowUp = view.up;
    block.sunShadows = 1;
    block.sunShadowForward = view.forward;
    block.sunShadowBiasM = sunShadowBiasM(view, resolution);
}

float sunVisibility(const SnowDepthMap& map, glm::vec3 p, float biasM) {
    if (map.resolution <= 0)
        return 1.0f;
    const glm::vec3 coords = snowMapCoords(map.view, p);
    if (!(coords.x >= 0.0f && coords.x <= 1.0f && coords.y >= 0.0f && coords.y <= 1.0f))
        return 1.0f;
    const float n = static_cast<float>(map.resolution);
    const glm::vec2 t = glm::vec2(coords) * n - 0.5f;
    const glm::vec2 cell = glm::floor(t);
    const glm::vec2 f = t - cell;
    const float depth = coords.z - biasM;
    const auto lit = [&](int dx, int dy) {
        const int x = std::clamp(static_cast<int>(cell.x) + dx, 0, map.resolution - 1);
        const int y = std::clamp(static_cast<int>(cell.y) + dy, 0, map.resolution - 1);
        return depth <= map.at(x, y) ? 1.0f : 0.0f;
    };
    const float bottom = lit(0, 0) + (lit(1, 0) - lit(0, 0)) * f.x;
    const float top = lit(0, 1) + (lit(1, 1) - lit(0, 1)) * f.x;
    return bottom + (top - bottom) * f.y;
}

}  // namespace grass::core
