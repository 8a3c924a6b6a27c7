// The inputs of one GPU physics step (shaders/physics.comp, SPEC §3–5), packed std430 as the
// shader reads them. What depends on time only — the substep times, the wind sources' and the
// colliders' path positions — is evaluated on the CPU with the reference's own functions, per
// substep, exactly as stepBlade samples them: wind at t = timeS + i·τ, colliders at t + τ.
// Shared by the editor's PhysicsGpu and the reference runtime (editor/runtime), so both feed the
// one shader the same numbers. GL-free, GLM only.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "physics/physics.h"

namespace grass::core {

// core::WindSource without its path (WindSource in shaders/include/physics.glsl).
struct WindSourceGpu {
    glm::vec4 directionStrength{0.0f};  // xyz direction, w strength
    glm::vec4 axisRadius{0.0f};         // xyz axis, w radiusM
    glm::vec4 shape{0.0f};              // coreRadiusM, wavelengthM, speedMps, gust
    glm::uvec4 kind{0u};                // x: core::WindKind
};
static_assert(sizeof(WindSourceGpu) == 64, "WindSourceGpu must be four vec4 (std430)");

// The source as the shaders read it (its path is the caller's to sample).
WindSourceGpu packWindSource(const WindSource& source);

// Every source as the shaders read it, with its centre on its path at timeS (xyz; w 0): what a
// pass that evaluates the wind at one time binds (the billboards, shaders/include/
// billboard_wind.glsl).
struct WindSourcesAt {
    std::vector<WindSourceGpu> sources;
    std::vector<glm::vec4> centres;
};
WindSourcesAt packWindSourcesAt(const std::vector<WindSource>& wind, float timeS);

// The broad phase of a core::SphereCollider (ColliderGroup in physics.glsl).
struct ColliderGroupGpu {
    glm::vec4 boundOffsetRadius{0.0f};
    glm::uvec4 size{1u, 0u, 0u, 0u};
};
static_assert(sizeof(ColliderGroupGpu) == 32, "ColliderGroupGpu must be two vec4 (std430)");

struct PhysicsStepInputs {
    std::uint32_t substepCount = 0;                // 0: nothing to do
    std::vector<glm::vec4> substeps;               // (t, τ, t + τ, 0) per substep
    std::vector<WindSourceGpu> windSources;        // per source
    std::vector<glm::vec4> windCentres;            // substep-major: [i · sources + k]
    std::vector<glm::vec4> colliderSpheres;        // substep-major: (centre at t + τ, radius)
    std::vector<ColliderGroupGpu> colliderGroups;  // per sphere
};

PhysicsStepInputs physicsStepInputs(const PhysicsParams& params,
                                    const std::vector<WindSource>& wind,
                                    const std::vector<SphereCollider>& colliders, float timeS);

}  // namespace grass::core
