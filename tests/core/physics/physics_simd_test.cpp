// The SIMD execution of the physics (core/physics/physics_simd.h, issue 29) against the scalar
// reference it implements (core::stepPhysics): a windy field with moving colliders and a packed
// group, centre gravity with a snow load, degenerate blades, a field at rest, and the extremes
// sweep of tests/support/physics_cases.h. Tolerance: the CPU/GPU agreement of docs/physics.md,
// 1e-3·h on every tip (the SIMD sine and exponential round differently from libm's).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include <hwy/targets.h>

#include "mesh/procedural.h"
#include "physics/physics_simd.h"
#include "scatter/scatter.h"
#include "support/physics_cases.h"

namespace grass::test {
namespace {

constexpr float TIP_TOLERANCE = 1e-3f;

std::vector<core::Blade> scatteredField(float density, std::size_t extra) {
    core::ProceduralMeshParams mesh;
    mesh.size = 4.0f;
    mesh.resolution = 8;
    core::ScatterParams scatter;
    scatter.density = density;
    std::vector<core::Blade> blades =
        core::scatterBlades(core::makeProceduralMesh(mesh), scatter, nullptr, 11).blades;
    // A count that is no multiple of any lane width: the last blades take the scalar step.
    blades.resize(blades.size() + extra, blades.front());
    return blades;
}

struct Forces {
    core::PhysicsParams params;
    std::vector<core::WindSource> wind;
    std::vector<core::SphereCollider> colliders;
};

// The agreement tests' moving wind and colliders (physics_cases.h), plus a vortex on a path.
Forces windyForces() {
    Forces f;
    f.wind = movingWind();
    core::WindSource vortex;
    vortex.kind = core::WindKind::Vortex;
    vortex.strength = 5.0f;
    vortex.radiusM = 2.0f;
    vortex.path = {{0.0f, {1.0f, 0.0f, 1.0f}}, {8.0f, {-1.0f, 0.0f, -1.0f}}};
    f.wind.push_back(vortex);
    f.colliders = movingColliders();
    return f;
}

struct Agreement {
    float maxTip = 0.0f;  // max |v2_simd − v2_scalar| / h
    float maxEtaError = 0.0f;
    float maxEta = 0.0f;
};

// Steps both executions side by side for `steps` steps (2 threads for the SIMD one).
Agreement runBoth(std::vector<core::Blade> blades, const Forces& forces, int steps,
                  core::GravityLoad load = {}) {
    std::vector<core::Blade> simd = blades;
    const std::vector<glm::vec3> tips = core::restTipsAsGrown(blades);
    std::vector<float> etaScalar(blades.size(), 0.0f), etaSimd(blades.size(), 0.0f);
    Agreement a;
    for (int step = 0; step < steps; ++step) {
        const float timeS = float(step) * forces.params.dtS;
        core::stepPhysics(blades, etaScalar, tips, forces.params, forces.wind, forces.colliders,
                          timeS, 1, load);
        core::stepPhysicsSimd(simd, etaSimd, tips, forces.params, forces.wind, forces.colliders,
                              timeS, 2, load);
        for (std::size_t i = 0; i < blades.size(); ++i) {
            const float h = blades[i].h();
            if (!(h > 0.0f))
                continue;
            a.maxTip = std::max(a.maxTip, glm::length(simd[i].v2() - blades[i].v2()) / h);
            a.maxEtaError = std::max(a.maxEtaError, std::abs(etaSimd[i] - etaScalar[i]));
            a.maxEta = std::max(a.maxEta, etaScalar[i]);
        }
    }
    return a;
}

TEST(PhysicsSimd, RunsOnTheWidestInstructionSetOfThisCpu) {
    const std::string target = core::physicsSimdTarget();
    std::printf("[ simd ] %s, %zu float lanes\n", target.c_str(), core::physicsSimdLanes());
    EXPECT_FALSE(target.empty());
    EXPECT_GE(core::physicsSimdLanes(), 4u);  // every x86-64 target has at least SSE's four
}

TEST(PhysicsSimd, MatchesTheScalarReferenceOnAWindyFieldWithColliders) {
    const Agreement a = runBoth(scatteredField(20.0f, 5), windyForces(), 600);
    std::printf("[ simd ] windy field, 600 steps: max |v2_simd - v2_scalar| / h = %.3g, max eta "
                "error %.3g (max eta %.3g)\n",
                double(a.maxTip), double(a.maxEtaError), double(a.maxEta));
    EXPECT_GT(a.maxEta, 0.0f);  // the colliders did hit blades
    EXPECT_LT(a.maxTip, TIP_TOLERANCE);
    EXPECT_LT(a.maxEtaError, 1e-3f * std::max(a.maxEta, 1e-3f));
}

// Every instruction set Highway compiled the step for and this CPU runs (SSSE3, SSE4, AVX2,
// AVX-512 where present, and the scalar fallback), forced one at a time: the other machines
// the dispatch may pick run the same agreement.
TEST(PhysicsSimd, EveryCompiledTargetMatchesTheReference) {
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        hwy::GetChosenTarget().Update(hwy::SupportedTargets());
        EXPECT_EQ(core::physicsSimdTarget(), hwy::TargetName(target));
        const Agreement a = runBoth(scatteredField(20.0f, 5), windyForces(), 120);
        std::printf("[ simd ] %s (%zu lanes): max tip error %.3g h\n", hwy::TargetName(target),
                    core::physicsSimdLanes(), double(a.maxTip));
        EXPECT_LT(a.maxTip, TIP_TOLERANCE) << hwy::TargetName(target);
        EXPECT_GT(a.maxEta, 0.0f) << hwy::TargetName(target);
    }
    hwy::SetSupportedTargetsForTest(0);
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
}

TEST(PhysicsSimd, MatchesWithCentreGravityAndASnowLoad) {
    Forces forces = windyForces();
    forces.params.gravityMode = core::GravityMode::Centre;
    forces.params.gravity = glm::vec4(0.0f, -30.0f, 0.0f, 9.81f);
    const std::vector<core::Blade> blades = scatteredField(20.0f, 3);
    std::vector<float> perBlade(blades.size());
    for (std::size_t i = 0; i < perBlade.size(); ++i)
        perBlade[i] = float(i % 7) * 0.5f;
    const Agreement a = runBoth(blades, forces, 300, core::GravityLoad{perBlade, 2.0f});
    std::printf("[ simd ] centre gravity + snow load: max tip error %.3g h\n", double(a.maxTip));
    EXPECT_LT(a.maxTip, TIP_TOLERANCE);
}

// Blades the reference must repair take its scalar step, exactly; repaired, they, the odd but
// valid ones and their neighbours in the same lanes step as the reference does.
TEST(PhysicsSimd, DegenerateBladesTakeTheReferenceStepExactly) {
    std::vector<core::Blade> blades = scatteredField(20.0f, 0);
    const std::vector<core::Blade> degenerate = degenerateBlades();
    for (std::size_t i = 0; i < degenerate.size(); ++i)
        blades[3 * i + 1] = degenerate[i];
    const Forces forces = windyForces();
    std::vector<core::Blade> scalar = blades, simd = blades;
    const std::vector<glm::vec3> tips = core::restTips(blades);
    std::vector<float> etaScalar(blades.size(), 0.0f), etaSimd(blades.size(), 0.0f);
    for (int step = 0; step < 20; ++step) {
        const float timeS = float(step) * forces.params.dtS;
        core::stepPhysics(scalar, etaScalar, tips, forces.params, forces.wind, forces.colliders,
                          timeS, 1);
        core::stepPhysicsSimd(simd, etaSimd, tips, forces.params, forces.wind, forces.colliders,
                              timeS, 1);
        for (std::size_t i = 0; i < degenerate.size() && step == 0; ++i) {
            const std::size_t at = 3 * i + 1;
            const core::Blade repaired = core::repairBlade(degenerate[i]);
            if (std::memcmp(&repaired, &degenerate[i], sizeof(core::Blade)) == 0)
                continue;  // valid, if odd (v2 on v0, a denormal height): the SIMD step takes it
            EXPECT_EQ(std::memcmp(&scalar[at], &simd[at], sizeof(core::Blade)), 0) << "blade " << i;
            EXPECT_EQ(etaScalar[at], etaSimd[at]) << "blade " << i;
        }
    }
    for (std::size_t i = 0; i < blades.size(); ++i) {
        if (scalar[i].h() > 0.0f && std::isfinite(scalar[i].h())) {
            EXPECT_LT(glm::length(simd[i].v2() - scalar[i].v2()) / scalar[i].h(), TIP_TOLERANCE)
                << "blade " << i;
        }
    }
}

// The SIMD collision loop skips a sphere on squared distances when no lane's tip or midpoint
// can be inside it, and a packed group when none can be inside its bound; with surfaces a hair
// from the points (physics_cases.h, single spheres and groups whose bound passes the same hair
// away), the blades inside must still be corrected and those outside left alone, on every
// compiled instruction set, as the reference does.
class SphereEdge : public ::testing::TestWithParam<bool> {};

TEST_P(SphereEdge, SpheresAHairFromTheTipOrMidpointDecideAsTheReference) {
    const SphereEdgeField field = sphereEdgeField(GetParam());
    const core::PhysicsParams params = sphereEdgeParams();
    const std::vector<glm::vec3> tips = core::restTips(field.blades);
    const auto expectInsideCorrected = [&](const std::vector<float>& eta, const char* what) {
        for (std::size_t i = 0; i < field.blades.size(); ++i)
            EXPECT_EQ(eta[i] > 0.0f, field.deltas[i] < 0.0f)
                << what << ": blade " << i << ", surface " << field.deltas[i] << " m away, eta "
                << eta[i];
    };
    std::vector<core::Blade> scalar = field.blades;
    std::vector<float> etaScalar(scalar.size(), 0.0f);
    core::stepPhysics(scalar, etaScalar, tips, params, {}, field.colliders, 0.0f, 1);
    expectInsideCorrected(etaScalar, "reference");
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        hwy::GetChosenTarget().Update(hwy::SupportedTargets());
        std::vector<core::Blade> simd = field.blades;
        std::vector<float> etaSimd(simd.size(), 0.0f);
        core::stepPhysicsSimd(simd, etaSimd, tips, params, {}, field.colliders, 0.0f, 2);
        expectInsideCorrected(etaSimd, hwy::TargetName(target));
    }
    hwy::SetSupportedTargetsForTest(0);
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
}

