#include "physics/physics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "blade/bezier.h"
#include "support/physics_cases.h"
#include "util/rng.h"

namespace grass::core {
namespace {

// The length tolerance, finiteness and the extremes sweep are shared with the GPU execution.
using test::isFinite;
using test::lengthEstimate;
using test::lengthTolerance;

glm::vec3 randomUnit(Rng& rng) {
    for (;;) {
        const glm::vec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f)
            return v / l;
    }
}

Blade randomBlade(Rng& rng) {
    const glm::vec3 v0(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
    const glm::vec3 up = randomUnit(rng);
    const float h = rng.uniform(0.05f, 2.0f);
    Blade b = makeRestBlade(v0, up, h, 0.01f, rng.uniform(0.0f, 50.0f), rng.uniform(0.0f, 6.28f));
    b.v2W = glm::vec4(v0 + randomUnit(rng) * (h * rng.uniform(0.0f, 2.0f)), b.w());
    return b;
}

std::vector<WindSource> randomWind(Rng& rng) {
    WindSource s;
    s.direction = randomUnit(rng);
    s.strength = rng.uniform(0.0f, 100.0f);
    s.gust = rng.uniform(0.0f, 1.0f);
    return {s};
}

PhysicsParams randomParams(Rng& rng) {
    PhysicsParams p;
    p.gravity = glm::vec4(randomUnit(rng), rng.uniform(0.0f, 30.0f));
    p.dtS = std::pow(10.0f, rng.uniform(-4.0f, 1.0f));
    return p;
}

PhysicsParams noGravity() {
    PhysicsParams p;
    p.gravity.w = 0.0f;
    return p;
}

TEST(Physics, ValidationKeepsBladeLength) {
    float maxRel = 0.0f, maxArcRel = 0.0f;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        Rng rng(seed);
        Blade b = randomBlade(rng);
        const glm::vec3 tip = restTip(b);
        float eta = 0.0f;
        stepBlade(b, eta, tip, randomParams(rng), randomWind(rng), {}, rng.uniform(0, 100));
        ASSERT_TRUE(isFinite(b)) << "seed " << seed;
        EXPECT_NEAR(lengthEstimate(b), b.h(), lengthTolerance(b)) << "seed " << seed;
        maxRel = std::max(maxRel, std::abs(lengthEstimate(b) - b.h()) / b.h());
        const float arc = bezierArcLength(b.v0(), b.v1(), b.v2());
        maxArcRel = std::max(maxArcRel, std::abs(arc - b.h()) / b.h());
    }
    std::printf("max relative error: length estimate %.3g, exact arc length %.3g\n", maxRel,
                maxArcRel);
}

TEST(Physics, TipNeverGoesBelowTheGroundPlane) {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        Rng rng(seed + 5000);
        Blade b = randomBlade(rng);
        const glm::vec3 tip = restTip(b);
        float eta = 0.0f;
        const PhysicsParams params = randomParams(rng);
        const auto wind = randomWind(rng);
        for (int step = 0; step < 5; ++step)
            stepBlade(b, eta, tip, params, wind, {}, 0.0f);
        EXPECT_GE(glm::dot(b.up(), b.v2() - b.v0()), -lengthTolerance(b)) << "seed " << seed;
    }
}

// SPEC §3 / issue 4: every combination of the extremes, with wind, gravity and a collider
// (tests/support/physics_cases.h); returns the largest relative length error.
float runExtremes(const std::function<PhysicsParams(const test::ExtremeCase&)>& paramsFor) {
    float maxRel = 0.0f;
    const std::vector<test::ExtremeCase> cases = test::extremeCases();
    EXPECT_EQ(cases.size(), 810u);
    for (const test::ExtremeCase& c : cases) {
        const PhysicsParams params = paramsFor(c);
        const std::vector<WindSource> wind = test::extremeWind(c);
        const std::vector<SphereCollider> colliders = test::extremeColliders(c);
        Blade b = test::extremeBlade(c);
        const glm::vec3 tip = restTip(b);
        float eta = 0.0f;
        for (int step = 0; step < test::EXTREME_STEP_COUNT; ++step) {
            const glm::vec3 before = b.v2();
            stepBlade(b, eta, tip, params, wind, colliders, test::extremeStepTimeS(c, step));
            if (!test::keepsExtremeInvariants(b, eta, c, before)) {
                ADD_FAILURE() << test::describeCase(c) << " step " << step;
                return maxRel;
            }
            maxRel = std::max(maxRel, test::relativeLengthError(b, c.h));
        }
    }
    return maxRel;
}

TEST(Physics, ExtremesStayFiniteAboveGroundAndKeepLength) {
    const float maxRel =
        runExtremes([](const test::ExtremeCase& c) { return test::extremeParams(c); });
    std::printf("810 combinations, max relative length error %.3g\n", maxRel);
}

