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

std::vector<float> snowLoadPerMetre(std::span<const Blade> blades, const SnowDepthMap& map,
                                    const SnowParams& params) {
    if (!snowLoadsBlades(params))
        return {};
    SnowParams perMetre = params;
    perMetre.amountM = 1.0f;
    const glm::vec3 up = snowUp(params);
    // params' drift direction is resolved (snowWithWindDrift), as the renderer's is.
    const SnowDriftMap drift =
        computeSnowDriftMap(map, params, snowDriftMapDirection(map.view, params.driftDirection));
    std::vector<float> load(blades.size(), 0.0f);
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const Blade& blade = blades[i];
        if (!(blade.h() > 0.0f))
            continue;
        const float rootFe = snowBoundaryExposure(map, blade.v0(), blade.up(), perMetre);
        const float depth = snowDepthAt(blade.v0(), rootFe, perMetre,
                                        snowDriftFactorAt(drift, map.view, blade.v0()));
        const float tipFe = exposureCoefficient(map, blade.v2(), up, params.samples,
                                                params.sampleRadiusTexels, params.depthBiasM);
        load[i] = snowLoadGravity(perMetre, depth, tipFe);
    }
    return load;
}

}  // namespace grass::core
