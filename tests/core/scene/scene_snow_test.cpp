// The snow load on the physics (SPEC §11, issue 9): blades in the open carry
// loadGravity·As·Zn·Fe, sheltered ones nothing; the load bends a simulated field down, more as
// snow accumulates; and a zero load changes nothing.
#include "scene/scene_snow.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_physics.h"
#include "support/density_dab.h"
#include "support/plane_project.h"

namespace grass::core {
namespace {

constexpr glm::vec3 BALL_CENTRE{0.0f, 1.3f, 0.0f};

// A 4 m plane of grass with a ball floating over its centre; snow falls straight down.
LoadedProject snowyPlane() {
    LoadedProject loaded = test::planeFieldProject({4.0f, 8, 40.0f, 0.3f, 0.5f});
    ColliderDesc ball;
    ball.name = "ball";
    ball.position = BALL_CENTRE;
    ball.radiusM = 0.7f;
    loaded.project.colliders = {ball};
    SnowParams& snow = loaded.project.snow;
    snow.enabled = 1u;
    snow.amountM = 0.1f;
    snow.fallDirection = {0.0f, -1.0f, 0.0f};
    snow.mapResolution = 512;
    snow.loadGravity = 60.0f;
    return loaded;
}

float fromAxis(glm::vec3 p) {
    return std::hypot(p.x, p.z);
}

TEST(SceneSnow, NoSnowOrNoLoadGravityGivesNoLoad) {
    LoadedProject loaded = snowyPlane();
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    const SnowParams on = loaded.project.snow;
    const SnowDepthMap map = sceneSnowDepthMap(*scene, on, 0.0f);
    const auto& blades = scene->layers.front().patched.blades;
    SnowParams off = on;
    off.enabled = 0u;
    EXPECT_TRUE(snowLoadPerMetre(blades, map, off).empty());
    SnowParams weightless = on;
    weightless.loadGravity = 0.0f;
    EXPECT_TRUE(snowLoadPerMetre(blades, map, weightless).empty());
    SnowParams none = on;
    none.amountM = 0.0f;
    EXPECT_TRUE(snowLoadPerMetre(blades, map, none).empty()) << "no snow and none to come";
    none.accumulationRate = 0.01f;
    EXPECT_EQ(snowLoadPerMetre(blades, map, none).size(), blades.size()) << "snow to come";
}

TEST(SceneSnow, OpenBladesCarryTheLoadShelteredBladesNone) {
    const LoadedProject loaded = snowyPlane();
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    const SnowParams& snow = loaded.project.snow;
    const SnowDepthMap map = sceneSnowDepthMap(*scene, snow, 0.0f);
    const auto& blades = scene->layers.front().patched.blades;
    const std::vector<float> load = snowLoadPerMetre(blades, map, snow);
    ASSERT_EQ(load.size(), blades.size());
    std::size_t open = 0, sheltered = 0;
    for (std::size_t i = 0; i < blades.size(); ++i) {
        if (!(blades[i].h() > 0.0f)) {
            EXPECT_EQ(load[i], 0.0f);
            continue;
        }
        const float r = fromAxis(blades[i].v0());
        if (r < 0.4f) {
            ++sheltered;
            EXPECT_EQ(load[i], 0.0f) << "blade " << i << " under the ball";
        } else if (r > 1.2f && r < 1.7f) {
            // Fully exposed, flat ground: loadGravity · 1 m · Zn, Zn = ½ + ½·noise.
            ++open;
            const float zn = 0.5f + 0.5f * snowNoiseAt(snow, blades[i].v0());
            EXPECT_NEAR(load[i], snow.loadGravity * zn, 1e-4f * snow.loadGravity);
        }
    }
    EXPECT_GT(sheltered, 5u);
    EXPECT_GT(open, 50u);
}

// Mean tip height over the blades whose roots lie in [r0, r1) from the ball's axis.
double meanTipHeight(const Scene& scene, float r0, float r1) {
    double sum = 0.0;
    std::size_t count = 0;
    for (const Blade& blade : scene.layers.front().patched.blades)
        if (blade.h() > 0.0f && fromAxis(blade.v0()) >= r0 && fromAxis(blade.v0()) < r1) {
            sum += blade.v2().y;
            ++count;
        }
    return count > 0 ? sum / double(count) : 0.0;
}

// Steps `loaded` for `seconds` with its physics (no wind) and returns the scene.
Scene simulate(const LoadedProject& loaded, float seconds) {
    auto scene = buildScene(loaded);
    EXPECT_TRUE(scene) << scene.error().str();
    auto physics = buildScenePhysics(loaded);
    EXPECT_TRUE(physics) << physics.error().str();
    physics->colliders.clear();  // the ball floats above the grass; it only shelters
    SceneSimulation simulation(*scene, std::move(*physics), 1);
    while (simulation.timeS() < seconds)
        simulation.step();
    return std::move(*scene);
}

TEST(SceneSnow, TheLoadBendsOpenBladesAndMoreAsSnowAccumulates) {
    LoadedProject loaded = snowyPlane();
    LoadedProject bare = loaded;
    bare.project.snow.enabled = 0u;
    const Scene still = simulate(bare, 1.0f);
    const Scene loadedScene = simulate(loaded, 1.0f);
    // In the open the snow pushes tips down; under the ball nothing changes at all.
    EXPECT_LT(meanTipHeight(loadedScene, 1.2f, 1.9f), meanTipHeight(still, 1.2f, 1.9f) - 0.01);
    EXPECT_DOUBLE_EQ(meanTipHeight(loadedScene, 0.0f, 0.4f), meanTipHeight(still, 0.0f, 0.4f));

    LoadedProject growing = loaded;
    growing.project.snow.accumulationRate = 0.1f;  // 0.1 m → 0.2 m over the second
    const Scene deeper = simulate(growing, 1.0f);
    EXPECT_LT(meanTipHeight(deeper, 1.2f, 1.9f), meanTipHeight(loadedScene, 1.2f, 1.9f) - 0.005);
}

TEST(SceneSnow, AZeroLoadLeavesTheStepBitIdentical) {
    const LoadedProject loaded = snowyPlane();
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    const Blade start = scene->layers.front().patched.blades.front();
    PhysicsParams params;
    Blade plain = start, zero = start, nan = start, heavy = start;
    float e0 = 0.0f, e1 = 0.0f, e2 = 0.0f, e3 = 0.0f;
    const glm::vec3 rest = restTip(start);
    stepBlade(plain, e0, rest, params, {}, {}, 0.0f);
    stepBlade(zero, e1, rest, params, {}, {}, 0.0f, 0.0f);
    stepBlade(nan, e2, rest, params, {}, {}, 0.0f, std::nanf(""));
    stepBlade(heavy, e3, rest, params, {}, {}, 0.0f, 50.0f);
    EXPECT_EQ(plain, zero);
    EXPECT_EQ(plain, nan) << "a non-finite load counts as none";
    EXPECT_LT(heavy.v2().y, plain.v2().y);
}

}  // namespace
}  // namespace grass::core

