#include "physics/wind.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "util/rng.h"

namespace grass::core {
namespace {

WindSource constantWind(glm::vec3 dir, float strength) {
    WindSource s;
    s.kind = WindKind::Directional;
    s.direction = dir;
    s.strength = strength;
    s.wavelengthM = 0.0f;
    return s;
}

WindSource radialSource(WindKind kind, glm::vec3 pos, float radius) {
    WindSource s;
    s.kind = kind;
    s.position = pos;
    s.strength = 3.0f;
    s.radiusM = radius;
    s.coreRadiusM = 0.5f;
    return s;
}

TEST(Wind, ConstantDirectionalBlowsAlongItsDirection) {
    const WindSource s = constantWind({2.0f, 0.0f, 0.0f}, 5.0f);
    const glm::vec3 w = windAt(s, {3.0f, 1.0f, -7.0f}, 12.0f);
    EXPECT_NEAR(w.x, 5.0f, 1e-6f);
    EXPECT_EQ(w.y, 0.0f);
    EXPECT_EQ(w.z, 0.0f);
}

TEST(Wind, DirectionalWaveTravelsWithItsSpeedAndStaysWithinStrength) {
    WindSource s = constantWind({0.0f, 0.0f, 1.0f}, 2.0f);
    s.wavelengthM = 4.0f;
    s.speedMps = 3.0f;
    s.gust = 0.7f;
    Rng rng(7);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 p(rng.uniform(-50, 50), rng.uniform(-2, 2), rng.uniform(-50, 50));
        const float t = rng.uniform(0, 100);
        const glm::vec3 w = windAt(s, p, t);
        EXPECT_GE(w.z, 0.0f);
        EXPECT_LE(w.z, 2.0f + 1e-5f);
        // Wave and gusts are advected with the wind: the field moves by speed·Δt.
        const glm::vec3 later = windAt(s, p + glm::vec3(0, 0, 3.0f * 0.5f), t + 0.5f);
        EXPECT_NEAR(later.z, w.z, 2e-3f) << "i " << i;
    }
}

TEST(Wind, EachSourceFallsToZeroAtItsRadiusContinuously) {
    const glm::vec3 c(1.0f, 0.0f, 2.0f);
    for (const WindKind kind : {WindKind::Directional, WindKind::Point, WindKind::Vortex}) {
        WindSource s = radialSource(kind, c, 10.0f);
        const glm::vec3 dir = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
        EXPECT_EQ(windAt(s, c + dir * 10.0f, 0.0f), glm::vec3(0.0f));
        EXPECT_EQ(windAt(s, c + dir * 25.0f, 0.0f), glm::vec3(0.0f));
        const float justInside = glm::length(windAt(s, c + dir * 9.999f, 0.0f));
        EXPECT_LT(justInside, 1e-5f) << "kind " << static_cast<int>(kind);
        EXPECT_GT(glm::length(windAt(s, c + dir * 5.0f, 0.0f)), 0.5f);
    }
}

TEST(Wind, DirectionalWithoutRadiusReachesEverywhere) {
    const WindSource s = constantWind({1.0f, 0.0f, 0.0f}, 1.0f);
    EXPECT_NEAR(windAt(s, {1e5f, 0.0f, -1e5f}, 0.0f).x, 1.0f, 1e-6f);
}

TEST(Wind, PointSourceBlowsRadiallyOutwards) {
    const glm::vec3 c(0.0f, 5.0f, 0.0f);
    const WindSource s = radialSource(WindKind::Point, c, 20.0f);
    Rng rng(3);
    for (int i = 0; i < 100; ++i) {
        const glm::vec3 p(rng.uniform(-10, 10), rng.uniform(0, 3), rng.uniform(-10, 10));
        const glm::vec3 w = windAt(s, p, 0.0f);
        const glm::vec3 out = glm::normalize(p - c);
        EXPECT_GT(glm::dot(w, out), 0.0f);
        EXPECT_LT(glm::length(glm::cross(w, out)), 1e-5f) << "i " << i;
    }
    // Continuous at the centre: the Rankine core goes to zero.
    EXPECT_EQ(windAt(s, c, 0.0f), glm::vec3(0.0f));
    EXPECT_LT(glm::length(windAt(s, c + glm::vec3(1e-4f, 0, 0), 0.0f)), 1e-3f);
}

TEST(Wind, VortexIsTangentialAroundItsAxis) {
    const glm::vec3 c(2.0f, 0.0f, -1.0f);
    const WindSource s = radialSource(WindKind::Vortex, c, 30.0f);
    Rng rng(4);
    for (int i = 0; i < 100; ++i) {
        const glm::vec3 p(rng.uniform(-10, 10), rng.uniform(0, 20), rng.uniform(-10, 10));
        const glm::vec3 w = windAt(s, p, 0.0f);
        glm::vec3 radial = p - c;
        radial.y = 0.0f;
        EXPECT_NEAR(w.y, 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(w, glm::normalize(radial)), 0.0f, 1e-5f) << "i " << i;
        // Counter-clockwise seen from +axis.
        EXPECT_GT(glm::cross(radial, w).y, 0.0f);
    }
}

TEST(Wind, PathInterpolatesLinearlyAndClampsAtTheEnds) {
    const std::vector<PathKey> path{{1.0f, {0, 0, 0}}, {3.0f, {4, 0, 0}}, {4.0f, {4, 2, 0}}};
    EXPECT_EQ(samplePath(path, -5.0f, {9, 9, 9}), glm::vec3(0, 0, 0));
    EXPECT_EQ(samplePath(path, 2.0f, {9, 9, 9}), glm::vec3(2, 0, 0));
    EXPECT_EQ(samplePath(path, 3.5f, {9, 9, 9}), glm::vec3(4, 1, 0));
    EXPECT_EQ(samplePath(path, 100.0f, {9, 9, 9}), glm::vec3(4, 2, 0));
    EXPECT_EQ(samplePath({}, 1.0f, {9, 9, 9}), glm::vec3(9, 9, 9));
    // A moving point source is centred on its path position.
    WindSource s = radialSource(WindKind::Point, {100, 0, 0}, 0.0f);
    s.path = path;
    const glm::vec3 w = windAt(s, glm::vec3(2, 0, 3), 2.0f);
    EXPECT_NEAR(w.x, 0.0f, 1e-6f);
    EXPECT_GT(w.z, 0.0f);
}

TEST(Wind, SourcesAreSummed) {
    const std::vector<WindSource> sources{constantWind({1, 0, 0}, 1.0f),
                                          constantWind({0, 0, 1}, 2.0f),
                                          radialSource(WindKind::Vortex, {0, 0, 0}, 10.0f)};
    const glm::vec3 p(3, 0, 1);
    const glm::vec3 sum =
        windAt(sources[0], p, 1.0f) + windAt(sources[1], p, 1.0f) + windAt(sources[2], p, 1.0f);
    EXPECT_EQ(windAt(sources, p, 1.0f), sum);
    EXPECT_EQ(windAt(std::vector<WindSource>{}, p, 1.0f), glm::vec3(0.0f));
}

TEST(Wind, GustNoiseIsBoundedSmoothAndDeterministic) {
    Rng rng(11);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 p(rng.uniform(-1e4f, 1e4f), rng.uniform(-10, 10), rng.uniform(-1e4f, 1e4f));
        const float n = valueNoise3(p);
        EXPECT_GE(n, 0.0f);
        EXPECT_LE(n, 1.0f);
        EXPECT_EQ(n, valueNoise3(p));
        EXPECT_NEAR(valueNoise3(p + glm::vec3(1e-3f, 0, 0)), n, 1e-2f) << "i " << i;
    }
}

TEST(Wind, NonFiniteInputGivesNoWind) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const WindSource s = radialSource(WindKind::Vortex, {0, 0, 0}, 0.0f);
    EXPECT_EQ(windAt(s, glm::vec3(nan, 0, 0), 0.0f), glm::vec3(0.0f));
    EXPECT_EQ(windAt(s, glm::vec3(1, 0, 0), std::numeric_limits<float>::infinity()),
              glm::vec3(0.0f));
}

}  // namespace
}  // namespace grass::core
