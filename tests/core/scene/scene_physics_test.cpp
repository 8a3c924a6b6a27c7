// A project's physics end to end on the CPU reference: a ball rolled through a field leaves a
// trail of crushed blades behind it while the rest of the field stands (issue 4).
#include "scene/scene_physics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "physics/physics.h"
#include "physics/physics_simd.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

LoadedProject rollingBallProject() {
    LoadedProject loaded = test::planeFieldProject({5.0f, 4, 150.0f, 0.3f, 0.5f});
    Project& project = loaded.project;
    project.physics.etaDecayPerS = 0.1f;
    project.physics.crushedRecoveryFloor = 0.02f;
    ColliderDesc ball;
    ball.name = "ball";
    ball.radiusM = 1.0f;
    // Across the field along x at z = 0, sunk 0.3 m into the ground, in 2 s.
    ball.path = {{0.0f, {-3.0f, 0.7f, 0.0f}}, {2.0f, {3.0f, 0.7f, 0.0f}}};
    project.colliders = {ball};
    return loaded;
}

struct BandStats {
    double tipHeight = 0.0;
    std::size_t count = 0;
    std::size_t withEta = 0;
};

TEST(ScenePhysics, RollingBallLeavesATrail) {
    const LoadedProject loaded = rollingBallProject();
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    auto physics = buildScenePhysics(loaded);
    ASSERT_TRUE(physics) << physics.error().str();
    ASSERT_EQ(physics->colliders.size(), 1u);
    SceneSimulation simulation(*scene, *physics, 2);
    for (int step = 0; step < 150; ++step)  // 2.5 s: the ball has crossed and stopped outside
        simulation.step();
    EXPECT_NEAR(simulation.timeS(), 2.5f, 1e-5f);

    BandStats trail, untouched;
    const LayerField& layer = scene->layers[0];
    for (std::size_t i = 0; i < layer.patched.blades.size(); ++i) {
        const Blade& blade = layer.patched.blades[i];
        if (blade.h() <= 0.0f || std::abs(blade.v0().x) > 1.5f)
            continue;
        const float z = std::abs(blade.v0().z);
        // Inside the ball's footprint (ground circle radius √(1² − 0.7²) = 0.71 m) or far away.
        BandStats* band = z < 0.4f ? &trail : z > 1.5f ? &untouched : nullptr;
        if (!band)
            continue;
        band->tipHeight += (blade.v2().y - blade.v0().y) / blade.h();
        band->count += 1;
        band->withEta += simulation.eta(0)[i] > 0.0f ? 1 : 0;
    }
    ASSERT_GT(trail.count, 50u);
    ASSERT_GT(untouched.count, 50u);
    const double trailHeight = trail.tipHeight / static_cast<double>(trail.count);
    const double untouchedHeight = untouched.tipHeight / static_cast<double>(untouched.count);
    // Standing grass keeps most of its height (gravity droops it a little); the trail lies low.
    EXPECT_GT(untouchedHeight, 0.7);
    EXPECT_LT(trailHeight, 0.6 * untouchedHeight);
    EXPECT_GT(trail.withEta, trail.count * 9 / 10);
    EXPECT_EQ(untouched.withEta, 0u);
    const FieldHealth health = simulation.health();
    EXPECT_EQ(health.nonfinite, 0u);
    EXPECT_EQ(health.belowGround, 0u);
    EXPECT_LT(health.maxRelLengthError, 1e-4);
    EXPECT_GT(health.crushedShare(), 0.05);
}

TEST(ScenePhysics, StillProjectStaysStill) {
    LoadedProject loaded = rollingBallProject();
    loaded.project.colliders.clear();
    loaded.project.physics.gravity.w = 0.0f;
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    const std::vector<Blade> before = scene->layers[0].patched.blades;
    auto physics = buildScenePhysics(loaded);
    ASSERT_TRUE(physics) << physics.error().str();
    SceneSimulation simulation(*scene, *physics, 1);
    for (int step = 0; step < 10; ++step)
        simulation.step();
    EXPECT_EQ(scene->layers[0].patched.blades, before);
    EXPECT_EQ(simulation.health().maxTipDisplacementM, 0.0);
}

}  // namespace
}  // namespace grass::core

