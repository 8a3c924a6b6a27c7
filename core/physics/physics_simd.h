// The data-parallel execution of the blade physics (issue 29): the step of core::stepBlade (the
// scalar reference, SPEC §3–5, which stays the tested definition) computed for a block of blades
// at once in SIMD lanes (Google Highway, the widest instruction set the CPU has, chosen at run
// time), with the blocks spread over a reused thread pool.
//
// Layout: the blade buffer stays the GPU's array of 64-byte records; each block of blades (three
// native vectors of lanes, simd_pack-inl.h: their dependency chains overlap) is transposed into
// lanes (structure of arrays) in cache by 4×4 transposes, stepped through every substep, and
// written back the same way: one read and one write of each blade per step, as the bandwidth
// bound in docs/physics.md assumes. What depends on time only (substep times, wind and collider
// path positions) is evaluated once per step for all blades (physics_step_inputs.h). Blades the
// reference would repair (non-finite values, zero height, an up that is not unit length) and the
// blades of a last partial block take the scalar reference.
//
// Results equal the scalar reference's within the CPU/GPU tolerance (1e-3·h on the tips; the
// SIMD sine and exponential differ from libm's in the last bits): tests/core/physics.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "physics/physics.h"

namespace grass::core {

// How the CPU runs the physics: the scalar reference (stepPhysics, the tested definition) or the
// SIMD execution (the default wherever speed matters: grass sim, the editor, the benchmarks).
enum class CpuPhysics { Scalar, Simd };
const char* cpuPhysicsName(CpuPhysics path);  // "scalar" | "simd"

// stepPhysics or stepPhysicsSimd, as `path` says.
void stepPhysicsOn(CpuPhysics path, std::span<Blade> blades, std::span<float> eta,
                   std::span<const glm::vec3> restTips, const PhysicsParams& params,
                   const std::vector<WindSource>& wind,
                   const std::vector<SphereCollider>& colliders, float timeS,
                   unsigned threadCount = 0, GravityLoad load = {});

// One step for all blades, as stepPhysics; threadCount 0: the shared pool's threads + the caller.
void stepPhysicsSimd(std::span<Blade> blades, std::span<float> eta,
                     std::span<const glm::vec3> restTips, const PhysicsParams& params,
                     const std::vector<WindSource>& wind,
                     const std::vector<SphereCollider>& colliders, float timeS,
                     unsigned threadCount = 0, GravityLoad load = {});

// The instruction set the SIMD step runs with on this CPU ("AVX2", "AVX3", "SSE4", ...) and its
// float lanes.
std::string physicsSimdTarget();
std::size_t physicsSimdLanes();

}  // namespace grass::core
