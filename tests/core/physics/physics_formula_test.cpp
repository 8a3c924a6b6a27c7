// The physics formulas of SPEC §3–5 pinned one at a time (issue 30, item 9): each test isolates a
// term of the reference step (core::stepBlade) and compares it with the formula computed here by
// hand, so a wrong constant or a swapped term fails. The other physics tests check behaviour
// (the field droops, recovers, keeps its length), which a wrong factor can still satisfy.
//
// Isolating a force: stiffness 0 makes the recovery term vanish (k = 0, the substep adds F·τ),
// one substep and a large move cap leave F·τ unclamped; the step then validates. So the step's
// result is validateBlade(v2 + F·τ), with the expected F written out below.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blade/blade.h"
#include "physics/physics.h"
#include "physics/wind.h"

namespace grass::core {
namespace {

constexpr float TAU = 1.0f / 60.0f;

PhysicsParams oneSubstepNoGravity() {
    PhysicsParams p;
    p.gravity.w = 0.0f;
    p.dtS = TAU;
    p.maxSubstepS = 1.0f;          // one substep of τ = Δt
    p.maxMovePerSubstep = 100.0f;  // F·τ stays unclamped
    return p;
}

// A blade leaning in x (v2 off the vertical), stiffness 0, validated, at the origin.
Blade leaningBlade(float h, float theta) {
    Blade b = makeRestBlade(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), h, 0.01f, 0.0f, theta);
    b.v2W = glm::vec4(0.4f * h, 0.8f * h, 0.1f * h, b.w());
    validateBlade(b);
    return b;
}

// The reference's step from timeS 0 with no colliders.
Blade stepped(Blade b, const PhysicsParams& params, const std::vector<WindSource>& wind) {
    float eta = 0.0f;
    stepBlade(b, eta, b.v0() + b.h() * b.up(), params, wind, {}, 0.0f);
    return b;
}

// validateBlade(v2 + F·τ): what the step must give when F is the force.
Blade validatedAfterForce(Blade b, glm::vec3 force) {
    b.v2W = glm::vec4(b.v2() + force * TAU, b.w());
    validateBlade(b);
    return b;
}

void expectSamePoints(const Blade& actual, const Blade& expected) {
    const float tolerance = 1e-6f * expected.h();
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(actual.v2()[axis], expected.v2()[axis], tolerance) << "v2 axis " << axis;
        EXPECT_NEAR(actual.v1()[axis], expected.v1()[axis], tolerance) << "v1 axis " << axis;
    }
}

// Validation step 2 (SPEC §3): v1 = v0 + up·h·max(1 − lproj/h, 0.05·max(lproj/h, 1)), lproj the
// length of v2 − v0 across up. After the passes the blade is at its fixed point, so v1 follows
// from the final v2 by the formula. Two leans: the first term (lproj/h = 0.3ish) and the 0.05
// floor (a blade lying nearly flat).
TEST(PhysicsFormula, V1IsPlacedAboveTheRootFromTheProjectedLength) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const float h = 0.8f;
    for (const glm::vec3 tipDirection : {glm::vec3(0.3f, 0.95f, 0.0f), glm::vec3(1.0f, 0.02f, 0.0f)}) {
        Blade b = makeRestBlade(glm::vec3(1.0f, 2.0f, 3.0f), up, h, 0.01f, 20.0f, 0.0f);
        b.v2W = glm::vec4(b.v0() + h * glm::normalize(tipDirection), b.w());
        validateBlade(b);
        const glm::vec3 d2 = b.v2() - b.v0();
        const float lproj = glm::length(d2 - up * glm::dot(d2, up));
        const float ratio = lproj / h;
        const float expected = h * std::max(1.0f - ratio, 0.05f * std::max(ratio, 1.0f));
        // v1 straight above v0, at the height the formula gives (the passes converge to 1e-5 h).
        EXPECT_NEAR(b.v1().x, b.v0().x, 1e-6f);
        EXPECT_NEAR(b.v1().z, b.v0().z, 1e-6f);
        EXPECT_NEAR(b.v1().y - b.v0().y, expected, 1e-4f * h) << "lproj/h " << ratio;
        // The floor case must be the floor: 1 − ratio would be smaller than 0.05 there.
        if (tipDirection.y < 0.1f) {
            EXPECT_LT(1.0f - ratio, 0.05f);
        }
    }
}

// Validation step 3, degree 2: (2·|v2 − v0| + |v1 − v0| + |v2 − v1|)/3 = h. Other weights (the
// chord alone, the control polygon alone, equal weights) are off by a percent or more on a bent
// blade, so the test tells them apart.
TEST(PhysicsFormula, LengthCorrectionUsesTheDegreeTwoEstimate) {
    const float h = 1.3f;
    Blade b = leaningBlade(h, 0.0f);
    b.v2W = glm::vec4(1.0f * h, 0.3f * h, 0.0f, b.w());  // strongly bent
    validateBlade(b);
    const float l0 = glm::length(b.v2() - b.v0());
    const float l1 = glm::length(b.v1() - b.v0()) + glm::length(b.v2() - b.v1());
    EXPECT_NEAR((2.0f * l0 + l1) / 3.0f, h, 1e-5f * h);
    EXPECT_GT(std::abs((l0 + l1) / 2.0f - h), 5e-3f * h);
    EXPECT_GT(std::abs(l0 - h), 1e-2f * h);
}

