#include "physics/physics_step_inputs.h"

#include <algorithm>

namespace grass::core {

WindSourceGpu packWindSource(const WindSource& source) {
    WindSourceGpu out;
    out.directionStrength = glm::vec4(source.direction, source.strength);
    out.axisRadius = glm::vec4(source.axis, source.radiusM);
    out.shape = glm::vec4(source.coreRadiusM, source.wavelengthM, source.speedMps, source.gust);
    out.kind = glm::uvec4(static_cast<std::uint32_t>(source.kind), 0u, 0u, 0u);
    return out;
}

WindSourcesAt packWindSourcesAt(const std::vector<WindSource>& wind, float timeS) {
    WindSourcesAt packed;
    for (const WindSource& source : wind) {
        packed.sources.push_back(packWindSource(source));
        packed.centres.emplace_back(samplePath(source.path, timeS, source.position), 0.0f);
    }
    return packed;
}

PhysicsStepInputs physicsStepInputs(const PhysicsParams& params,
                                    const std::vector<WindSource>& wind,
                                    const std::vector<SphereCollider>& colliders, float timeS) {
    PhysicsStepInputs inputs;
    const std::uint32_t n = substepCount(params);
    inputs.substepCount = n;
    if (n == 0)
        return inputs;
    // The same float expressions as core::stepBlade, so the times match bit for bit.
    const float tau = params.dtS / static_cast<float>(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const float t = timeS + static_cast<float>(i) * tau;
        inputs.substeps.emplace_back(t, tau, t + tau, 0.0f);
        for (const WindSource& source : wind)
            inputs.windCentres.emplace_back(samplePath(source.path, t, source.position), 0.0f);
        for (const SphereCollider& sphere : colliders)
            inputs.colliderSpheres.emplace_back(
                samplePath(sphere.path, t + tau, sphere.centre), sphere.radiusM);
    }
    for (const WindSource& source : wind)
        inputs.windSources.push_back(packWindSource(source));
    for (const SphereCollider& sphere : colliders)
        inputs.colliderGroups.push_back(
            {glm::vec4(sphere.boundOffset, sphere.boundRadiusM),
             glm::uvec4(std::max(sphere.groupSize, 1u), 0u, 0u, 0u)});
    return inputs;
}

}  // namespace grass::core
