// FieldSimulation (core/scene/field_simulation.h): the editor's CPU physics steps a copy of the
// scene's blades exactly as SceneSimulation steps the scene itself, leaves the scene at rest,
// and restarts re-grown patches from the scene's blades.
#include <gtest/gtest.h>

#include <cstring>

#include "project/project.h"
#include "scene/field_simulation.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

TEST(FieldSimulation, StepsACopyAsSceneSimulationStepsTheScene) {
    auto loaded = loadProject(test::sourceDir() / "tests/data/projects/windy");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = buildScene(*loaded);
    auto physics = buildScenePhysics(*loaded);
    ASSERT_TRUE(scene.ok() && physics.ok());
    Scene reference = *scene;
    const std::vector<Blade> rest = scene->layers[0].patched.blades;

    FieldSimulation field(*scene);
    SceneSimulation simulation(reference, *physics, 2);
    for (int step = 0; step < 40; ++step) {
        field.step(*physics, simulation.timeS(), 2);
        simulation.step();
    }
    const std::vector<Blade>& stepped = reference.layers[0].patched.blades;
    ASSERT_EQ(field.blades(0).size(), stepped.size());
    // The same execution on the same inputs: bit for bit.
    EXPECT_EQ(std::memcmp(field.blades(0).data(), stepped.data(), stepped.size() * sizeof(Blade)), 0);
    EXPECT_NE(std::memcmp(field.blades(0).data(), rest.data(), rest.size() * sizeof(Blade)), 0);
    // The scene it was made from stays at rest.
    EXPECT_EQ(std::memcmp(scene->layers[0].patched.blades.data(), rest.data(),
                          rest.size() * sizeof(Blade)),
              0);

    // Re-grown patch 0 (here: its rest blades) restarts at rest, η 0; the others go on.
    const std::size_t patch = scene->layers[0].patched.patchSize;
    field.resetPatches(0, *scene, std::vector<std::uint32_t>{0});
    EXPECT_EQ(std::memcmp(field.blades(0).data(), rest.data(), patch * sizeof(Blade)), 0);
    for (std::size_t i = 0; i < patch; ++i)
        EXPECT_EQ(field.eta(0)[i], 0.0f);
    EXPECT_EQ(std::memcmp(field.blades(0).data() + patch, stepped.data() + patch,
                          (stepped.size() - patch) * sizeof(Blade)),
              0);
    field.reset(*scene);
    EXPECT_EQ(std::memcmp(field.blades(0).data(), rest.data(), rest.size() * sizeof(Blade)), 0);
}

}  // namespace
}  // namespace grass::core
