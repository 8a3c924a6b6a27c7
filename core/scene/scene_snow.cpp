#include "scene/scene_snow.h"

#include <algorithm>

#include "snow/snow_drift.h"

namespace grass::core {

OrthoSnowView sceneSnowView(const Scene& scene, const SnowParams& params, float timeS) {
    Bounds bounds = scene.bounds;
    for (const SceneProp& prop : scene.props) {
        const Bounds local = meshBounds(prop.mesh);
        const glm::mat4 model = prop.modelAt(timeS);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p{(corner & 1) ? local.max.x : local.min.x,
                              (corner & 2) ? local.max.y : local.min.y,
                              (corner & 4) ? local.max.z : local.min.z};
            const glm::vec3 q = glm::vec3(model * glm::vec4(p, 1.0f));
            bounds.min = glm::min(bounds.min, q);
            bounds.max = glm::max(bounds.max, q);
        }
    }
    const float margin = 0.02f * glm::length(bounds.size()) + 1e-3f;
    return makeOrthoSnowView(params.fallDirection, bounds, margin);
}

SnowDepthMap sceneSnowDepthMap(const Scene& scene, const SnowParams& params, float timeS) {
    std::vector<std::array<glm::vec3, 3>> triangles = snowTriangles(scene.mesh);
    for (const SceneProp& prop : scene.props) {
        const glm::mat4 model = prop.modelAt(timeS);
        for (auto triangle : snowTriangles(prop.mesh)) {
            for (glm::vec3& corner : triangle)
                corner = glm::vec3(model * glm::vec4(corner, 1.0f));
            triangles.push_back(triangle);
        }
    }
    return renderSnowDepthMap(triangles, sceneSnowView(scene, params, timeS), params.mapResolution);
}

bool snowLoadsBlades(const SnowParams& params) {
    return params.enabled != 0u && params.loadGravity > 0.0f &&
           (params.amountM > 0.0f || params.accumulationRate > params.meltRate);
}

SnowWeigher::SnowWeigher(SnowDepthMap map, const SnowParams& params)
    : mMap(std::move(map)), mParams(params), mPerMetre(params), mLoads(snowLoadsBlades(params)) {
    mPerMetre.amountM = 1.0f;
    // params' drift direction is resolved (snowWithWindDrift), as the renderer's is.
    if (mLoads)
        mDrift = computeSnowDriftMap(mMap, mParams,
                                     snowDriftMapDirection(mMap.view, mParams.driftDirection));
}

float SnowWeigher::loadPerMetre(const Blade& blade) const {
    if (!mLoads || !(blade.h() > 0.0f))
        return 0.0f;
    const float rootFe = snowBoundaryExposure(mMap, blade.v0(), blade.up(), mPerMetre);
    const float depth = snowDepthAt(blade.v0(), rootFe, mPerMetre,
                                    snowDriftFactorAt(mDrift, mMap.view, blade.v0()));
    const float tipFe = exposureCoefficient(mMap, blade.v2(), snowUp(mParams), mParams.samples,
                                            mParams.sampleRadiusTexels, mParams.depthBiasM);
    return snowLoadGravity(mPerMetre, depth, tipFe);
}

std::vector<float> SnowWeigher::loadsPerMetre(std::span<const Blade> blades) const {
    if (!mLoads)
        return {};
    std::vector<float> load(blades.size(), 0.0f);
    for (std::size_t i = 0; i < blades.size(); ++i)
        load[i] = loadPerMetre(blades[i]);
    return load;
}

std::vector<float> snowLoadPerMetre(std::span<const Blade> blades, const SnowDepthMap& map,
                                    const SnowParams& params) {
    if (!snowLoadsBlades(params))
        return {};
    return SnowWeigher(map, params).loadsPerMetre(blades);
}

}  // namespace grass::core