INSTANTIATE_TEST_SUITE_P(PhysicsSimd, SphereEdge, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param) {
                             return param.param ? "GroupedSpheres" : "SingleSpheres";
                         });

// Nothing acts on a field at rest: both executions leave it bit for bit as it was.
TEST(PhysicsSimd, AFieldAtRestStaysBitIdentical) {
    std::vector<core::Blade> blades = scatteredField(20.0f, 1);
    const std::vector<core::Blade> before = blades;
    Forces still;
    still.params.gravity.w = 0.0f;
    std::vector<float> eta(blades.size(), 0.0f);
    const std::vector<glm::vec3> tips = core::restTipsAsGrown(blades);
    for (int step = 0; step < 5; ++step)
        core::stepPhysicsSimd(blades, eta, tips, still.params, still.wind, still.colliders,
                              float(step) * still.params.dtS, 2);
    EXPECT_EQ(std::memcmp(blades.data(), before.data(), blades.size() * sizeof(core::Blade)), 0);
}

// The extremes sweep (810 cases) through the SIMD execution: each dispatch group replicated into
// whole blocks of lanes, the invariants after every step, and the scalar reference alongside.
TEST(PhysicsSimd, ExtremesKeepTheInvariantsAndTheReference) {
    const std::size_t lanes = core::physicsSimdLanes();
    float maxTipDeviation = 0.0f;
    std::string worst;
    for (const std::vector<ExtremeCase>& group : groupCases(extremeCases())) {
        const ExtremeCase& first = group.front();
        const core::PhysicsParams params = extremeParams(first);
        const std::vector<core::WindSource> wind = extremeWind(first);
        const std::vector<core::SphereCollider> colliders = extremeColliders(first);
        std::vector<ExtremeCase> cases;
        while (cases.size() < 2 * lanes)
            cases.insert(cases.end(), group.begin(), group.end());
        cases.resize(cases.size() / lanes * lanes);
        std::vector<core::Blade> scalar;
        for (const ExtremeCase& c : cases)
            scalar.push_back(extremeBlade(c));
        std::vector<core::Blade> simd = scalar;
        const std::vector<glm::vec3> tips = core::restTips(scalar);
        std::vector<float> etaScalar(scalar.size(), 0.0f), etaSimd(scalar.size(), 0.0f);
        for (int step = 0; step < EXTREME_STEP_COUNT; ++step) {
            const float timeS = extremeStepTimeS(first, step);
            const std::vector<core::Blade> before = simd;
            core::stepPhysics(scalar, etaScalar, tips, params, wind, colliders, timeS, 1);
            core::stepPhysicsSimd(simd, etaSimd, tips, params, wind, colliders, timeS, 1);
            for (std::size_t i = 0; i < cases.size(); ++i) {
                ASSERT_TRUE(keepsExtremeInvariants(simd[i], etaSimd[i], cases[i], before[i].v2()))
                    << describeCase(cases[i]) << " step " << step;
                const float deviation = glm::length(simd[i].v2() - scalar[i].v2()) / cases[i].h;
                if (deviation > maxTipDeviation) {
                    maxTipDeviation = deviation;
                    worst = describeCase(cases[i]) + " step " + std::to_string(step);
                }
            }
        }
    }
    std::printf("[ simd ] extremes: max |v2_simd - v2_scalar| / h = %.3g (%s)\n",
                double(maxTipDeviation), worst.c_str());
    EXPECT_LT(maxTipDeviation, TIP_TOLERANCE) << worst;
}

}  // namespace
}  // namespace grass::test
