// Culling and level of detail for Kim & Cho's stem sets (issue 24): the growth technique is
// culled and thinned as blades are (SPEC §6: frustum, distance classes, the editor's uniform
// thinning) and drawn with fewer samples per level farther away (SPEC §7's LOD distances).
//
// On the CPU, unlike the blades' compute pass: stem sets do not move (no physics acts on them),
// there is one per six blade slots, and the test per set is one bounding sphere, so a frame's
// cull of the meadow's ~10k sets is a few tens of microseconds and its visible list a small
// upload; the vertex shader, which evaluates a B-spline per vertex, is where the frame went.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "growth/growth_stems.h"

namespace grass::core {

// Samples per level at LOD 0, 1, 2 (SPEC §7's classes: up to lodDistance, up to 3·lodDistance,
// beyond). Five is the paper's; three still bends through every level point's neighbourhood;
// two keeps one segment per level, where a stem is a few pixels tall.
inline constexpr std::array<int, 3> STEM_SET_LOD_SAMPLES{STEM_SAMPLES_PER_LEVEL, 3, 2};
inline constexpr int STEM_SET_LOD_COUNT = int(STEM_SET_LOD_SAMPLES.size());

struct StemSetCullSettings {
    bool frustum = true;
    bool distance = true;
    int distanceClasses = 8;     // as CullSettings: set i kept while i mod n < ceil(n·(1 − d/dmax))
    float maxDistanceM = 100.0f;
    float lodDistanceM = 8.0f;  // 0: every set at LOD 0
    int keepEvery = 1;          // the editor's reduced picture: set i drawn when i mod N = 0
};

struct StemSetCullResult {
    // Instance indices per LOD, ascending.
    std::array<std::vector<std::uint32_t>, STEM_SET_LOD_COUNT> visible;
    std::size_t setsIn = 0;  // sets that hold a blade (null sets are not counted)
    std::size_t culledFrustum = 0;
    std::size_t culledDistance = 0;  // thinning, uniform or by distance
    std::size_t drawn() const;
};

// A sphere about the root that holds the whole set at `levels` (clamped to 1..4), metres: the
// stems' level points lie within Σβ^i + levels·spreadZ of the root in the bend plane and
// α/2 + spreadX across it, the ribbons half a width beyond.
float stemSetBoundRadius(const StemSetInstance& set, int levels);

// The level of detail of a set whose root is `distanceM` from the camera (lod.glsl's bladeLod).
int stemSetLod(float distanceM, float lodDistanceM);

// Fills `out` (its lists are reused) with the sets of `sets` to draw from a camera at
// `cameraPosition` whose view-projection is `viewProj` (OpenGL clip space).
void cullStemSets(std::span<const StemSetInstance> sets, int levels, const glm::mat4& viewProj,
                  glm::vec3 cameraPosition, const StemSetCullSettings& settings,
                  StemSetCullResult& out);

}  // namespace grass::core
