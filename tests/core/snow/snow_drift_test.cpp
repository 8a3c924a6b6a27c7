// Snow drifting with the wind (issue 30 item 2): the drift factor D from the maximum upwind
// slope over the depth map — more snow in the lee of a block, less on its windward crest, none
// changed on open flat ground or without drift — its smooth reading between cells, the wind
// direction it follows, and what it does to the depth and the coverage.
#include "snow/snow_drift.h"

#include <gtest/gtest.h>

#include <cmath>

#include "snow/snow.h"
#include "support/snow_triangles.h"

namespace grass::core {
namespace {

using Triangle = test::SnowTriangle;
using test::addRect;

// Flat ground 24 m across with a 1 m block, 1 m high, over the origin; snow falls straight down
// on a 512² map (4.7 cm texels, 37.5 cm cells).
SnowDepthMap blockMap() {
    std::vector<Triangle> triangles;
    addRect(triangles, -12.0f, 12.0f, -12.0f, 12.0f, 0.0f);
    addRect(triangles, -0.5f, 0.5f, -0.5f, 0.5f, 1.0f);
    const OrthoSnowView view =
        makeOrthoSnowView({0.0f, -1.0f, 0.0f}, {{-12.0f, 0.0f, -12.0f}, {12.0f, 1.0f, 12.0f}}, 0.1f);
    return renderSnowDepthMap(triangles, view, 512);
}

SnowParams driftingSnow(float drift, glm::vec3 to) {
    SnowParams params;
    params.enabled = 1u;
    params.drift = drift;
    params.driftReachM = 4.0f;
    params.driftFollowsWind = 0u;
    params.driftDirection = to;
    return params;
}

float driftAt(const SnowDepthMap& map, const SnowParams& params, glm::vec3 p) {
    const SnowDriftMap drift =
        computeSnowDriftMap(map, params, snowDriftMapDirection(map.view, params.driftDirection));
    return snowDriftFactorAt(drift, map.view, p);
}

TEST(SnowDrift, TheLeeOfABlockGathersSnowAndItsWindwardCrestLosesIt) {
    const SnowDepthMap map = blockMap();
    const SnowParams params = driftingSnow(1.0f, {1.0f, 0.0f, 0.0f});
    // Open flat ground far from the block: no shelter, no scour.
    EXPECT_NEAR(driftAt(map, params, {-8.0f, 0.0f, 5.0f}), 1.0f, 1e-3f);
    EXPECT_NEAR(driftAt(map, params, {8.0f, 0.0f, -6.0f}), 1.0f, 1e-3f);
    // Upwind of the block the ground sees nothing higher upwind.
    EXPECT_NEAR(driftAt(map, params, {-2.0f, 0.0f, 0.0f}), 1.0f, 1e-3f);
    // Right behind it, the block stands 1 m high within 2.5 m: Sx > 20°, the snow doubles.
    EXPECT_NEAR(driftAt(map, params, {1.5f, 0.0f, 0.0f}), 2.0f, 1e-3f);
    EXPECT_NEAR(driftAt(map, params, {2.5f, 0.0f, 0.0f}), 2.0f, 1e-3f);
    // Further back the shelter weakens: at 3.8 m from the block Sx = atan(1/3.8..) ≈ 14°.
    const float further = driftAt(map, params, {4.3f, 0.0f, 0.0f});
    EXPECT_GT(further, 1.4f);
    EXPECT_LT(further, 1.95f);
    // Beyond the reach nothing shelters.
    EXPECT_NEAR(driftAt(map, params, {6.0f, 0.0f, 0.0f}), 1.0f, 1e-3f);
    // Beside the block (its lee does not reach sideways).
    EXPECT_NEAR(driftAt(map, params, {2.0f, 0.0f, 3.0f}), 1.0f, 1e-3f);
    // On the block's top the nearest upwind samples are level with it: Sx = 0, as Winstral's
    // maximum has it (a plateau is not a crest).
    EXPECT_NEAR(driftAt(map, params, {0.0f, 1.0f, 0.0f}), 1.0f, 1e-3f);
}

// A 1.5 m bank rising downwind over 3 m (26.6°) to a plateau: the wind scours the slope that
// faces it, and drops the snow over the far edge.
TEST(SnowDrift, AWindwardSlopeIsScouredAndTheFarSideGathers) {
    std::vector<Triangle> triangles;
    addRect(triangles, -12.0f, 12.0f, -12.0f, 12.0f, 0.0f);
    triangles.push_back({glm::vec3(-3, 0, -3), glm::vec3(0, 1.5f, -3), glm::vec3(0, 1.5f, 3)});
    triangles.push_back({glm::vec3(-3, 0, -3), glm::vec3(0, 1.5f, 3), glm::vec3(-3, 0, 3)});
    addRect(triangles, 0.0f, 3.0f, -3.0f, 3.0f, 1.5f);
    const SnowDepthMap map = renderSnowDepthMap(
        triangles,
        makeOrthoSnowView({0, -1, 0}, {{-12.0f, 0.0f, -12.0f}, {12.0f, 1.5f, 12.0f}}, 0.1f), 512);
    const SnowParams params = driftingSnow(1.0f, {1.0f, 0.0f, 0.0f});
    // Half-way up the bank the steepest upwind view is the open ground 3 m back, 1 m below:
    // about −14° with the 4 m reach (the slope itself is −26.6° near by).
    const float bank = driftAt(map, params, {-1.0f, 1.0f, 0.0f});
    EXPECT_LT(bank, 0.45f);
    EXPECT_GT(bank, 0.15f);
    EXPECT_NEAR(driftAt(map, params, {2.0f, 1.5f, 0.0f}), 1.0f, 1e-3f);   // the plateau
    EXPECT_NEAR(driftAt(map, params, {4.0f, 0.0f, 0.0f}), 2.0f, 1e-3f);   // below its far edge
}

TEST(SnowDrift, DriftScalesTheChangeAndZeroChangesNothing) {
    const SnowDepthMap map = blockMap();
    EXPECT_NEAR(driftAt(map, driftingSnow(0.4f, {1, 0, 0}), {2.0f, 0.0f, 0.0f}), 1.4f, 1e-3f);
    EXPECT_NEAR(driftAt(map, driftingSnow(0.4f, {1, 0, 0}), {-0.3f, 1.0f, 0.0f}),
                1.0f - 0.4f * (1.0f - driftAt(map, driftingSnow(1.0f, {1, 0, 0}), {-0.3f, 1.0f, 0.0f})),
                1e-3f);
    const SnowParams none = driftingSnow(0.0f, {1, 0, 0});
    EXPECT_TRUE(computeSnowDriftMap(map, none, {1.0f, 0.0f}).factor.empty());
    EXPECT_EQ(driftAt(map, none, {2.0f, 0.0f, 0.0f}), 1.0f);
    // Wind along the fall has no direction across the map: no drift either.
    EXPECT_EQ(snowDriftMapDirection(map.view, {0.0f, -3.0f, 0.0f}), glm::vec2(0.0f));
    EXPECT_EQ(driftAt(map, driftingSnow(1.0f, {0.0f, -1.0f, 0.0f}), {2.0f, 0.0f, 0.0f}), 1.0f);
}

TEST(SnowDrift, TurningTheWindMirrorsTheDrift) {
    const SnowDepthMap map = blockMap();
    for (const float x : {0.8f, 1.7f, 3.1f, 4.4f, -0.3f}) {
        const float y = std::abs(x) < 0.5f ? 1.0f : 0.0f;
        EXPECT_NEAR(driftAt(map, driftingSnow(1.0f, {1, 0, 0}), {x, y, 0.1f}),
                    driftAt(map, driftingSnow(1.0f, {-1, 0, 0}), {-x, y, 0.1f}), 0.06f)
            << x;
        // Along z the same block drifts the same way.
        EXPECT_NEAR(driftAt(map, driftingSnow(1.0f, {1, 0, 0}), {x, y, 0.1f}),
                    driftAt(map, driftingSnow(1.0f, {0, 0, 1}), {0.1f, y, x}), 0.06f)
            << x;
    }
}

TEST(SnowDrift, TheFactorIsContinuousAcrossCells) {
    // A per-point Sx jumps wherever a sample crosses the block's edge; read between cell centres
    // the factor moves by at most a cell's change over a cell (37.5 cm here), so 1 cm steps
    // move it by a few hundredths, never by the 1.0 a jump would.
    const SnowDepthMap map = blockMap();
    const SnowParams params = driftingSnow(1.0f, {1, 0, 0});
    const SnowDriftMap drift =
        computeSnowDriftMap(map, params, snowDriftMapDirection(map.view, params.driftDirection));
    float previous = snowDriftFactorAt(drift, map.view, {0.6f, 0.0f, 0.2f});
    float largest = 0.0f;
    for (int i = 1; i <= 600; ++i) {
        const float x = 0.6f + 0.01f * static_cast<float>(i);
        const float d = snowDriftFactorAt(drift, map.view, {x, 0.0f, 0.2f});
        largest = std::max(largest, std::abs(d - previous));
        previous = d;
    }
    EXPECT_LT(largest, 0.04f);
    EXPECT_NEAR(previous, 1.0f, 1e-3f);  // back to open ground at x = 6.6
}

TEST(SnowDrift, TheDriftFollowsTheDirectionalWinds) {
    SnowParams params = driftingSnow(1.0f, {0.0f, 0.0f, 1.0f});
    params.driftFollowsWind = 1u;
    WindSource east;
    east.direction = {2.0f, 0.0f, 0.0f};
    east.strength = 2.0f;
    WindSource north;
    north.direction = {0.0f, 0.0f, 1.0f};
    north.strength = 1.0f;
    WindSource tornado;
    tornado.kind = WindKind::Vortex;
    tornado.strength = 50.0f;
    const std::vector<WindSource> wind{east, north, tornado};
    const glm::vec3 to = snowDriftWorldDirection(params, wind);
    EXPECT_NEAR(glm::length(glm::normalize(to) - glm::normalize(glm::vec3(2, 0, 1))), 0.0f, 1e-5f);
    EXPECT_EQ(snowDriftWorldDirection(params, {}), glm::vec3(0.0f));
    const SnowParams resolved = snowWithWindDrift(params, wind);
    EXPECT_EQ(resolved.driftFollowsWind, 0u);
    EXPECT_EQ(resolved.driftDirection, to);
    params.driftFollowsWind = 0u;
    EXPECT_EQ(snowDriftWorldDirection(params, wind), glm::vec3(0.0f, 0.0f, 1.0f));
}

TEST(SnowDrift, DriftScalesTheDepthAndScourOnlyTheCoverage) {
    SnowParams params;
    params.enabled = 1u;
    params.amountM = 0.3f;
    const glm::vec3 p(1.0f, 0.0f, 2.0f), up(0.0f, 1.0f, 0.0f);
    const float depth = snowDepthAt(p, 1.0f, params);
    EXPECT_FLOAT_EQ(snowDepthAt(p, 1.0f, params, 1.8f), 1.8f * depth);
    EXPECT_FLOAT_EQ(glm::length(snowDisplacement(p, up, 1.0f, params, 0.5f)), 0.5f * depth);
    const SnowShade plain = shadeSnow(params, p, up, 1.0f, 1.0f, glm::vec3(0.2f));
    const SnowShade lee = shadeSnow(params, p, up, 1.0f, 1.0f, glm::vec3(0.2f), 1.8f);
    const SnowShade scoured = shadeSnow(params, p, up, 1.0f, 1.0f, glm::vec3(0.2f), 0.25f);
    EXPECT_EQ(lee.Fp, plain.Fp);  // a drift is no whiter than full snow
    EXPECT_FLOAT_EQ(scoured.Fp, 0.25f * plain.Fp);
    EXPECT_FLOAT_EQ(lee.displacement.y, 1.8f * plain.displacement.y);
    // Without drift, bit for bit what it was.
    EXPECT_EQ(shadeSnow(params, p, up, 0.7f, 0.6f, glm::vec3(0.2f), 1.0f).displacement,
              shadeSnow(params, p, up, 0.7f, 0.6f, glm::vec3(0.2f)).displacement);
}

}  // namespace
}  // namespace grass::core