namespace grass::core {
namespace {

// A mesh collider becomes its packed spheres placed in the world: centre = position + scale·c,
// radius scale·r, and a path moves every sphere by the same offset.
// A project in a fresh scratch folder whose one collider is tests/data/gltf/cube.glb packed into
// `sphereCount` spheres at `position`, moving 2 m along x in its first second.
LoadedProject cubeColliderProject(const char* folderName, ColliderDesc rock) {
    const auto folder = test::scratchDir(folderName);
    std::filesystem::copy_file(test::sourceDir() / "tests/data/gltf/cube.glb", folder / "cube.glb",
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::remove_all(folder / ".grass-cache");
    LoadedProject loaded;
    loaded.folder = folder;
    loaded.file = folder / "project.json";
    rock.name = "rock";
    rock.shape = ColliderShape::Mesh;
    rock.file = "cube.glb";
    rock.path = {{0.0f, rock.position}, {1.0f, rock.position + glm::vec3(2.0f, 0.0f, 0.0f)}};
    loaded.project.colliders = {rock};
    return loaded;
}

TEST(ScenePhysics, MeshColliderIsPlacedPackedSpheres) {
    ColliderDesc rock;
    rock.scale = 2.0f;
    rock.sphereCount = 8;
    rock.packingResolution = 16;
    rock.position = {10.0f, 0.0f, 0.0f};
    const LoadedProject loaded = cubeColliderProject("scene_physics_mesh_collider", rock);

    auto physics = buildScenePhysics(loaded);
    ASSERT_TRUE(physics) << physics.error().str();
    ASSERT_EQ(physics->notes.size(), 1u);
    EXPECT_NE(physics->notes[0].find("packed"), std::string::npos) << physics->notes[0];
    ASSERT_FALSE(physics->colliders.empty());
    ASSERT_LE(physics->colliders.size(), 8u);
    // cube.glb spans [-0.5, 0.5, -0.5] .. [0.5, 1.5, 0.5]; scaled by 2 and moved by +10 in x.
    for (const SphereCollider& sphere : physics->colliders) {
        const glm::vec3 c = sphere.centre;
        EXPECT_GE(c.x - sphere.radiusM, 9.0f - 1e-4f);
        EXPECT_LE(c.x + sphere.radiusM, 11.0f + 1e-4f);
        EXPECT_GE(c.y - sphere.radiusM, 1.0f - 1e-4f);
        EXPECT_LE(c.y + sphere.radiusM, 3.0f + 1e-4f);
        ASSERT_EQ(sphere.path.size(), 2u);
        EXPECT_EQ(sphere.path[0].posWorld, c);
        EXPECT_NEAR(glm::length(sphere.path[1].posWorld - c - glm::vec3(2.0f, 0.0f, 0.0f)), 0.0f,
                    1e-5f);
    }
    // A second build reads the cache and places the same spheres.
    auto again = buildScenePhysics(loaded);
    ASSERT_TRUE(again) << again.error().str();
    EXPECT_EQ(again->colliders, physics->colliders);
    EXPECT_NE(again->notes[0].find("(cached in"), std::string::npos) << again->notes[0];
}

// A packed mesh's broad phase has two levels: the first sphere bounds the whole mesh, the first
// of each later chunk of ~√N spheres (in Morton order) bounds its chunk. Every bound holds its
// spheres, and the blades step bit for bit as with no bounds at all, on the reference and the
// SIMD step: a bound only skips spheres that could not touch the blade.
TEST(ScenePhysics, MeshColliderBoundsItsSpheresInChunks) {
    ColliderDesc rock;
    rock.sphereCount = 40;
    rock.packingResolution = 24;
    rock.position = {-1.0f, -0.6f, 0.0f};
    const LoadedProject loaded = cubeColliderProject("scene_physics_mesh_chunks", rock);
    auto physics = buildScenePhysics(loaded);
    ASSERT_TRUE(physics) << physics.error().str();
    const std::vector<SphereCollider>& spheres = physics->colliders;
    const std::size_t n = spheres.size();
    ASSERT_GE(n, 20u);
    const auto chunk = static_cast<std::size_t>(std::ceil(std::sqrt(double(n))));
    const auto holds = [&](std::size_t head, std::size_t first, std::size_t count) {
        const glm::vec3 bound = spheres[head].centre + spheres[head].boundOffset;
        for (std::size_t i = first; i < first + count; ++i)
            EXPECT_LE(glm::length(spheres[i].centre - bound) + spheres[i].radiusM,
                      spheres[head].boundRadiusM)
                << "sphere " << i << " outside the bound on " << head;
    };
    EXPECT_EQ(spheres[0].groupSize, n);
    holds(0, 0, n);
    std::size_t heads = 0;
    for (std::size_t i = 1; i < n; ++i) {
        if (i % chunk != 0) {
            EXPECT_EQ(spheres[i].groupSize, 1u) << i;
            continue;
        }
        ++heads;
        EXPECT_EQ(spheres[i].groupSize, std::min(chunk, n - i)) << i;
        holds(i, i, spheres[i].groupSize);
        // Morton order keeps a chunk compact: its bound is well inside the mesh's.
        EXPECT_LT(spheres[i].boundRadiusM, spheres[0].boundRadiusM) << i;
    }
    EXPECT_EQ(heads, (n - 1) / chunk);

    std::vector<SphereCollider> unbounded = spheres;
    for (SphereCollider& sphere : unbounded)
        sphere.groupSize = 1;
    std::vector<Blade> blades;
    for (int z = -12; z <= 12; ++z)
        for (int x = -30; x <= 30; ++x)
            blades.push_back(makeRestBlade({0.05f * float(x), 0.0f, 0.05f * float(z)}, {0, 1, 0},
                                           0.3f, 0.01f, 30.0f, 0.1f * float(x + z)));
    const auto tips = restTips(blades);
    for (const CpuPhysics path : {CpuPhysics::Scalar, CpuPhysics::Simd}) {
        SCOPED_TRACE(cpuPhysicsName(path));
        std::vector<Blade> a = blades, b = blades;
        std::vector<float> etaA(blades.size(), 0.0f), etaB = etaA;
        for (int step = 0; step < 30; ++step) {
            const float t = float(step) / 30.0f;
            stepPhysicsOn(path, a, etaA, tips, PhysicsParams{}, {}, spheres, t, 1);
            stepPhysicsOn(path, b, etaB, tips, PhysicsParams{}, {}, unbounded, t, 1);
        }
        EXPECT_EQ(a, b);
        EXPECT_EQ(etaA, etaB);
        EXPECT_GT(std::count_if(etaA.begin(), etaA.end(), [](float e) { return e > 0.0f; }), 50);
    }
}

TEST(ScenePhysics, MissingColliderMeshIsNamed) {
    LoadedProject loaded;
    loaded.folder = test::scratchDir("scene_physics_missing_mesh");
    loaded.file = loaded.folder / "project.json";
    ColliderDesc rock;
    rock.shape = ColliderShape::Mesh;
    rock.file = "nowhere.glb";
    loaded.project.colliders = {rock};
    auto physics = buildScenePhysics(loaded);
    ASSERT_FALSE(physics);
    EXPECT_NE(physics.error().str().find("nowhere.glb"), std::string::npos)
        << physics.error().str();
}

}  // namespace
}  // namespace grass::core
