#include "blade/bezier.h"

#include <gtest/gtest.h>

#include "util/rng.h"

namespace grass::core {
namespace {

// Reference arc length by brute-force polyline with many segments (converges as 1/n²).
double polylineLength(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, int n) {
    double length = 0.0;
    glm::dvec3 prev = p0;
    for (int i = 1; i <= n; ++i) {
        const glm::dvec3 p = bezierPoint(p0, p1, p2, static_cast<float>(i) / static_cast<float>(n));
        length += glm::length(p - prev);
        prev = p;
    }
    return length;
}

TEST(Bezier, EndpointsAreControlPoints) {
    const glm::vec3 p0(0, 0, 0), p1(0, 1, 0), p2(1, 1, 0);
    EXPECT_EQ(bezierPoint(p0, p1, p2, 0.0f), p0);
    EXPECT_EQ(bezierPoint(p0, p1, p2, 1.0f), p2);
    const glm::vec3 mid = bezierPoint(p0, p1, p2, 0.5f);
    EXPECT_FLOAT_EQ(mid.x, 0.25f);
    EXPECT_FLOAT_EQ(mid.y, 0.75f);
}

TEST(Bezier, TangentMatchesFiniteDifference) {
    const glm::vec3 p0(0, 0, 0), p1(0.2f, 1, 0.1f), p2(1, 1.3f, -0.4f);
    for (float v : {0.1f, 0.5f, 0.9f}) {
        const float e = 1e-3f;
        const glm::vec3 fd =
            (bezierPoint(p0, p1, p2, v + e) - bezierPoint(p0, p1, p2, v - e)) / (2 * e);
        const glm::vec3 t = bezierTangent(p0, p1, p2, v);
        EXPECT_NEAR(glm::length(fd - t), 0.0f, 1e-3f) << "v=" << v;
    }
}

TEST(Bezier, ArcLengthOfStraightLineIsDistance) {
    EXPECT_NEAR(bezierArcLength({0, 0, 0}, {0, 0.5f, 0}, {0, 1, 0}), 1.0f, 1e-6f);
    // Uneven parametrisation of a straight segment: still its length.
    EXPECT_NEAR(bezierArcLength({0, 0, 0}, {0, 0.9f, 0}, {0, 1, 0}), 1.0f, 1e-5f);
    EXPECT_NEAR(bezierArcLength({1, 1, 1}, {1, 1, 1}, {1, 1, 1}), 0.0f, 1e-7f);
}

TEST(Bezier, ArcLengthMatchesPolylineOnRandomCurves) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        Rng rng(seed);
        auto rnd = [&] {
            return glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        };
        const glm::vec3 p0 = rnd(), p1 = rnd(), p2 = rnd();
        const double reference = polylineLength(p0, p1, p2, 20000);
        EXPECT_NEAR(bezierArcLength(p0, p1, p2), reference, 1e-4 * reference + 1e-6)
            << "seed " << seed;
    }
}

TEST(Bezier, ArcLengthOfFoldedBackCurve) {
    // p1 beyond p2 on one line: the curve goes out and comes back.
    const glm::vec3 p0(0, 0, 0), p1(0, 2, 0), p2(0, 1, 0);
    EXPECT_NEAR(bezierArcLength(p0, p1, p2), polylineLength(p0, p1, p2, 20000), 1e-4);
}

TEST(Bezier, LengthEstimateIsExactForStraightAndCloseForBent) {
    EXPECT_NEAR(bezierLengthEstimate({0, 0, 0}, {0, 0.5f, 0}, {0, 1, 0}), 1.0f, 1e-6f);
    // A quarter-bent blade: the estimate of Jahrmann §5.2 is within 2 % of the true length.
    const glm::vec3 p0(0, 0, 0), p1(0, 1, 0), p2(0.8f, 1.0f, 0);
    const float exact = bezierArcLength(p0, p1, p2);
    EXPECT_NEAR(bezierLengthEstimate(p0, p1, p2), exact, 0.02f * exact);
}

}  // namespace
}  // namespace grass::core