// Issue 10: the same sweep at every quality preset (their substep policies differ).
class PhysicsAtPreset : public ::testing::TestWithParam<QualityPreset> {};

TEST_P(PhysicsAtPreset, ExtremesStayFiniteAboveGroundAndKeepLength) {
    const QualityPreset preset = GetParam();
    const float maxRel = runExtremes(
        [preset](const test::ExtremeCase& c) { return test::extremeParams(c, preset); });
    std::printf("%s: 810 combinations, max relative length error %.3g\n",
                std::string(qualityPresetName(preset)).c_str(), maxRel);
}

INSTANTIATE_TEST_SUITE_P(Presets, PhysicsAtPreset, ::testing::ValuesIn(QUALITY_PRESETS),
                         [](const auto& preset) {
                             return std::string(qualityPresetName(preset.param));
                         });

TEST(Physics, DegenerateBladesAreReportedAndRepaired) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // 0: h = 0, 1: v2 == v0, 2: up = 0, 3: NaN tip, 4: NaN root and s, then more of the rule.
    std::vector<Blade> blades = test::degenerateBlades();
    EXPECT_EQ(checkBlade(blades[0]), "");
    EXPECT_EQ(checkBlade(blades[1]), "");
    EXPECT_EQ(checkBlade(blades[2]), "up has zero length");
    EXPECT_EQ(checkBlade(blades[3]), "control point v1 or v2 is not finite");
    const Result<void> checked = checkBlades(blades, "field.grass");
    ASSERT_FALSE(checked.ok());
    EXPECT_EQ(checked.error().str(), "field.grass: blade 2: up has zero length");

    std::vector<glm::vec3> tips = restTips(blades);
    std::vector<float> eta(blades.size(), nan);
    WindSource wind;
    wind.strength = 3.0f;
    for (int step = 0; step < 30; ++step)
        stepPhysics(blades, eta, tips, PhysicsParams{}, {wind}, {}, 0.1f * float(step));
    for (std::size_t i = 0; i < blades.size(); ++i) {
        EXPECT_TRUE(isFinite(blades[i])) << "blade " << i;
        EXPECT_TRUE(std::isfinite(eta[i]));
    }
    // h = 0 stays on its root; the repaired up is +y; the folded blade unfolds (recovery s = 0,
    // but gravity and wind act); NaN root goes to the origin with h = 0.
    EXPECT_EQ(blades[0].v2(), glm::vec3(1, 0, 0));
    EXPECT_EQ(blades[2].up(), glm::vec3(0, 1, 0));
    EXPECT_NEAR(lengthEstimate(blades[1]), 1.0f, 1e-4f);
    EXPECT_NEAR(lengthEstimate(blades[3]), 1.0f, 1e-4f);
    EXPECT_EQ(blades[4].v2(), glm::vec3(0.0f));
}

TEST(Physics, BladeWithoutForcesStaysAtRest) {
    Rng rng(1);
    std::vector<Blade> blades;
    for (int i = 0; i < 100; ++i)
        blades.push_back(
            makeRestBlade(randomUnit(rng), randomUnit(rng), 0.5f, 0.01f, 10.0f, rng.uniform(0, 6)));
    const std::vector<Blade> before = blades;
    std::vector<float> eta(blades.size(), 0.0f);
    const auto tips = restTips(blades);
    for (int step = 0; step < 100; ++step)
        stepPhysics(blades, eta, tips, noGravity(), {}, {}, 0.0f);
    EXPECT_EQ(blades, before);
}

