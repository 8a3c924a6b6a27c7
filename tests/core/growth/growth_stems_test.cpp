// Kim & Cho growth geometry (SPEC §9): the paper's level recurrence and test vector, the B-spline
// endpoints and degree rule, vertex counts per stem and per set of 6.
#include <gtest/gtest.h>

#include <cmath>

#include "growth/growth_stems.h"

namespace grass::core {
namespace {

TEST(GrowthStems, PaperTestVectorBeta07) {
    StemSetParams params;
    params.beta = 0.7f;
    params.theta = 0.0f;
    params.spreadZ = 0.0f;
    const auto points = stemLevelPoints(params, 0);
    ASSERT_EQ(points.size(), 5u);
    EXPECT_NEAR(points[1].y, 0.7f, 1e-6f);
    EXPECT_NEAR(points[2].y, 1.19f, 1e-6f);
    EXPECT_NEAR(points[3].y, 1.19f + 0.343f, 1e-5f);
    for (const auto& p : points)
        EXPECT_EQ(p.z, 0.0f) << "no bend, no z spread: the stem stays in its plane";
}

TEST(GrowthStems, BendRotatesTheLevelsTowardsZ) {
    StemSetParams params;
    params.theta = 0.5f;
    params.spreadZ = 0.0f;
    const auto points = stemLevelPoints(params, 2);
    // Level 1: (β cos θ, β sin θ) from the origin.
    EXPECT_NEAR(points[1].y, 0.7f * std::cos(0.5f), 1e-6f);
    EXPECT_NEAR(points[1].z, 0.7f * std::sin(0.5f), 1e-6f);
    EXPECT_GT(points[4].z, points[1].z) << "the bend accumulates level by level";
}

TEST(GrowthStems, LevelsAreClampedToOneToFour) {
    StemSetParams params;
    for (int levels : {-3, 0, 1, 2, 3, 4, 9}) {
        params.levels = levels;
        EXPECT_EQ(stemLevelPoints(params, 0).size(),
                  static_cast<std::size_t>(std::clamp(levels, 1, 4) + 1));
    }
}

TEST(GrowthStems, BSplineInterpolatesItsEndpointsAtEveryDegree) {
    for (int levels = 1; levels <= 4; ++levels) {
        StemSetParams params;
        params.levels = levels;
        params.theta = 0.4f;
        const auto controls = stemLevelPoints(params, 4);
        const glm::vec3 start = clampedBSpline(controls, 0.0f);
        const glm::vec3 end = clampedBSpline(controls, 1.0f);
        EXPECT_LT(glm::length(start - controls.front()), 1e-6f) << levels;
        EXPECT_LT(glm::length(end - controls.back()), 1e-5f) << levels;
    }
}

TEST(GrowthStems, DegreeFollowsThePointCount) {
    // Two points: a line (degree 1); the midpoint is the average.
    const std::vector<glm::vec3> line{{0, 0, 0}, {0, 2, 0}};
    EXPECT_NEAR(clampedBSpline(line, 0.5f).y, 1.0f, 1e-6f);
    // Three points: a quadratic Bézier (the clamped B-spline of degree 2 on 3 points).
    const std::vector<glm::vec3> quad{{0, 0, 0}, {1, 2, 0}, {2, 0, 0}};
    const glm::vec3 mid = clampedBSpline(quad, 0.5f);
    EXPECT_NEAR(mid.x, 1.0f, 1e-6f);
    EXPECT_NEAR(mid.y, 1.0f, 1e-6f);  // 0.25·0 + 0.5·2 + 0.25·0
    // Five points, degree 3: stays within the control polygon's bounds (convex hull).
    const std::vector<glm::vec3> five{{0, 0, 0}, {0, 1, 0}, {0, 2, 1}, {0, 3, 0}, {0, 4, 2}};
    for (int i = 0; i <= 20; ++i) {
        const glm::vec3 p = clampedBSpline(five, static_cast<float>(i) / 20.0f);
        EXPECT_GE(p.y, -1e-6f);
        EXPECT_LE(p.y, 4.0f + 1e-6f);
        EXPECT_GE(p.z, -1e-6f);
        EXPECT_LE(p.z, 2.0f + 1e-6f);
    }
}

TEST(GrowthStems, VertexCountsMatchThePaper) {
    StemSetParams params;
    params.levels = 4;
    EXPECT_EQ(stemRibbon(params, 0, 0.01f).size(), 40u);
    EXPECT_EQ(stemSetVertices(params, 0.01f).size(), 240u);
    params.levels = 1;
    EXPECT_EQ(stemSetVertices(params, 0.01f).size(), 60u);
}

// α has two roles (docs/growth.md, issue 30 item 5): the paper's x_i = ±α/2 ± spread places the
// stem groups α apart, and the ribbon's width (the caller's halfWidth, from the blade's width
// scaled by α/0.25). The ribbon narrows to a point at the tip by default; tip width 1 is the
// paper's constant-width strip, and every share between scales the tip linearly.
TEST(GrowthStems, TipWidthSetsTheRibbonsWidthFromRootToTip) {
    StemSetParams params;
    params.levels = 4;
    const float half = 0.02f;
    const auto widthAt = [&](const std::vector<glm::vec3>& ribbon, std::size_t sample) {
        return glm::length(ribbon[2 * sample + 1] - ribbon[2 * sample]);
    };
    const auto pointed = stemRibbon(params, 0, half);
    const auto strip = stemRibbon(params, 0, half, 1.0f);
    const auto third = stemRibbon(params, 0, half, 0.3f);
    const std::size_t tip = pointed.size() / 2 - 1, middle = tip / 2;
    EXPECT_NEAR(widthAt(pointed, 0), 2.0f * half, 1e-6f);
    EXPECT_NEAR(widthAt(pointed, tip), 0.0f, 1e-6f);
    for (std::size_t i = 0; i <= tip; ++i)
        EXPECT_NEAR(widthAt(strip, i), 2.0f * half, 1e-6f) << i;
    EXPECT_NEAR(widthAt(third, tip), 0.3f * 2.0f * half, 1e-6f);
    const float u = static_cast<float>(middle) / static_cast<float>(tip);
    EXPECT_NEAR(widthAt(third, middle), 2.0f * half * (1.0f - 0.7f * u), 1e-6f);
    // The centre line does not move with the width.
    for (std::size_t i = 0; i <= tip; ++i)
        EXPECT_NEAR(glm::length((strip[2 * i] + strip[2 * i + 1]) -
                                (pointed[2 * i] + pointed[2 * i + 1])),
                    0.0f, 1e-6f);
    // The paper's offset: stems 0 (−x group) and 3 (+x group) stand α apart in x.
    StemSetParams noSpread = params;
    noSpread.spreadX = noSpread.spreadZ = 0.0f;
    noSpread.alpha = 0.2f;
    EXPECT_NEAR(stemLevelPoints(noSpread, 3)[1].x - stemLevelPoints(noSpread, 0)[1].x,
                0.2f, 1e-6f);
}

TEST(GrowthStems, SixStemsAreDistinct) {
    StemSetParams params;
    for (int a = 0; a < STEMS_PER_SET; ++a)
        for (int b = a + 1; b < STEMS_PER_SET; ++b)
            EXPECT_GT(glm::length(stemLevelPoints(params, a).back() -
                                  stemLevelPoints(params, b).back()),
                      1e-4f)
                << a << " vs " << b;
}

}  // namespace
}  // namespace grass::core
