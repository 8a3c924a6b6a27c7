#include "snow/snow_drift.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

namespace {

// A texel holds a surface when its depth lies inside the view's range: the CPU map stores
// SNOW_MAP_EMPTY where none is, the GPU map its cleared far plane (depthRange).
bool holdsSurface(const SnowDepthMap& map, float depth) {
    return depth < map.view.depthRangeM;
}

// The world position of the surface a texel holds: its centre across the map, at its depth.
glm::vec3 texelWorld(const SnowDepthMap& map, int ix, int iy, float depth) {
    const float n = static_cast<float>(map.resolution);
    return snowMapToWorld(map.view, {(static_cast<float>(ix) + 0.5f) / n,
                                     (static_cast<float>(iy) + 0.5f) / n, depth});
}

float cellFactor(const SnowDepthMap& map, int cx, int cy, glm::vec2 direction,
                 const SnowParams& params) {
    const float sx = snowDriftShelterAngle(map, cx, cy, direction, params.driftReachM);
    return 1.0f + params.drift * std::clamp(sx / SNOW_DRIFT_REFERENCE_RAD, -1.0f, 1.0f);
}

}  // namespace

glm::vec3 snowDriftWorldDirection(const SnowParams& params, std::span<const WindSource> wind) {
    if (params.driftFollowsWind == 0u)
        return params.driftDirection;
    glm::vec3 sum(0.0f);
    for (const WindSource& source : wind) {
        const float length = glm::length(source.direction);
        if (source.kind == WindKind::Directional && length > 0.0f && std::isfinite(length) &&
            std::isfinite(source.strength))
            sum += std::max(source.strength, 0.0f) * source.direction / length;
    }
    return sum;
}

SnowParams snowWithWindDrift(SnowParams params, std::span<const WindSource> wind) {
    params.driftDirection = snowDriftWorldDirection(params, wind);
    params.driftFollowsWind = 0u;
    return params;
}

glm::vec2 snowDriftMapDirection(const OrthoSnowView& view, glm::vec3 worldDirection) {
    const glm::vec2 across(glm::dot(worldDirection, view.right), glm::dot(worldDirection, view.up));
    const float length = glm::length(across);
    // Within 0.06° of the fall (or no wind at all) the drift has no direction.
    return length > 1e-3f * glm::length(worldDirection) && length > 0.0f && std::isfinite(length)
               ? across / length
               : glm::vec2(0.0f);
}

bool snowDrifts(const SnowParams& params, glm::vec2 mapDirection) {
    return params.enabled != 0u && params.drift > 0.0f && params.driftReachM > 0.0f &&
           glm::dot(mapDirection, mapDirection) > 0.0f;
}

float snowDriftShelterAngle(const SnowDepthMap& map, int cx, int cy, glm::vec2 mapDirection,
                            float reachM) {
    const float half = 0.5f * static_cast<float>(SNOW_DRIFT_CELL_TEXELS);
    const glm::vec2 centre(static_cast<float>(cx * SNOW_DRIFT_CELL_TEXELS) + half,
                           static_cast<float>(cy * SNOW_DRIFT_CELL_TEXELS) + half);
    const int hx = snowTexelIndex(centre.x), hy = snowTexelIndex(centre.y);
    const float here = map.at(hx, hy);
    if (!holdsSurface(map, here))
        return 0.0f;
    const glm::vec3 herePos = texelWorld(map, hx, hy, here);
    const float reachTexels = reachM / map.texelSizeM();
    float steepest = 0.0f;
    bool any = false;
    for (int k = 1; k <= SNOW_DRIFT_SAMPLES; ++k) {
        const float share = static_cast<float>(k) / static_cast<float>(SNOW_DRIFT_SAMPLES);
        const glm::vec2 s = centre - mapDirection * (reachTexels * share);
        const int sx = snowTexelIndex(s.x), sy = snowTexelIndex(s.y);
        const float stored = map.at(sx, sy);
        if (!holdsSurface(map, stored))
            continue;
        // Heights along world up (+Y) and distances across it: under a slanted fall the map
        // plane is tilted, and depths along the fall would read level ground as a slope.
        const glm::vec3 d = texelWorld(map, sx, sy, stored) - herePos;
        const float across = std::sqrt(d.x * d.x + d.z * d.z);
        if (!(across > 0.0f))
            continue;
        const float slope = d.y / across;
        steepest = any ? std::max(steepest, slope) : slope;
        any = true;
    }
    return any ? std::atan(steepest) : 0.0f;
}

SnowDriftMap computeSnowDriftMap(const SnowDepthMap& map, const SnowParams& params,
                                 glm::vec2 mapDirection) {
    SnowDriftMap drift;
    if (!snowDrifts(params, mapDirection) || map.resolution < SNOW_DRIFT_CELL_TEXELS)
        return drift;
    drift.resolution = map.resolution / SNOW_DRIFT_CELL_TEXELS;
    drift.factor.resize(static_cast<std::size_t>(drift.resolution) *
                        static_cast<std::size_t>(drift.resolution));
    for (int cy = 0; cy < drift.resolution; ++cy)
        for (int cx = 0; cx < drift.resolution; ++cx)
            drift.factor[static_cast<std::size_t>(cy) * static_cast<std::size_t>(drift.resolution) +
                         static_cast<std::size_t>(cx)] =
                cellFactor(map, cx, cy, mapDirection, params);
    return drift;
}

float snowDriftFactorAt(const SnowDriftMap& drift, const OrthoSnowView& view, glm::vec3 posWorld) {
    if (drift.factor.empty() || drift.resolution <= 0)
        return 1.0f;
    const glm::vec3 c = snowMapCoords(view, posWorld);
    const float n = static_cast<float>(drift.resolution);
    // Cell centres sit at (i + 0.5)/n: bilinear between the four around the point.
    const float x = std::clamp(c.x * n - 0.5f, 0.0f, n - 1.0f);
    const float y = std::clamp(c.y * n - 0.5f, 0.0f, n - 1.0f);
    const int x0 = std::min(static_cast<int>(x), drift.resolution - 1);
    const int y0 = std::min(static_cast<int>(y), drift.resolution - 1);
    const int x1 = std::min(x0 + 1, drift.resolution - 1), y1 = std::min(y0 + 1, drift.resolution - 1);
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    const auto at = [&](int i, int j) {
        return drift.factor[static_cast<std::size_t>(j) * static_cast<std::size_t>(drift.resolution) +
                            static_cast<std::size_t>(i)];
    };
    const float bottom = at(x0, y0) + fx * (at(x1, y0) - at(x0, y0));
    const float top = at(x0, y1) + fx * (at(x1, y1) - at(x0, y1));
    return bottom + fy * (top - bottom);
}

}  // namespace grass::core