TEST(Physics, GravityDroopsTheBladeAndConverges) {
    Blade b = makeRestBlade({0, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 20.0f, 0.3f);
    const glm::vec3 tip = restTip(b);
    float eta = 0.0f;
    const PhysicsParams params;
    for (int step = 0; step < 600; ++step)
        stepBlade(b, eta, tip, params, {}, {}, 0.0f);
    const glm::vec3 settled = b.v2();
    EXPECT_LT(settled.y, 0.95f);
    EXPECT_GT(settled.y, 0.2f);
    for (int step = 0; step < 600; ++step)
        stepBlade(b, eta, tip, params, {}, {}, 0.0f);
    EXPECT_LT(glm::length(b.v2() - settled), 1e-5f);
    // One stalled 10 s frame lands on the same steady state.
    Blade big = makeRestBlade({0, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 20.0f, 0.3f);
    PhysicsParams stalled = params;
    stalled.dtS = 10.0f;
    stepBlade(big, eta, tip, stalled, {}, {}, 0.0f);
    EXPECT_LT(glm::length(big.v2() - settled), 1e-2f);
    std::printf("steady tip (%.4f %.4f %.4f); after one dt = 10 s step off by %.3g m\n", settled.x,
                settled.y, settled.z, glm::length(big.v2() - settled));
}

TEST(Physics, RecoveryReturnsAPushedBladeTowardsItsRestTip) {
    Blade b = makeRestBlade({0, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 5.0f, 0.0f);
    const glm::vec3 tip = restTip(b);
    b.v2W = glm::vec4(0.9f, 0.1f, 0.0f, 0.01f);
    validateBlade(b);
    float eta = 0.0f;
    float previous = glm::length(b.v2() - tip);
    for (int step = 0; step < 300; ++step) {
        stepBlade(b, eta, tip, noGravity(), {}, {}, 0.0f);
        const float now = glm::length(b.v2() - tip);
        EXPECT_LE(now, previous + 1e-6f) << "step " << step;
        previous = now;
    }
    EXPECT_LT(previous, 1e-3f);
}

TEST(Physics, SphereCollisionPushesTheTipOutAndEtaDecaysAtRateA) {
    Blade b = makeRestBlade({0, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 5.0f, 0.0f);
    const glm::vec3 tip = restTip(b);
    float eta = 0.0f;
    const SphereCollider ball{{0.3f, 1.0f, 0.0f}, 0.4f, {}};
    PhysicsParams params = noGravity();
    stepBlade(b, eta, tip, params, {}, {ball}, 0.0f);
    EXPECT_GT(glm::length(b.v2() - ball.centre), 0.4f - 1e-3f);
    EXPECT_LT(b.v2().x, 0.0f);
    EXPECT_GT(eta, 0.0f);
    // Without the ball, η falls at a = 0.5/s.
    eta = 2.0f;
    params.dtS = 1.0f;
    stepBlade(b, eta, tip, params, {}, {}, 0.0f);
    EXPECT_NEAR(eta, 1.5f, 1e-5f);
    for (int step = 0; step < 10; ++step)
        stepBlade(b, eta, tip, params, {}, {}, 0.0f);
    EXPECT_EQ(eta, 0.0f);
}

TEST(Physics, CrushedBladesRecoverMoreSlowly) {
    Blade fresh = makeRestBlade({0, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 5.0f, 0.0f);
    const glm::vec3 tip = restTip(fresh);
    fresh.v2W = glm::vec4(0.9f, 0.1f, 0.0f, 0.01f);
    validateBlade(fresh);
    Blade crushed = fresh;
    float etaFresh = 0.0f, etaCrushed = 5.0f;
    PhysicsParams params = noGravity();
    params.etaDecayPerS = 0.0f;
    for (int step = 0; step < 30; ++step) {
        stepBlade(fresh, etaFresh, tip, params, {}, {}, 0.0f);
        stepBlade(crushed, etaCrushed, tip, params, {}, {}, 0.0f);
    }
    // Recovery is weakened to max(1 − η, 0.1) = 10%.
    EXPECT_LT(glm::length(fresh.v2() - tip), 0.5f * glm::length(crushed.v2() - tip));
}

TEST(Physics, CentreGravityLeansBladesOnTheFarSideTowardsTheCentre) {
    // A blade on the underside of a planet of radius 10, pointing away from it (-y).
    const glm::vec3 centre(0.0f);
    const Blade start = makeRestBlade({0, -10, 0}, {0, -1, 0}, 1.0f, 0.01f, 5.0f, 0.0f);
    const glm::vec3 tip = restTip(start);
    PhysicsParams towardsCentre;
    towardsCentre.gravityMode = GravityMode::Centre;
    towardsCentre.gravity = glm::vec4(centre, 9.81f);
    PhysicsParams down;  // world -y: along this blade's up, it only stretches it
    Blade a = start, b = start;
    float etaA = 0.0f, etaB = 0.0f;
    for (int step = 0; step < 300; ++step) {
        stepBlade(a, etaA, tip, towardsCentre, {}, {}, 0.0f);
        stepBlade(b, etaB, tip, down, {}, {}, 0.0f);
    }
    EXPECT_LT(glm::length(a.v2() - centre), 10.6f);
    EXPECT_GT(glm::length(b.v2() - centre), 10.95f);
}

TEST(Physics, ResultsDoNotDependOnTheThreadCount) {
    Rng rng(42);
    std::vector<Blade> blades;
    for (int i = 0; i < 6000; ++i) {
        const glm::vec3 v0(rng.uniform(-10, 10), 0.0f, rng.uniform(-10, 10));
        blades.push_back(makeRestBlade(v0, {0, 1, 0}, rng.uniform(0.2f, 1.0f), 0.01f,
                                       rng.uniform(1, 20), rng.uniform(0, 6)));
    }
    const auto tips = restTips(blades);
    WindSource gusty;
    gusty.strength = 4.0f;
    gusty.gust = 0.5f;
    const std::vector<WindSource> wind{gusty};
    const std::vector<SphereCollider> balls{
        {{0, 0.3f, 0}, 1.5f, {{0.0f, {-10, 0.3f, 0}}, {1.0f, {10, 0.3f, 0}}}}};
    std::vector<Blade> one = blades, four = blades;
    std::vector<float> etaOne(blades.size(), 0.0f), etaFour(blades.size(), 0.0f);
    for (int step = 0; step < 20; ++step) {
        const float t = static_cast<float>(step) / 60.0f;
        stepPhysics(one, etaOne, tips, PhysicsParams{}, wind, balls, t, 1);
        stepPhysics(four, etaFour, tips, PhysicsParams{}, wind, balls, t, 4);
    }
    EXPECT_EQ(one, four);
    EXPECT_EQ(etaOne, etaFour);
    EXPECT_GT(std::count_if(etaOne.begin(), etaOne.end(), [](float e) { return e > 0.0f; }), 0);
}

// Three spheres rolling together, as a packed mesh gives them.
std::vector<SphereCollider> rollingCluster() {
    std::vector<SphereCollider> spheres;
    for (const glm::vec3 offset :
         {glm::vec3(0.0f), glm::vec3(0.6f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 0.7f)}) {
        SphereCollider sphere;
        sphere.centre = glm::vec3(-5.0f, 0.3f, 0.0f) + offset;
        sphere.radiusM = 0.5f;
        sphere.path = {{0.0f, sphere.centre}, {0.5f, sphere.centre + glm::vec3(10.0f, 0, 0)}};
        spheres.push_back(sphere);
    }
    return spheres;
}

// The broad phase of a sphere group must not change results: its bound is conservative.
TEST(Physics, ColliderGroupBoundSkipsWithoutChangingResults) {
    Rng rng(9);
    std::vector<Blade> blades;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 v0(rng.uniform(-6, 6), 0.0f, rng.uniform(-3, 3));
        blades.push_back(makeRestBlade(v0, {0, 1, 0}, rng.uniform(0.2f, 0.6f), 0.01f,
                                       rng.uniform(10, 60), rng.uniform(0, 6)));
    }
    const auto tips = restTips(blades);
    const std::vector<SphereCollider> singles = rollingCluster();
    std::vector<SphereCollider> grouped = singles;
    grouped[0].groupSize = 3;
    grouped[0].boundOffset = glm::vec3(0.3f, 0.0f, 0.35f);  // the middle of the three centres
    grouped[0].boundRadiusM = 0.5f + glm::length(glm::vec3(0.3f, 0.0f, 0.35f)) + 1e-4f;
    // A group whose bound is (wrongly) far away proves the bound is what is tested.
    std::vector<SphereCollider> misplaced = grouped;
    misplaced[0].boundOffset = glm::vec3(0.0f, 100.0f, 0.0f);

    std::vector<Blade> a = blades, b = blades, c = blades;
    std::vector<float> etaA(blades.size(), 0.0f), etaB = etaA, etaC = etaA;
    for (int step = 0; step < 40; ++step) {
        const float t = static_cast<float>(step) / 60.0f;
        stepPhysics(a, etaA, tips, PhysicsParams{}, {}, singles, t, 1);
        stepPhysics(b, etaB, tips, PhysicsParams{}, {}, grouped, t, 1);
        stepPhysics(c, etaC, tips, PhysicsParams{}, {}, misplaced, t, 1);
    }
    EXPECT_EQ(a, b);
    EXPECT_EQ(etaA, etaB);
    EXPECT_GT(std::count_if(etaA.begin(), etaA.end(), [](float e) { return e > 0.0f; }), 50);
    EXPECT_EQ(std::count_if(etaC.begin(), etaC.end(), [](float e) { return e > 0.0f; }), 0);
}

TEST(Physics, SubstepCountFollowsThePolicy) {
    PhysicsParams p;
    p.dtS = 1.0f / 60.0f;
    EXPECT_EQ(substepCount(p), 2u);
    p.dtS = 1e-5f;
    EXPECT_EQ(substepCount(p), 1u);
    p.dtS = 10.0f;
    EXPECT_EQ(substepCount(p), 8u);
    p.dtS = 0.0f;
    EXPECT_EQ(substepCount(p), 0u);
}

}  // namespace
}  // namespace grass::core

namespace grass::core {
namespace {

TEST(CapEta, LowersOnlyWhatLiesAboveTheCap) {
    std::vector<float> eta{0.0f, 0.5f, 1.0f, 39.8f, ETA_MAX};
    EXPECT_EQ(capEta(eta, 1.0f), 2u);
    EXPECT_EQ(eta, (std::vector<float>{0.0f, 0.5f, 1.0f, 1.0f, 1.0f}));
    EXPECT_EQ(capEta(eta, 1.0f), 0u);
}

}  // namespace
}  // namespace grass::core
