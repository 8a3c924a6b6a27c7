// A project's physics end to end on the CPU reference: a ball rolled through a field leaves a
// trail of crushed blades behind it while the rest of the field stands (issue 4).
#include "scene/scene_physics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh/gltf_loader.h"
#include "physics/physics.h"
#include "physics/physics_simd.h"
#include "scene/scene_props.h"
#include "support/gltf_writer.h"
#include "support/plane_project.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

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

// A georeferenced ground (a 40 m tile at UTM-like coordinates, centimetres, +Z up) is moved next
// to grass's origin (docs/meshes.md); a rock exported from the same map frame is moved with it,
// in the ground's unit and up axis, so its spheres stand on the field where the map has them.
// Before, the rock stayed at its file's coordinates, 5,400 km away, and touched no blade.
TEST(ScenePhysics, AMeshColliderInAMovedGroundsFrameMovesWithIt) {
    const std::filesystem::path dir = test::scratchDir("scene_physics_georeferenced");
    test::GltfAsset tile = test::singleMeshAsset(test::gridPrimitive(4000.0f, 4000.0f, 4));
    // The grid lies in its x-z plane; turned a quarter about x it lies in x-y, flat for +Z up.
    tile.nodes[0].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    tile.nodes[0].translation = {512345.0f, 5412345.0f, 120.0f};
    test::writeGltf(dir / "tile.gltf", tile);
    // A 2 m × 1 m × 1 m block (file units: cm, +Z up) 5 m east and 3 m north of the tile's
    // centre, standing on it.
    test::writeGltf(dir / "rock.gltf",
                    test::singleMeshAsset(test::boxPrimitive({512745.0f, 5412595.0f, 120.0f},
                                                             {512945.0f, 5412695.0f, 220.0f})));
    ASSERT_TRUE(writeFileAtomic(dir / "project.json", R"({"format": "grass-project", "version": 3,
        "name": "tile", "mesh": {"file": "tile.gltf", "unit": "cm", "up": "+Z"},
        "layers": [{"name": "grass", "density": 4.0}],
        "colliders": [{"name": "rock", "shape": "mesh", "file": "rock.gltf", "spheres": 24}]})")
                    .ok());
    auto loaded = loadProject(dir / "project.json");
    ASSERT_TRUE(loaded) << loaded.error().str();
    auto scene = buildScene(*loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    ASSERT_NE(scene->groundOrigin, glm::dvec3(0.0)) << "the tile must be far enough to move";
    EXPECT_EQ(groundOriginOf(*loaded), scene->groundOrigin);
    // Where the map puts the rock's centre, in grass's frame: (east, up, -north) in metres from
    // the ground's origin.
    const glm::dvec3 rockCentre{512845.0, 5412645.0, 170.0};
    const glm::dvec3 offset = (rockCentre - scene->groundOrigin) * 0.01;
    const glm::vec3 expected(offset.x, offset.z, -offset.y);
    ASSERT_LT(glm::length(expected), 20.0f) << "the rock lies on the tile";

    auto physics = buildScenePhysics(*loaded, scene->groundOrigin);
    ASSERT_TRUE(physics) << physics.error().str();
    ASSERT_FALSE(physics->colliders.empty());
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const SphereCollider& sphere : physics->colliders) {
        lo = glm::min(lo, sphere.centre - glm::vec3(sphere.radiusM));
        hi = glm::max(hi, sphere.centre + glm::vec3(sphere.radiusM));
    }
    // The spheres' bounds cover the block (2 m east-west, 1 m up, 1 m north-south) around
    // where the map has it, within the packing's slack.
    EXPECT_LT(glm::length(0.5f * (lo + hi) - expected), 0.15f)
        << lo.x << " " << lo.y << " " << lo.z << " / " << hi.x << " " << hi.y << " " << hi.z;
    EXPECT_NEAR(hi.x - lo.x, 2.0f, 0.2f);
    EXPECT_NEAR(hi.y - lo.y, 1.0f, 0.2f);
    EXPECT_NEAR(hi.z - lo.z, 1.0f, 0.2f);
    EXPECT_TRUE(std::any_of(physics->notes.begin(), physics->notes.end(), [](const std::string& n) {
        return n.find("collider rock: rock.gltf lies") != std::string::npos &&
               n.find("placed in the ground's frame") != std::string::npos;
    }));
    // The drawn rock (a prop) stands in the same place.
    ASSERT_EQ(scene->props.size(), 1u);
    const Bounds drawn = meshBounds(scene->props[0].mesh);
    EXPECT_LT(glm::length(0.5f * (drawn.min + drawn.max) - expected), 1e-3f);

    // A ground that was not moved leaves a far rock where its file has it, and says so.
    auto nearGround = *loaded;
    nearGround.project.mesh = MeshSource{};
    auto unmoved = buildScenePhysics(nearGround, glm::dvec3(0.0));
    ASSERT_TRUE(unmoved) << unmoved.error().str();
    EXPECT_GT(glm::length(unmoved->colliders[0].centre), 1e6f);
    EXPECT_TRUE(std::any_of(unmoved->notes.begin(), unmoved->notes.end(), [](const std::string& n) {
        return n.find("out of the field's reach") != std::string::npos;
    }));
}

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

// A packed mesh's broad phase is nested three levels deep: the first sphere bounds the whole
// mesh, which is cut into ∛N runs of neighbours (in Morton order), each cut again; the first
// sphere of every later run bounds its run. Every bound holds its spheres, runs nest inside the
// run they start in, and the blades step bit for bit as with no bounds at all, on the reference
// and the SIMD step: a bound only skips spheres that could not touch the blade.
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
    ASSERT_GE(n, 27u);  // enough for three levels of three
    EXPECT_EQ(spheres[0].groupSize, n);
    // The run each sphere lies in at each depth: ends[d] is where the run at depth d ends.
    std::vector<std::size_t> ends{n};
    std::size_t deepest = 0, bounds = 0;
    for (std::size_t i = 0; i < n; ++i) {
        while (i >= ends.back())
            ends.pop_back();
        const SphereCollider& head = spheres[i];
        if (head.groupSize <= 1)
            continue;
        ++bounds;
        const std::size_t end = i + head.groupSize;
        EXPECT_LE(end, ends.back()) << "the run at " << i << " leaves the run it starts in";
        const glm::vec3 bound = head.centre + head.boundOffset;
        for (std::size_t k = i; k < std::min(end, n); ++k)
            EXPECT_LE(glm::length(spheres[k].centre - bound) + spheres[k].radiusM,
                      head.boundRadiusM)
                << "sphere " << k << " outside the bound on " << i;
        if (i > 0) {
            ends.push_back(end);
            deepest = std::max(deepest, ends.size() - 1);
            // Morton order keeps a run compact: its bound is well inside the mesh's.
            EXPECT_LT(head.boundRadiusM, spheres[0].boundRadiusM) << i;
        }
    }
    EXPECT_EQ(deepest, 2u) << "runs and runs within runs below the mesh's bound";
    EXPECT_GE(bounds, 6u);

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
