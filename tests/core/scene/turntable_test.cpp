#include "scene/turntable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "util/rng.h"

namespace grass::core {
namespace {

constexpr double TWO_PI = 6.283185307179586476925;

OrbitCamera someCamera() {
    return OrbitCamera::lookAt(glm::vec3(14, 7, 14), glm::vec3(1, 0.5f, -2), 0.8f);
}

TEST(Turntable, FrameZeroIsTheStartCamera) {
    const OrbitCamera start = someCamera();
    const OrbitCamera first = turntableCamera(start, 0, 8);
    EXPECT_EQ(first.yawRad, start.yawRad);
    EXPECT_EQ(first.position(), start.position());
    EXPECT_EQ(first.view(), start.view());
}

TEST(Turntable, FrameKTurnsTheYawByTwoPiKOverN) {
    const OrbitCamera start = someCamera();
    for (const int n : {2, 3, 4, 8, 360, 3600}) {
        for (int k = 0; k < n; k += std::max(1, n / 16)) {
            const OrbitCamera camera = turntableCamera(start, k, n);
            const double expected = start.yawRad + TWO_PI * k / n;
            EXPECT_NEAR(camera.yawRad, expected, 1e-5) << "frame " << k << " of " << n;
            EXPECT_EQ(camera.pitchRad, start.pitchRad);
            EXPECT_EQ(camera.distance, start.distance);
            EXPECT_EQ(camera.target, start.target);
            EXPECT_EQ(camera.fovYRad, start.fovYRad);
            EXPECT_EQ(camera.nearPlane, start.nearPlane);
            EXPECT_EQ(camera.farPlane, start.farPlane);
        }
    }
}

// The orbit is about the vertical axis through the target: every eye keeps its distance to the
// target, its height, and its horizontal radius; consecutive eyes are 2π/N apart about +Y.
TEST(Turntable, EyesCircleTheTargetAtTheSameHeightAndDistance) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        Rng rng(seed);
        const glm::vec3 target(rng.uniform(-50.0f, 50.0f), rng.uniform(-5.0f, 5.0f),
                               rng.uniform(-50.0f, 50.0f));
        const glm::vec3 eye =
            target + glm::vec3(rng.uniform(-30.0f, 30.0f), rng.uniform(0.5f, 20.0f),
                               rng.uniform(-30.0f, 30.0f));
        const OrbitCamera start = OrbitCamera::lookAt(eye, target, 0.8f);
        const int n = 2 + static_cast<int>(rng.below(99));
        const glm::vec3 startOffset = start.position() - target;
        const float radius = std::hypot(startOffset.x, startOffset.z);
        for (int k = 0; k < n; ++k) {
            const glm::vec3 offset = turntableCamera(start, k, n).position() - target;
            const float tolerance = 1e-4f * std::max(1.0f, start.distance);
            EXPECT_NEAR(glm::length(offset), start.distance, tolerance) << "seed " << seed;
            EXPECT_NEAR(offset.y, startOffset.y, tolerance) << "seed " << seed;
            EXPECT_NEAR(std::hypot(offset.x, offset.z), radius, tolerance) << "seed " << seed;
            const double turned =
                std::atan2(offset.x, offset.z) - std::atan2(startOffset.x, startOffset.z);
            const double expected = TWO_PI * k / n;
            EXPECT_NEAR(std::remainder(turned - expected, TWO_PI), 0.0, 1e-3)
                << "seed " << seed << " frame " << k << " of " << n;
        }
    }
}

TEST(Turntable, FramePathsAreZeroPaddedAndKeepTheExtension) {
    EXPECT_EQ(turntableFramePath("out/meadow.png", 0, 4), "out/meadow_0000.png");
    EXPECT_EQ(turntableFramePath("out/meadow.png", 3, 4), "out/meadow_0003.png");
    EXPECT_EQ(turntableFramePath("meadow.tif", 3599, 3600), "meadow_3599.tif");
    // More digits only when the last frame needs them.
    EXPECT_EQ(turntableFramePath("a.png", 7, 12345), "a_00007.png");
    EXPECT_EQ(turntableFramePath("dir.v2/shot.final.png", 1, 2), "dir.v2/shot.final_0001.png");
}

TEST(Turntable, SheetPathSitsNextToTheFrames) {
    EXPECT_EQ(turntableSheetPath("out/meadow.png"), "out/meadow_sheet.png");
    EXPECT_EQ(turntableSheetPath("meadow.exr"), "meadow_sheet.exr");
}

}  // namespace
}  // namespace grass::core
