// The cull pass's formula rules of SPEC §6 (core/scene/cull_rules.h, the twin of
// shaders/include/cull_rules.glsl): distance thinning keeps ceil(n·(1 − dproj/dmax)) of each
// n blades, and the orientation test culls blades whose width direction points within
// acos(0.9) of the view. Hand-computed values: a floor for the ceil, a moved threshold or a
// dropped term changes one of them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/cull_rules.h"

namespace grass::core {
namespace {

constexpr float DMAX = 100.0f;

TEST(CullRules, AllClassesKeptAtTheCamera) {
    EXPECT_EQ(distanceKeptCount(10, 0.0f, DMAX), 10u);
    EXPECT_EQ(distanceKeptCount(8, 0.0f, DMAX), 8u);
    EXPECT_EQ(distanceKeptCount(1, 0.0f, DMAX), 1u);
}

TEST(CullRules, KeptCountRoundsUp) {
    // 10·(1 − 0.95) = 0.5: ceil keeps one blade of ten (floor would keep none, round one).
    EXPECT_EQ(distanceKeptCount(10, 0.95f * DMAX, DMAX), 1u);
    // 10·0.75 = 7.5 → 8 (floor 7); 10·0.21 = 2.1 → 3 (round 2).
    EXPECT_EQ(distanceKeptCount(10, 25.0f, DMAX), 8u);
    EXPECT_EQ(distanceKeptCount(10, 79.0f, DMAX), 3u);
    // 8·(1 − 0.5) = 4 exactly (every term a power of two): ceil leaves an integer alone.
    EXPECT_EQ(distanceKeptCount(8, 0.5f * DMAX, DMAX), 4u);
}

TEST(CullRules, FallsLinearlyWithProjectedDistance) {
    // n = 4 at dmax = 100 m: 4 kept up to 25 m out, then 3, 2, 1 per quarter.
    EXPECT_EQ(distanceKeptCount(4, 10.0f, DMAX), 4u);
    EXPECT_EQ(distanceKeptCount(4, 30.0f, DMAX), 3u);
    EXPECT_EQ(distanceKeptCount(4, 60.0f, DMAX), 2u);
    EXPECT_EQ(distanceKeptCount(4, 80.0f, DMAX), 1u);
    // The ratio dproj/dmax, not dproj alone: the same blade at dmax = 200 m keeps 4·0.7 → 3.
    EXPECT_EQ(distanceKeptCount(4, 60.0f, 2.0f * DMAX), 3u);
}

TEST(CullRules, NothingKeptFromMaxDistanceOn) {
    EXPECT_EQ(distanceKeptCount(10, DMAX, DMAX), 0u);
    EXPECT_EQ(distanceKeptCount(10, 1.5f * DMAX, DMAX), 0u);
    EXPECT_EQ(distanceKeptCount(10, 1e30f, DMAX), 0u);
    // Just inside dmax the last class survives.
    EXPECT_EQ(distanceKeptCount(10, 0.999f * DMAX, DMAX), 1u);
}

TEST(CullRules, BladeIndexModuloClassesPicksTheKept) {
    // 10 classes at 75 % of dmax: ceil(2.5) = 3 kept, classes 0, 1, 2 of every ten.
    const float dproj = 0.75f * DMAX;
    for (std::uint32_t index = 0; index < 40; ++index)
        EXPECT_EQ(keptByDistance(index, 10, dproj, DMAX), index % 10 < 3) << "index " << index;
    // One class: every blade is kept until dmax, none after.
    EXPECT_TRUE(keptByDistance(7, 1, 0.99f * DMAX, DMAX));
    EXPECT_FALSE(keptByDistance(7, 1, DMAX, DMAX));
}

TEST(CullRules, ProjectedDistanceDropsTheUpComponent) {
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    // 3 m across, 4 m along: the part along up does not count (|toBlade| would be 5).
    EXPECT_NEAR(projectedDistance({3.0f, 4.0f, 0.0f}, up), 3.0f, 1e-6f);
    // Straight below the camera: near, however high the camera.
    EXPECT_NEAR(projectedDistance({0.0f, -50.0f, 0.0f}, up), 0.0f, 1e-6f);
    // A tilted up (a blade on a wall facing +x): 3-4-12 across y and z, 7 m along up.
    EXPECT_NEAR(projectedDistance({7.0f, 3.0f, 4.0f}, {1.0f, 0.0f, 0.0f}), 5.0f, 1e-6f);
}

TEST(CullRules, ViewAlongTheWidthCullsViewAcrossTheFaceKeeps) {
    const glm::vec3 width{1.0f, 0.0f, 0.0f};
    // Looking along the width direction (either way): the blade is seen edge-on.
    EXPECT_TRUE(seenEdgeOn({1.0f, 0.0f, 0.0f}, width));
    EXPECT_TRUE(seenEdgeOn({-1.0f, 0.0f, 0.0f}, width));
    // Looking at its face or down its length: kept.
    EXPECT_FALSE(seenEdgeOn({0.0f, 0.0f, 1.0f}, width));
    EXPECT_FALSE(seenEdgeOn({0.0f, -1.0f, 0.0f}, width));
    // Half way (45°, |cos| = 0.707): kept.
    EXPECT_FALSE(seenEdgeOn(glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f)), width));
}

TEST(CullRules, OrientationThresholdIsCosineNineTenths) {
    EXPECT_EQ(ORIENTATION_CULL_COS, 0.9f);
    const glm::vec3 width{1.0f, 0.0f, 0.0f};
    // A view whose cosine with the width is c: (c, √(1 − c²), 0).
    const auto view = [](float c) { return glm::vec3(c, std::sqrt(1.0f - c * c), 0.0f); };
    EXPECT_TRUE(seenEdgeOn(view(0.91f), width));
    EXPECT_TRUE(seenEdgeOn(-view(0.91f), width));
    EXPECT_FALSE(seenEdgeOn(view(0.89f), width));
    EXPECT_FALSE(seenEdgeOn(-view(0.89f), width));
    // The threshold itself is kept: the test is a strict >.
    EXPECT_FALSE(seenEdgeOn({1.0f, 0.0f, 0.0f}, {0.9f, 0.0f, 0.0f}));
}

}  // namespace
}  // namespace grass::core