// The wind force (SPEC §4): F = w·fd·fr, fd = 1 − |n(w)·n(v2 − v0)| (a blade facing the wind
// along its own direction takes none), fr = (v2 − v0)·up / h (a standing blade takes all, a
// flattened one none). h ≠ 1 so a missing /h shows.
TEST(PhysicsFormula, WindForceIsScaledByDirectionalAndHeightFactors) {
    const float h = 0.5f;
    const Blade b = leaningBlade(h, 0.0f);
    const glm::vec3 d2 = b.v2() - b.v0();
    // With the blade's lean and against it: the absolute value of the cosine matters.
    for (const glm::vec3 direction : {glm::vec3(1.0f, 0.0f, 1.0f), glm::vec3(-1.0f, 0.0f, -0.2f)}) {
        WindSource wind;
        wind.direction = direction;
        wind.strength = 6.0f;
        wind.wavelengthM = 0.0f;  // constant: w = strength · normalize(direction)
        wind.gust = 0.0f;
        const glm::vec3 w = wind.strength * glm::normalize(wind.direction);
        ASSERT_NEAR(glm::length(windAt(wind, b.v0(), 0.0f) - w), 0.0f, 1e-6f);

        const float fd = 1.0f - std::abs(glm::dot(glm::normalize(w), glm::normalize(d2)));
        const float fr = glm::dot(d2, b.up()) / h;
        ASSERT_GT(fd, 0.1f);
        ASSERT_LT(fd, 0.9f);  // both factors strictly inside (0, 1): each one matters
        ASSERT_GT(fr, 0.1f);
        ASSERT_LT(fr, 0.99f);
        expectSamePoints(stepped(b, oneSubstepNoGravity(), {wind}),
                         validatedAfterForce(b, w * (fd * fr)));
    }
}

// Front gravity (SPEC §4): gF = 0.25·|gE|·f with f = normalize(up × widthDirection(up, θ)), the
// blade's front; added to gE, not scaled by h. θ ≠ 0 so the front is not an axis.
TEST(PhysicsFormula, FrontGravityPullsTowardsTheBladesFront) {
    const float h = 0.6f;
    const float theta = 0.7f;
    const Blade b = leaningBlade(h, theta);
    PhysicsParams params = oneSubstepNoGravity();
    params.gravity = glm::vec4(0.0f, -2.0f, 0.0f, 9.81f);  // direction is normalised
    const glm::vec3 gE(0.0f, -9.81f, 0.0f);
    const glm::vec3 front = glm::normalize(glm::cross(b.up(), widthDirection(b.up(), theta)));
    // The front is horizontal here and turns with θ.
    ASSERT_NEAR(front.y, 0.0f, 1e-6f);
    ASSERT_GT(std::abs(front.x), 0.3f);
    ASSERT_GT(std::abs(front.z), 0.3f);
    const Blade actual = stepped(b, params, {});
    expectSamePoints(actual, validatedAfterForce(b, gE + 0.25f * 9.81f * front));
    // The opposite front (a swapped cross product) would pull the tip the other way.
    const Blade swapped = validatedAfterForce(b, gE - 0.25f * 9.81f * front);
    EXPECT_GT(glm::length(actual.v2() - swapped.v2()), 1e-3f * h);
}

// Centre gravity (GravityMode::Centre): gE points from the root to the centre point.
TEST(PhysicsFormula, CentreGravityPointsFromTheRootToTheCentre) {
    const float h = 0.6f;
    const Blade b = leaningBlade(h, 0.0f);
    PhysicsParams params = oneSubstepNoGravity();
    params.gravityMode = GravityMode::Centre;
    const glm::vec3 centre(3.0f, -4.0f, 0.0f);
    params.gravity = glm::vec4(centre, 5.0f);
    params.frontGravityScale = 0.0f;  // gE alone
    const glm::vec3 gE = 5.0f * glm::normalize(centre - b.v0());
    expectSamePoints(stepped(b, params, {}), validatedAfterForce(b, gE));
}

// Collision at the midpoint (SPEC §5): m = ¼v0 + ½v1 + ¼v2 moves a quarter as much as v2, so a
// sphere that holds m but not the tip moves the tip by 4·d, d = (|c − m| − ρ)·n(c − m); η grows by
// |d|². The tip's direction from the root after the step tells the factor: 4 gives
// n(v2 + 4d − v0), 2 or 1 another direction.
TEST(PhysicsFormula, MidpointCollisionMovesTheTipByFourTimesTheCorrection) {
    const float h = 1.0f;
    Blade b = makeRestBlade(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), h, 0.01f, 0.0f, 0.0f);
    validateBlade(b);  // standing straight: v1 = v2 = (0, 1, 0), m = (0, 0.75, 0)
    const glm::vec3 m = 0.25f * b.v0() + 0.5f * b.v1() + 0.25f * b.v2();
    ASSERT_NEAR(m.y, 0.75f, 1e-6f);
    SphereCollider sphere;
    sphere.centre = glm::vec3(0.3f, 0.75f, 0.0f);
    sphere.radiusM = 0.35f;
    ASSERT_GT(glm::length(b.v2() - sphere.centre), sphere.radiusM) << "the tip is outside";
    const glm::vec3 d = (glm::length(sphere.centre - m) - sphere.radiusM) *
                        glm::normalize(sphere.centre - m);  // (−0.05, 0, 0)

    float eta = 0.0f;
    Blade actual = b;
    stepBlade(actual, eta, b.v2(), oneSubstepNoGravity(), {}, {sphere}, 0.0f);
    EXPECT_NEAR(eta, glm::dot(d, d), 1e-6f);
    const glm::vec3 expectedDirection = glm::normalize(b.v2() + 4.0f * d - b.v0());
    const glm::vec3 direction = glm::normalize(actual.v2() - actual.v0());
    EXPECT_NEAR(glm::length(direction - expectedDirection), 0.0f, 1e-5f);
    const glm::vec3 twice = glm::normalize(b.v2() + 2.0f * d - b.v0());
    EXPECT_GT(glm::length(direction - twice), 0.05f);
}

}  // namespace
}  // namespace grass::core
