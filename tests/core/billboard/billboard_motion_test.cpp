// How star billboards move (core/billboard/billboard_motion.h, issue 30 item 3): the scene's
// wind bends a tuft as it bends a blade of the same stiffness (checked against the physics
// itself), never beyond its height and keeping its length; the upper normals turn as GPU Gems'
// listing 7-1 turns them; and the three animation modes differ where the book says they do:
// per object every upper vertex of an object moves alike, per vertex each by its own position.
#include "billboard/billboard_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/physics.h"

namespace grass::core {
namespace {

constexpr glm::vec3 UP{0.0f, 1.0f, 0.0f};

WindSource steadyWind(glm::vec3 direction, float strength) {
    WindSource wind;
    wind.kind = WindKind::Directional;
    wind.direction = direction;
    wind.strength = strength;
    wind.wavelengthM = 0.0f;  // constant: no travelling wave
    return wind;
}

glm::vec3 horizontal(glm::vec3 v) {
    return {v.x, 0.0f, v.z};
}

TEST(BillboardWindBend, LightWindBendsTheTuftAsItBendsABladeOfTheSameStiffness) {
    // The reference: one blade of the physics, upright, no gravity, in a steady wind, stepped
    // until it settles. Its tip's horizontal displacement is where recovery balances the wind.
    const float h = 0.4f, s = 60.0f;
    for (const float strength : {0.3f, 1.0f, 2.0f}) {
        const std::vector<WindSource> wind = {steadyWind({1, 0, 0}, strength)};
        PhysicsParams params;
        params.gravity = glm::vec4(0.0f, -1.0f, 0.0f, 0.0f);
        params.frontGravityScale = 0.0f;
        Blade blade = makeRestBlade(glm::vec3(0.0f), UP, h, 0.01f, s, 0.0f);
        const glm::vec3 restTip = blade.v2();
        float eta = 0.0f;
        for (int step = 0; step < 600; ++step)
            stepBlade(blade, eta, restTip, params, wind, {}, static_cast<float>(step) * params.dtS);
        const float bladeBend = glm::length(horizontal(blade.v2() - restTip));
        const glm::vec3 bend = billboardWindBend(wind[0].direction * strength, UP, h, s);
        // The blade's own length correction and fd/fr shrink its bend a little as it leans; the
        // tuft's saturation x/(1+x) does the same by design: within 15 % of each other, and the
        // tuft moves downwind.
        EXPECT_NEAR(glm::length(horizontal(bend)), bladeBend, 0.15f * bladeBend)
            << "wind " << strength << " m/s";
        EXPECT_GT(bend.x, 0.0f);
        EXPECT_NEAR(bend.z, 0.0f, 1e-7f);
    }
}

TEST(BillboardWindBend, SmallWindMovesTheTopByWindOverStiffness) {
    // Δ = w/s, the equilibrium of dv2/dt = s·(Iv2 − v2) + w; saturation is second order.
    const glm::vec3 bend = billboardWindBend({0.06f, 0.0f, 0.0f}, UP, 0.5f, 60.0f);
    EXPECT_NEAR(bend.x, 0.001f, 0.001f * 0.003f);
}

TEST(BillboardWindBend, StormNeverBendsBeyondTheHeightAndKeepsTheLength) {
    const float h = 0.3f;
    float previous = 0.0f;
    for (const float strength : {1.0f, 10.0f, 100.0f, 1.0e4f, 1.0e8f}) {
        const glm::vec3 bend = billboardWindBend({0.0f, 0.0f, -strength}, UP, h, 40.0f);
        const float reach = glm::length(horizontal(bend));
        EXPECT_LT(reach, h);
        EXPECT_GT(reach, previous) << "a stronger wind bends further";
        previous = reach;
        // Root to moved top stays h long: the top sinks as it leans.
        EXPECT_NEAR(glm::length(UP * h + bend), h, 1e-5f);
        EXPECT_LE(bend.y, 0.0f);
    }
}

TEST(BillboardWindBend, NothingBendsWithoutWindHeightOrStiffnessOrWithWindAlongUp) {
    EXPECT_EQ(billboardWindBend(glm::vec3(0.0f), UP, 0.4f, 60.0f), glm::vec3(0.0f));
    EXPECT_EQ(billboardWindBend({0.0f, 5.0f, 0.0f}, UP, 0.4f, 60.0f), glm::vec3(0.0f));
    EXPECT_EQ(billboardWindBend({1.0f, 0.0f, 0.0f}, UP, 0.0f, 60.0f), glm::vec3(0.0f));
    EXPECT_EQ(billboardWindBend({1.0f, 0.0f, 0.0f}, UP, 0.4f, 0.0f), glm::vec3(0.0f));
    const float nan = std::nanf("");
    EXPECT_EQ(billboardWindBend({nan, 0.0f, 0.0f}, UP, 0.4f, 60.0f), glm::vec3(0.0f));
}

TEST(BillboardWindBend, FollowsTheObjectsUpOnASlope) {
    // On a 45° slope the wind across the tuft's own up bends it, not the world's horizontal.
    const glm::vec3 up = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    const glm::vec3 bend = billboardWindBend({2.0f, 0.0f, 0.0f}, up, 0.4f, 60.0f);
    const float h = 0.4f;
    EXPECT_NEAR(glm::length(up * h + bend), h, 1e-5f);
    EXPECT_LT(glm::dot(bend, up), 0.0f);  // sinks along its own up
}

StarVertex upperVertex(glm::vec3 position, glm::vec3 centre, float height) {
    StarVertex v;
    v.position = position;
    v.objectCentre = centre;
    v.normal = UP;
    v.sway = 1.0f;
    v.objectHeight = height;
    return v;
}

TEST(AnimateStarVertex, UpperNormalsTurnAsListing71RootsStay) {
    const glm::vec3 translation(0.1f, -0.02f, 0.05f);
    StarVertex top = upperVertex({1, 0.4f, 2}, {1, 0, 2}, 0.4f);
    const StarVertexMotion moved = animateStarVertex(top, translation);
    EXPECT_EQ(moved.position, top.position + translation);
    const glm::vec3 expected = glm::normalize(UP * 0.4f + translation);
    EXPECT_NEAR(glm::length(moved.normal - expected), 0.0f, 1e-6f);
    StarVertex root = top;
    root.sway = 0.0f;
    root.position.y = 0.0f;
    const StarVertexMotion still = animateStarVertex(root, translation);
    EXPECT_EQ(still.position, root.position);
    EXPECT_EQ(still.normal, UP);
}

// The six upper vertices of one star: two per quad, 60° apart, width 0.5 m.
std::vector<StarVertex> upperVerticesOfOneObject(glm::vec3 centre, float height) {
    GrassObject object;
    object.centre = centre;
    object.height = height;
    object.width = 0.5f;
    const StarMesh star = buildStarVertices({object});
    std::vector<StarVertex> uppers;
    for (const StarVertex& v : star.vertices)
        if (v.sway > 0.0f)
            uppers.push_back(v);
    return uppers;
}

TEST(BillboardVertexMotion, PerObjectMovesAnObjectsTopsAlikePerVertexDoesNot) {
    const std::vector<StarVertex> uppers = upperVerticesOfOneObject({3.0f, 0.0f, -2.0f}, 0.4f);
    ASSERT_EQ(uppers.size(), 6u);
    BillboardWind sway;
    sway.directionXZ = {1.0f, 0.4f};
    sway.amplitudeM = 0.06f;
    WindSource helicopter;
    helicopter.kind = WindKind::Point;
    helicopter.position = {2.0f, 1.0f, -2.5f};
    helicopter.strength = 3.0f;
    helicopter.radiusM = 8.0f;
    const std::vector<WindSource> sources = {helicopter};
    const BillboardSceneWind scene{sources, 60.0f};
    const float t = 1.7f;
    const glm::vec3 clusterCentre(0.0f);
    for (const BillboardWindMode mode :
         {BillboardWindMode::PerObject, BillboardWindMode::PerVertex,
          BillboardWindMode::PerCluster}) {
        float largestSpread = 0.0f;
        const glm::vec3 first =
            billboardVertexMotion(uppers[0], mode, clusterCentre, t, sway, scene).position -
            uppers[0].position;
        for (const StarVertex& v : uppers) {
            const glm::vec3 moved =
                billboardVertexMotion(v, mode, clusterCentre, t, sway, scene).position -
                v.position;
            EXPECT_GT(glm::length(moved), 0.005f);
            largestSpread = std::max(largestSpread, glm::length(moved - first));
        }
        if (mode == BillboardWindMode::PerVertex)
            EXPECT_GT(largestSpread, 0.003f) << "per vertex: each top by its own position";
        else
            EXPECT_LT(largestSpread, 1e-6f) << "mode " << static_cast<int>(mode);
    }
}

TEST(BillboardVertexMotion, AHelicopterBlowsTheTopsAwayFromItself) {
    WindSource helicopter;
    helicopter.kind = WindKind::Point;
    helicopter.position = {0.0f, 2.0f, 0.0f};
    helicopter.strength = 4.0f;
    helicopter.radiusM = 10.0f;
    const std::vector<WindSource> sources = {helicopter};
    BillboardWind noSway;
    noSway.amplitudeM = 0.0f;
    for (const glm::vec3 centre : {glm::vec3(3, 0, 0), glm::vec3(-2, 0, 4), glm::vec3(0, 0, -5)}) {
        for (const StarVertex& v : upperVerticesOfOneObject(centre, 0.4f)) {
            const glm::vec3 moved = billboardVertexMotion(v, BillboardWindMode::PerObject,
                                                          glm::vec3(0.0f), 0.0f, noSway,
                                                          {sources, 60.0f})
                                        .position -
                                    v.position;
            EXPECT_GT(glm::dot(horizontal(moved), glm::normalize(horizontal(centre))),
                      0.9f * glm::length(horizontal(moved)));
        }
    }
}

TEST(BillboardVertexMotion, WithoutSceneWindItIsTheBooksSwayAlone) {
    const std::vector<StarVertex> uppers = upperVerticesOfOneObject({1.0f, 0.0f, 1.0f}, 0.35f);
    BillboardWind sway;
    sway.amplitudeM = 0.08f;
    for (const StarVertex& v : uppers) {
        const StarVertexMotion m =
            billboardVertexMotion(v, BillboardWindMode::PerVertex, glm::vec3(0.0f), 0.9f, sway, {});
        EXPECT_EQ(m.position, v.position + billboardWindOffset(v.position, 0.9f, sway));
    }
}

}  // namespace
}  // namespace grass::core