namespace grass::core {
namespace {

// The editor's brush in winter: blades painted back into a bare patch carry the snow their
// neighbours carry, as a field grown so carries it in grass render. Before, the live physics
// kept each slot's load from when the field was weighed, so the new blades stood under none.
TEST(SceneSnow, BladesABrushRegrowsCarryTheSnowAFieldGrownSoCarries) {
    LoadedProject loaded = snowyPlane();
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    const float openX = -1.4f;  // in the open, away from the ball's shelter
    test::paintDensityDab(*scene, BrushMode::Subtract, openX);
    auto physics = buildScenePhysics(loaded);
    ASSERT_TRUE(physics) << physics.error().str();
    prepareSnowLoads(*physics, *scene);  // the field with its bare patch, weighed
    const std::vector<float> weighedBare = physics->snowLoadPerMetre.front();

    const RegrowReport back = test::paintDensityDab(*scene, BrushMode::Add, openX);
    ASSERT_FALSE(back.patches.empty());
    reweighSnowLoads(*physics, *scene, 0, back.patches);

    ScenePhysics grownSo = *buildScenePhysics(loaded);
    prepareSnowLoads(grownSo, *scene);
    const std::vector<float>& expected = grownSo.snowLoadPerMetre.front();
    const std::vector<float>& load = physics->snowLoadPerMetre.front();
    ASSERT_EQ(load.size(), expected.size());
    std::size_t regained = 0;
    for (std::size_t i = 0; i < load.size(); ++i) {
        EXPECT_EQ(load[i], expected[i]) << "slot " << i;
        regained += weighedBare[i] == 0.0f && load[i] > 0.0f ? 1 : 0;
    }
    EXPECT_GT(regained, 20u) << "blades grown back into the bare patch, now under snow";
}

// A layer without a load, or a physics never weighed, stays as it is.
TEST(SceneSnow, ReweighingWithoutALoadChangesNothing) {
    LoadedProject loaded = snowyPlane();
    loaded.project.snow.enabled = 0u;
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    auto physics = buildScenePhysics(loaded);
    ASSERT_TRUE(physics) << physics.error().str();
    prepareSnowLoads(*physics, *scene);
    const RegrowReport back = test::paintDensityDab(*scene, BrushMode::Subtract, -1.4f);
    reweighSnowLoads(*physics, *scene, 0, back.patches);
    reweighSnowLoads(*physics, *scene, 7, back.patches);  // no such layer
    EXPECT_FALSE(physics->anySnowLoad());
    EXPECT_EQ(physics->snowWeigher, nullptr);
}

}  // namespace
}  // namespace grass::core
