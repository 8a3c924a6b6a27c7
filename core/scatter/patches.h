// Patches (SPEC §2): blades split into groups of exactly `patchSize` blades (a multiple of the
// compute work-group size), compact and roughly rectangular by recursive median bisection along
// the longest axis (balanced k-d clustering), sorted in Morton order inside each patch. The
// last patch is padded with null blades (h = 0, w = 0: zero area, skipped by the shaders) so
// every patch is full. Each patch's box contains every blade's reach: a sphere of radius h
// around its root, since v2 can swing anywhere on it.
#pragma once

#include <cstdint>
#include <vector>

#include "blade/blade.h"
#include "mesh/surface_mesh.h"

namespace grass::core {

struct Patch {
    std::uint32_t firstBlade = 0;
    std::uint32_t bladeCount = 0;  // live blades; the rest up to patchSize are padding
    Bounds bounds;                 // covers v0 ± h of every live blade
};

struct PatchedBlades {
    std::uint32_t patchSize = 0;
    std::vector<Blade> blades;  // patchCount × patchSize, patch-major
    std::vector<Patch> patches;
    std::vector<std::uint32_t>
        sourceIndex;  // blade i came from input blade sourceIndex[i] (padding: UINT32_MAX)
};

// The 63-bit Morton code of p quantised to 21 bits per axis within box (clamped to it): the
// order of blades inside a patch.
std::uint64_t mortonCode(glm::vec3 p, const Bounds& box);

// patchSize must be > 0; an empty input gives no patches.
PatchedBlades buildPatches(const std::vector<Blade>& blades, std::uint32_t patchSize);

}  // namespace grass::core
