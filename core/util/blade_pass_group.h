// How many invocations a work group of the per-blade compute passes (shaders/physics.comp,
// shaders/cull.comp) holds: 32, the size every measured figure was taken with, unless the
// GRASS_COMPUTE_GROUP variable names another. GL-free.
//
// Why it is a knob: on llvmpipe a work group runs on one thread, lane by lane in SIMD registers,
// and groups of 32 measured best for the cull (128: no better, docs/rendering.md). On a GPU a
// group of 32 is one warp, and NVIDIA's SMs hold at most 32 resident groups (CUDA's occupancy
// tables for compute capability 8.0–9.0: 32 blocks, 64 warps an SM), so groups of one warp fill
// at most half an SM's warp slots; the cull's per-group atomics (a reservation per level of
// detail) also fall with the group's size. But the one GPU run with larger physics groups (128,
// 2026-12-05, together with another change) measured no gain (docs/physics.md), so the size
// stays 32 until `.ci/gpu/run.sh` measures 256 beside it (its `bench-groups-256` step).
#pragma once

#include <cstdint>
#include <string>

#include "util/result.h"

namespace grass::core {

inline constexpr std::uint32_t DEFAULT_BLADE_PASS_GROUP = 32;
// The cull tests each run of 32 blades against its patch (patches hold multiples of 32 blades),
// and GL guarantees 1024 invocations a group: 32 to 256 in steps of 32 are allowed.
inline constexpr std::uint32_t BLADE_PASS_GROUP_STEP = 32;
inline constexpr std::uint32_t MAX_BLADE_PASS_GROUP = 256;

// A size both passes can run: a multiple of 32 from 32 to 256.
bool isBladePassGroupSize(std::uint32_t size);

// The group size for GRASS_COMPUTE_GROUP's value `text` (nullptr or empty: unset, the default).
// A value that is not a multiple of 32 from 32 to 256 is an error naming the variable.
Result<std::uint32_t> bladePassGroupSize(const char* text);
// The same for the process's GRASS_COMPUTE_GROUP.
Result<std::uint32_t> bladePassGroupSizeFromEnvironment();

// The define that sizes the passes' groups (physics.comp's GROUP_SIZE, cull.comp's GROUP_RUNS
// runs of 32 blades); the only way a size reaches the shaders, so the only place it is checked
// (precondition: isBladePassGroupSize).
std::string physicsGroupDefine(std::uint32_t groupSize);
std::string cullGroupDefine(std::uint32_t groupSize);

}  // namespace grass::core
