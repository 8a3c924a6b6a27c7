// Physics buffers of core/physics/physics.cpp, mirrored for shaders/physics.comp; the wind field
// is wind_field.glsl's. World space, metres, seconds. Names follow the CPU reference (STYLE.md
// §1, §3).
//
// Everything that depends on time only (substep count, substep times, path positions of wind
// sources and colliders) is evaluated on the CPU by render::PhysicsGpu and uploaded per substep,
// with exactly the CPU reference's float arithmetic: GLSL division is not correctly rounded, so
// ceil(dtS / maxSubstepS) or t + i·τ computed here could differ from the CPU by a substep.

#include "wind_field.glsl"

// core::PhysicsParams (std430, 48 bytes; static_asserts in core/physics/physics.h).
struct PhysicsParams {
    vec4 gravity;
    float dtS;
    float etaDecayPerS;
    float maxSubstepS;
    float maxMovePerSubstep;
    uint gravityMode;
    uint maxSubsteps;
    float frontGravityScale;
    float crushedRecoveryFloor;
};

const uint GRAVITY_MODE_CENTRE = 1u;

// The blade buffer of blade.glsl, writable here (same binding, same layout).
layout(std430, binding = 0) buffer PhysicsBladeBuffer {
    Blade physicsBlades[];
};
layout(std430, binding = 1) readonly buffer PhysicsParamsBuffer {
    PhysicsParams params;
};
layout(std430, binding = 2) buffer EtaBuffer {
    float eta[];
};
// Rest tips Iv2 (xyz; w unused).
layout(std430, binding = 3) readonly buffer RestTipBuffer {
    vec4 restTips[];
};
layout(std430, binding = 4) readonly buffer WindSourceBuffer {
    WindSource windSources[];
};
// windCentres[i · windCount + j]: source j's centre at substep i's time t (xyz).
layout(std430, binding = 5) readonly buffer WindCentreBuffer {
    vec4 windCentres[];
};
// colliderSpheres[i · colliderCount + j]: collider j at t + τ of substep i (xyz centre, w radiusM).
layout(std430, binding = 6) readonly buffer ColliderBuffer {
    vec4 colliderSpheres[];
};
// colliderGroups[j]: the broad phase of core::SphereCollider j (render::ColliderGroupGpu):
// boundOffsetRadius = (boundOffset, boundRadiusM), size.x = groupSize.
struct ColliderGroup {
    vec4 boundOffsetRadius;
    uvec4 size;
};
layout(std430, binding = 8) readonly buffer ColliderGroupBuffer {
    ColliderGroup colliderGroups[];
};
// core::GravityLoad: blade i's |gE| grows by gravityLoadScale · gravityLoad[i] (snow load);
// bound and read only when gravityLoadScale > 0.
layout(std430, binding = 9) readonly buffer GravityLoadBuffer {
    float gravityLoad[];
};
// substepTimes[i]: x = t = timeS + i·τ, y = τ, z = t + τ (the collision time).
layout(std430, binding = 7) readonly buffer SubstepBuffer {
    vec4 substepTimes[];
};

// e^x − 1 without the cancellation of exp(x) − 1 near 0 (GLSL has no expm1): a Taylor
// polynomial below |x| = 0.5 (truncation < 3e-9 relative), exp(x) − 1 above.
float expm1(float x) {
    if (abs(x) >= 0.5)
        return exp(x) - 1.0;
    return x * (1.0 + x * (1.0 / 2.0 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 +
           x * (1.0 / 720.0 + x * (1.0 / 5040.0 + x * (1.0 / 40320.0))))))));
}
