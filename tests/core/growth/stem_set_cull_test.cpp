// The stem sets' cull (issue 24): the bounding sphere holds every vertex the set draws, sets
// outside the view or thinned by distance are not drawn (SPEC §6's rules, as for blades), the
// editor's uniform thinning keeps one in N, and LOD follows SPEC §7's distance classes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "growth/stem_set_cull.h"

namespace grass::core {
namespace {

StemSetInstance setAt(glm::vec3 root, float metresPerUnit = 0.2f) {
    StemSetInstance set;
    set.rootMetresPerUnit = glm::vec4(root, metresPerUnit);
    return set;
}

// A camera at (0, 2, 10) looking at the origin, 45° field of view, 16:9.
struct View {
    glm::vec3 eye{0.0f, 2.0f, 10.0f};
    glm::mat4 viewProj = glm::perspective(glm::radians(45.0f), 16.0f / 9.0f, 0.1f, 500.0f) *
                         glm::lookAt(glm::vec3(0.0f, 2.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
};

TEST(StemSetCull, BoundHoldsEveryVertexOfTheSet) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 200; ++trial) {
        StemSetInstance set = setAt({0, 0, 0}, 0.05f + unit(rng));
        set.alphaBetaThetaB = {0.25f * unit(rng), unit(rng), 1.0472f * unit(rng), 1.0f};
        set.halfWidthSpread = {0.05f * unit(rng), 0.2f * unit(rng), 0.2f * unit(rng), 0.0f};
        for (int levels = 1; levels <= MAX_STEM_LEVELS; ++levels) {
            StemSetParams params;
            params.alpha = set.alphaBetaThetaB.x;
            params.beta = set.alphaBetaThetaB.y;
            params.theta = set.alphaBetaThetaB.z;
            params.levels = levels;
            params.spreadX = set.halfWidthSpread.y;
            params.spreadZ = set.halfWidthSpread.z;
            const float radius = stemSetBoundRadius(set, levels);
            // The frame is a rotation and the scale uniform: distance from the root is |p|·scale.
            for (const glm::vec3 p : stemSetVertices(params, set.halfWidthSpread.x))
                ASSERT_LE(glm::length(p) * set.rootMetresPerUnit.w, radius * (1.0f + 1e-5f))
                    << "trial " << trial << ", levels " << levels;
        }
    }
}

TEST(StemSetCull, SetsBehindTheCameraOrBesideTheViewAreCulled) {
    const View view;
    const std::vector<StemSetInstance> sets{setAt({0, 0, 0}), setAt({0, 0, 30}),
                                            setAt({80, 0, 0}), setAt({1, 0, -2})};
    StemSetCullSettings settings;
    settings.distance = false;
    StemSetCullResult result;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.setsIn, 4u);
    EXPECT_EQ(result.culledFrustum, 2u) << "behind the camera, far to the side";
    EXPECT_EQ(result.drawn(), 2u);
    settings.frustum = false;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.drawn(), 4u) << "with the test off every set is drawn";
}

TEST(StemSetCull, ASetAtTheEdgeOfTheViewStaysWhileAnyOfItCanShow) {
    const View view;
    // The left edge at the origin's depth is 10.2·tan(22.5°)·16/9 ≈ 7.51 m out. A root 7.8 m
    // out is outside by 0.23 m from the plane, but its stems reach 0.2·Σ(0.7^i + 0.05) + ... ≈
    // 0.39 m: it stays. At 8.5 m (0.8 m from the plane) none of it can show.
    const std::vector<StemSetInstance> sets{setAt({-7.8f, 0, 0}), setAt({-8.5f, 0, 0})};
    StemSetCullSettings settings;
    settings.distance = false;
    StemSetCullResult result;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.visible[1], std::vector<std::uint32_t>{0});
    EXPECT_EQ(result.culledFrustum, 1u);
}

TEST(StemSetCull, NullSetsAreNeitherCountedNorDrawn) {
    const View view;
    std::vector<StemSetInstance> sets{setAt({0, 0, 0}), setAt({0, 0, 0}, 0.0f)};
    StemSetCullResult result;
    cullStemSets(sets, 4, view.viewProj, view.eye, StemSetCullSettings{}, result);
    EXPECT_EQ(result.setsIn, 1u);
    EXPECT_EQ(result.drawn(), 1u);
}

TEST(StemSetCull, DistanceThinsByClassAsBladesDo) {
    const View view;
    // 800 sets 50 m away along the view axis (dproj 50 m of dmax 100): ceil(8·0.5) = 4 of 8
    // classes stay.
    std::vector<StemSetInstance> sets(800, setAt({0, 0, 10.0f - 50.0f}));
    StemSetCullSettings settings;
    StemSetCullResult result;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.drawn(), 400u);
    EXPECT_EQ(result.culledDistance, 400u);
    for (const auto& list : result.visible)
        for (std::uint32_t i : list)
            EXPECT_LT(i % 8u, 4u);
    settings.distance = false;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.drawn(), 800u);
}

TEST(StemSetCull, UniformThinningKeepsOneInN) {
    const View view;
    std::vector<StemSetInstance> sets(64, setAt({0, 0, 0}));
    StemSetCullSettings settings;
    settings.keepEvery = 4;
    StemSetCullResult result;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.drawn(), 16u);
    for (std::uint32_t i : result.visible[0])
        EXPECT_EQ(i % 4u, 0u);
}

TEST(StemSetCull, LevelOfDetailFollowsTheBladesDistanceClasses) {
    const View view;
    // 2, 12 and 30 m from the camera with lodDistance 8: LOD 0, 1 (< 24 m) and 2.
    const std::vector<StemSetInstance> sets{setAt({0, 2, 8}), setAt({0, 2, -2}), setAt({0, 2, -20})};
    StemSetCullSettings settings;
    settings.distance = false;
    StemSetCullResult result;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    ASSERT_EQ(result.visible[0], std::vector<std::uint32_t>{0});
    ASSERT_EQ(result.visible[1], std::vector<std::uint32_t>{1});
    ASSERT_EQ(result.visible[2], std::vector<std::uint32_t>{2});
    settings.lodDistanceM = 0.0f;
    cullStemSets(sets, 4, view.viewProj, view.eye, settings, result);
    EXPECT_EQ(result.visible[0].size(), 3u) << "lodDistance 0: full detail everywhere";
    EXPECT_EQ(STEM_SET_LOD_SAMPLES[0], STEM_SAMPLES_PER_LEVEL);
}

}  // namespace
}  // namespace grass::core
