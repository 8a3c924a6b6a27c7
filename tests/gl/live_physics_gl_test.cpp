// Issue 29: the editor's live physics runs where it is fastest — the SIMD execution on the CPU
// with one upload a frame on software GL, the compute shader elsewhere (app/live_scene.h). Both
// devices must move the renderer's blades alike, and auto must pick the CPU on llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include "app/collider_packing_job.h"
#include "app/live_scene.h"
#include "gl/headless_context.h"
#include "gl_context_fixture.h"
#include "scene/motion_edit.h"
#include "scene/scene_physics.h"
#include "support/density_dab.h"
#include "support/gltf_writer.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using LivePhysicsTest = GlTest;

std::vector<core::Blade> rendererBlades(const editor::Live& live, std::size_t layer) {
    const gl::BufferRef buffer = live.renderer->bladeBuffers().at(layer);
    const std::size_t count = live.scene->layers[layer].patched.blades.size();
    std::vector<core::Blade> blades(count);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(count * sizeof(core::Blade)), blades.data());
    return blades;
}

editor::Live liveOn(const core::LoadedProject& loaded, editor::PhysicsDevice device) {
    auto grown = editor::growField(loaded, true);
    EXPECT_TRUE(grown.ok()) << grown.error().str();
    auto live = editor::bringUpLive(std::move(*grown), {}, device);
    EXPECT_TRUE(live.ok()) << live.error().str();
    return std::move(*live);
}

// tests/data/projects/windy: a gusty breeze, a vortex on a path and a rolling ball, 1 s.
TEST_F(LivePhysicsTest, CpuAndGpuMoveTheRenderersBladesAlike) {
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/windy");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    editor::Live cpu = liveOn(*loaded, editor::PhysicsDevice::Cpu);
    editor::Live gpu = liveOn(*loaded, editor::PhysicsDevice::Gpu);
    ASSERT_TRUE(cpu.physics && cpu.physics->cpu && !cpu.physics->gpu);
    ASSERT_TRUE(gpu.physics && gpu.physics->gpu && !gpu.physics->cpu);
    EXPECT_EQ(cpu.physics->deviceLabel(), "cpu");
    const std::vector<core::Blade> rest = cpu.scene->layers[0].patched.blades;
    // Frame by frame as the editor does (a tenth of a second a frame), with no step cap, so both
    // simulate the same steps.
    for (double t = 0.1; t <= 1.0 + 1e-9; t += 0.1) {
        EXPECT_EQ(cpu.physics->advanceTo(t, 1000), 0.0);
        EXPECT_EQ(gpu.physics->advanceTo(t, 1000), 0.0);
    }
    ASSERT_EQ(cpu.physics->steps, gpu.physics->steps);
    const std::vector<core::Blade> a = rendererBlades(cpu, 0), b = rendererBlades(gpu, 0);
    float maxTip = 0.0f, moved = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!(rest[i].h() > 0.0f))
            continue;
        maxTip = std::max(maxTip, glm::length(a[i].v2() - b[i].v2()) / rest[i].h());
        moved = std::max(moved, glm::length(a[i].v2() - rest[i].v2()));
    }
    std::printf("[ live physics ] %zu steps: max |v2_cpu - v2_gpu| / h = %.3g, tips moved up to "
                "%.3f m\n",
                cpu.physics->steps, double(maxTip), double(moved));
    EXPECT_GT(moved, 0.01f);   // the field did move on the CPU device's uploads
    EXPECT_LT(maxTip, 1e-3f);  // the CPU/GPU tolerance (docs/physics.md)
    // The scene itself stays at rest: the tools pick and paint it.
    EXPECT_EQ(std::memcmp(rest.data(), cpu.scene->layers[0].patched.blades.data(),
                          rest.size() * sizeof(core::Blade)),
              0);
    // A re-grown patch restarts at rest in the CPU's copy.
    cpu.physics->regrown(0, *cpu.scene, {0});
    const std::span<const core::Blade> copy = cpu.physics->cpu->blades(0);
    const std::size_t patch = cpu.scene->layers[0].patched.patchSize;
    EXPECT_EQ(std::memcmp(copy.data(), rest.data(), patch * sizeof(core::Blade)), 0);
}

// tests/data/projects/tiny live on `device`: no wind, no collider.
editor::Live tinyLiveOn(editor::PhysicsDevice device) {
    auto tiny = core::loadProject(sourceDir() / "tests/data/projects/tiny");
    EXPECT_TRUE(tiny.ok()) << tiny.error().str();
    return tiny.ok() ? liveOn(*tiny, device) : editor::Live{};
}

// Plays the live field frame by frame (a tenth of a second each) until it rests, 10 s at most,
// then 2 s more, in which it must compute no step, keep its clock and leave the renderer's blades
// as they were. Returns the time played; negative when it never rested.
double playUntilItRests(editor::Live& live, const char* what) {
    editor::LivePhysics& physics = *live.physics;
    EXPECT_TRUE(physics.timeIndependent);
    double t = 0.0;
    for (; t < 10.0 && !physics.resting; t += 0.1)
        EXPECT_EQ(physics.advanceTo(t, 1000), 0.0);
    if (!physics.resting) {
        ADD_FAILURE() << what << ": still stepping after " << t << " s";
        return -1.0;
    }
    std::printf("[ live physics ] %s rests after %.1f s (%zu steps)\n", what, t,
                physics.computedSteps);
    const std::size_t computed = physics.computedSteps;
    const std::vector<core::Blade> shown = rendererBlades(live, 0);
    for (double until = t + 2.0; t < until; t += 0.1)
        EXPECT_EQ(physics.advanceTo(t, 1000), 0.0);
    EXPECT_EQ(physics.computedSteps, computed) << what << ": a resting field computes no step";
    EXPECT_NEAR(physics.timeS(), t - 0.1, physics.scene.params.dtS) << "its clock goes on";
    EXPECT_FALSE(physics.moved) << what << ": nor is it drawn again";
    const std::vector<core::Blade> after = rendererBlades(live, 0);
    EXPECT_EQ(std::memcmp(shown.data(), after.data(), shown.size() * sizeof(core::Blade)), 0);
    return t;
}

// The windy project, whose wind depends on time, never rests.
void expectTheWindyFieldNeverRests(editor::PhysicsDevice device) {
    auto windy = core::loadProject(sourceDir() / "tests/data/projects/windy");
    ASSERT_TRUE(windy.ok()) << windy.error().str();
    editor::Live blown = liveOn(*windy, device);
    EXPECT_FALSE(blown.physics->timeIndependent);
    for (double s = 0.1; s < 3.0; s += 0.1)
        blown.physics->advanceTo(s, 1000);
    EXPECT_FALSE(blown.physics->resting);
    EXPECT_TRUE(blown.physics->moved);
}

// A field that nothing moves rests on the CPU: tests/data/projects/tiny has no wind and no
// collider, its blades settle under gravity, and after REST_AFTER_STEPS still steps the clock
// goes on without computing a step, the renderer's blades as they were. A re-grow wakes it.
TEST_F(LivePhysicsTest, AFieldThatNothingMovesRestsUntilItsBladesAreMoved) {
    editor::Live live = tinyLiveOn(editor::PhysicsDevice::Cpu);
    ASSERT_TRUE(live.physics && live.physics->cpu);
    editor::LivePhysics& physics = *live.physics;
    const double t = playUntilItRests(live, "the tiny field on the CPU");
    ASSERT_GT(t, 0.0);
    // Resting changes nothing a step would have: one more computed step moves no tip.
    const std::size_t computed = physics.computedSteps;
    physics.wake();
    physics.advanceTo(t + 0.05, 1000);
    EXPECT_GT(physics.computedSteps, computed);
    EXPECT_FALSE(physics.moved) << "the rest was a fixed point of the step";
    physics.regrown(0, *live.scene, {0});
    EXPECT_FALSE(physics.resting) << "a re-grow wakes it";
    expectTheWindyFieldNeverRests(editor::PhysicsDevice::Cpu);
}

// The same on the GPU, whose blades are stepped in place and never read back: its steps mark
// whether they moved the field (physics.comp, read a frame later behind a fence), and a field
// that nothing moves rests there too. Before 2026-12-07 it never did: the editor stepped and
// drew a still field every frame while the timeline played.
TEST_F(LivePhysicsTest, AFieldThatNothingMovesRestsOnTheGpuToo) {
    editor::Live live = tinyLiveOn(editor::PhysicsDevice::Gpu);
    ASSERT_TRUE(live.physics && live.physics->gpu);
    editor::LivePhysics& physics = *live.physics;
    double t = playUntilItRests(live, "the tiny field on the GPU");
    ASSERT_GT(t, 0.0);
    // It rested where it had settled: a second more of steps moves no tip by the share.
    const std::vector<core::Blade> shown = rendererBlades(live, 0);
    physics.wake();
    for (double until = t + 1.0; t < until; t += 0.1)
        physics.advanceTo(t, 1000);
    const std::vector<core::Blade> later = rendererBlades(live, 0);
    float moved = 0.0f;
    for (std::size_t i = 0; i < shown.size(); ++i)
        if (shown[i].h() > 0.0f)
            moved = std::max(moved, glm::length(later[i].v2() - shown[i].v2()) / shown[i].h());
    EXPECT_LE(moved, editor::STILL_TIP_SHARE);
    physics.regrown(0, *live.scene, {0});
    EXPECT_FALSE(physics.resting) << "a re-grow wakes it";
    expectTheWindyFieldNeverRests(editor::PhysicsDevice::Gpu);
}

// The largest η over the live field's first layer, on either device.
float largestEta(const editor::LivePhysics& physics) {
    const std::vector<float> eta =
        physics.cpu ? std::vector<float>(physics.cpu->eta(0).begin(), physics.cpu->eta(0).end())
                    : physics.gpu->readEta(0);
    return eta.empty() ? 0.0f : *std::max_element(eta.begin(), eta.end());
}

// A ball sunk into a plane's grass (a rock) holds the blades under it crushed for good, and the
// field must rest as a field without it does; once the ball is gone its trail must not rest
// until the crushed blades have recovered (η 0 everywhere).
void expectAStillBallLetsTheFieldRestButNotItsTrail(editor::PhysicsDevice device) {
    core::LoadedProject loaded = planeFieldProject({2.0f, 4, 60.0f, 0.3f, 0.5f});
    addBall(loaded, {0.0f, 0.15f, 0.0f}, 0.4f);
    editor::Live live = liveOn(loaded, device);
    ASSERT_TRUE(live.physics);
    editor::LivePhysics& physics = *live.physics;
    EXPECT_TRUE(physics.timeIndependent);
    double t = 0.0;
    for (; t < 30.0 && !physics.resting; t += 0.1)
        physics.advanceTo(t, 1000);
    ASSERT_TRUE(physics.resting) << physics.deviceLabel() << ": still stepping after " << t << " s";
    EXPECT_GT(largestEta(physics), 1.0f) << "the blades under the ball rest crushed";
    std::printf(
        "[ live physics ] on the %s the field under a still ball rests after %.1f s, "
        "largest eta %.1f\n",
        physics.deviceLabel().c_str(), t, double(largestEta(physics)));
    if (physics.cpu) {
        // The rest is a fixed point of the step: one more computed frame moves no tip.
        physics.wake();
        physics.advanceTo(t + 0.1, 1000);
        EXPECT_FALSE(physics.moved);
    }
    // The ball lifted away: the crushed blades recover, standing still at first (stiffness held
    // at the floor while η decays), and the field rests only once they have.
    physics.scene.colliders.clear();
    physics.wake();
    const double recovered = t + largestEta(physics) / physics.scene.params.etaDecayPerS;
    for (t += 0.2; t < recovered + 30.0 && !physics.resting; t += 0.1)
        physics.advanceTo(t, 1000);
    ASSERT_TRUE(physics.resting) << physics.deviceLabel() << ": still stepping after " << t << " s";
    EXPECT_GE(t, recovered - 1.0) << "rested before η could decay";
    EXPECT_EQ(largestEta(physics), 0.0f) << "a recovering blade let the field rest";
}

// projects/winter played on: its rocks hold the blades under them crushed for good (it never
// rested: η rose under the rocks every step, so the editor stepped 473 blades' worth of nothing
// every frame and drew the reduced picture of a moving field).
TEST_F(LivePhysicsTest, BladesAStillColliderHoldsDownLetTheFieldRestButATrailDoesNot) {
    expectAStillBallLetsTheFieldRestButNotItsTrail(editor::PhysicsDevice::Cpu);
}

TEST_F(LivePhysicsTest, BladesAStillColliderHoldsDownLetTheFieldRestOnTheGpuButATrailDoesNot) {
    expectAStillBallLetsTheFieldRestButNotItsTrail(editor::PhysicsDevice::Gpu);
}

// The lowest tip (v2.y) among the blades whose root lies within `radiusM` of the plane's centre.
float lowestTipNearCentre(std::span<const core::Blade> blades, float radiusM) {
    float lowest = 1e30f;
    for (const core::Blade& blade : blades)
        if (glm::length(glm::vec2(blade.v0().x, blade.v0().z)) < radiusM)
            lowest = std::min(lowest, blade.v2().y);
    return lowest;
}

// A ball moved (a gizmo drag, a typed position) is followed at once without growing the field
// again (editor::followMotion): the physics takes the ball where it now stands, built as a fresh
// build of the edited project builds it, its prop moves, and the field's blades stay the ones it
// had, then bend under the ball. Before, the editor grew the whole field again for each such
// edit, and its blades restarted from rest.
TEST_F(LivePhysicsTest, AMovedBallPushesTheBladesWithoutTheFieldGrowingAgain) {
    core::LoadedProject loaded = planeFieldProject({2.0f, 4, 60.0f, 0.3f, 0.5f});
    addBall(loaded, {0.0f, 3.0f, 0.0f}, 0.4f);  // out of every blade's reach
    core::LoadedProject moved = loaded;
    moved.project.colliders[0].position = {0.0f, 0.15f, 0.0f};  // sunk into the grass
    auto expected = core::buildScenePhysics(moved);
    ASSERT_TRUE(expected.ok()) << expected.error().str();
    for (const auto device : {editor::PhysicsDevice::Cpu, editor::PhysicsDevice::Gpu}) {
        editor::Live live = liveOn(loaded, device);
        ASSERT_TRUE(live.physics);
        editor::LivePhysics& physics = *live.physics;
        physics.advanceTo(1.0, 1000);
        const core::Scene* field = live.scene.get();
        const std::size_t blades = field->layers[0].patched.blades.size();
        const float before = lowestTipNearCentre(rendererBlades(live, 0), 0.2f);

        auto followed = editor::followMotion(live, moved, /*settled=*/true);
        ASSERT_TRUE(followed.ok()) << followed.error().str();
        EXPECT_TRUE(*followed);
        EXPECT_TRUE(physics.scene.colliders == expected->colliders);
        EXPECT_EQ(live.scene->props[0].position, moved.project.colliders[0].position);
        EXPECT_FALSE(*editor::followMotion(live, moved, true)) << "nothing more to follow";
        physics.advanceTo(2.0, 1000);
        EXPECT_EQ(live.scene.get(), field);
        EXPECT_EQ(live.scene->layers[0].patched.blades.size(), blades);
        const float after = lowestTipNearCentre(rendererBlades(live, 0), 0.2f);
        std::printf("[ live physics ] %s: lowest tip under the ball %.3f m before, %.3f m after\n",
                    editor::physicsDeviceName(device), double(before), double(after));
        EXPECT_GT(before, 0.25f) << "the field stood before the ball came";
        EXPECT_LT(after, 0.1f) << "the moved ball did not crush the blades under it";
    }
}

// A quality preset's substeps (or another step) are followed live: the physics steps on with
// them from the time it had reached, the field keeps its blades. Before, the editor grew the
// field again for them.
TEST_F(LivePhysicsTest, AnotherPhysicsStepIsFollowedWithoutTheFieldGrowingAgain) {
    core::LoadedProject loaded = planeFieldProject({2.0f, 4, 60.0f, 0.3f, 0.5f});
    loaded.project.wind.push_back(core::WindDesc{});
    for (const auto device : {editor::PhysicsDevice::Cpu, editor::PhysicsDevice::Gpu}) {
        editor::Live live = liveOn(loaded, device);
        ASSERT_TRUE(live.physics);
        editor::LivePhysics& physics = *live.physics;
        physics.advanceTo(0.5, 1000);
        const core::Scene* field = live.scene.get();
        core::LoadedProject stepped = loaded;
        stepped.project.physics.maxSubstepS = 1.0f / 240.0f;
        stepped.project.physics.dtS = 1.0f / 30.0f;
        ASSERT_TRUE(core::onlyMotionChanged(loaded.project, stepped.project));
        auto followed = editor::followMotion(live, stepped, /*settled=*/true);
        ASSERT_TRUE(followed.ok()) << followed.error().str();
        EXPECT_TRUE(*followed);
        EXPECT_TRUE(physics.scene.params == stepped.project.physics);
        EXPECT_NEAR(physics.timeS(), 0.5, 1e-6) << "the physics' time stays where it was";
        EXPECT_FALSE(*editor::followMotion(live, stepped, true)) << "nothing more to follow";
        const std::size_t computedBefore = physics.computedSteps;
        physics.advanceTo(1.01, 1000);
        EXPECT_GT(physics.computedSteps, computedBefore);
        EXPECT_EQ(physics.steps, 30u) << "1.01 s in whole steps of 1/30 s (60 of the old 1/60 s)";
        EXPECT_EQ(live.scene.get(), field);
        for (const core::Blade& blade : rendererBlades(live, 0))
            EXPECT_TRUE(std::isfinite(blade.v2W.x) && std::isfinite(blade.v2W.y))
                << "a blade blew up";
    }
}

// A ball added, then deleted, is followed as a moved one is: its prop is made (and drawn by the
// renderer) or dropped, the physics takes it or lets it go, and the field keeps its blades. A
// mesh collider whose packing the field does not hold yet is left to a re-grow (packing can take
// seconds, on the re-grow's worker).
TEST_F(LivePhysicsTest, ABallAddedOrDeletedIsFollowedWithoutTheFieldGrowingAgain) {
    core::LoadedProject loaded = planeFieldProject({2.0f, 4, 60.0f, 0.3f, 0.5f});
    editor::Live live = liveOn(loaded, editor::PhysicsDevice::Cpu);
    ASSERT_TRUE(live.physics);
    const core::Scene* field = live.scene.get();
    EXPECT_EQ(live.renderer->propCount(), 0u);

    core::LoadedProject added = loaded;
    addBall(added, {0.0f, 0.15f, 0.0f}, 0.4f);
    auto followed = editor::followMotion(live, added, /*settled=*/true);
    ASSERT_TRUE(followed.ok()) << followed.error().str();
    EXPECT_EQ(live.scene->props.size(), 1u);
    EXPECT_EQ(live.renderer->propCount(), 1u);
    EXPECT_EQ(live.physics->scene.colliders.size(), 1u);
    live.physics->advanceTo(1.0, 1000);
    EXPECT_LT(lowestTipNearCentre(live.physics->cpu->blades(0), 0.2f), 0.05f)
        << "the added ball crushes the blades under it";

    ASSERT_TRUE(editor::followMotion(live, loaded, /*settled=*/true).ok());
    EXPECT_TRUE(live.scene->props.empty());
    EXPECT_EQ(live.renderer->propCount(), 0u);
    EXPECT_TRUE(live.physics->scene.colliders.empty());
    live.physics->advanceTo(4.0, 1000);
    EXPECT_GT(lowestTipNearCentre(live.physics->cpu->blades(0), 0.2f), 0.25f)
        << "the blades rise once the ball is deleted";
    EXPECT_EQ(live.scene.get(), field);

    core::ColliderDesc rock;
    rock.shape = core::ColliderShape::Mesh;
    rock.file = "rock.glb";
    EXPECT_FALSE(live.motion.packed({rock}));
    EXPECT_TRUE(live.motion.packed(added.project.colliders));
}

// A plane field in `dir` with a rock on it: a mesh collider of 16 spheres, its box in rock.gltf.
core::LoadedProject rockProject(const std::filesystem::path& dir) {
    writeGltf(dir / "rock.gltf",
              singleMeshAsset(boxPrimitive({-0.3f, 0.0f, -0.2f}, {0.3f, 0.4f, 0.2f})));
    core::LoadedProject loaded = planeFieldProject({2.0f, 4, 60.0f, 0.3f, 0.5f}, dir);
    core::ColliderDesc rock;
    rock.name = "rock";
    rock.shape = core::ColliderShape::Mesh;
    rock.file = "rock.gltf";
    rock.sphereCount = 16;
    loaded.project.colliders = {rock};
    return loaded;
}

// A mesh collider (a rock) dragged in the editor is followed from the packing its field was grown
// with: no frame of the drag reads its mesh or its packing cache (here both are gone), and its
// spheres are those a fresh build of the moved rock would give.
TEST_F(LivePhysicsTest, ADraggedRockIsFollowedWithoutReadingItsFiles) {
    const std::filesystem::path dir = scratchDir("live_physics_rock");
    core::LoadedProject loaded = rockProject(dir);
    core::LoadedProject moved = loaded;
    moved.project.colliders[0].position = {0.5f, 0.0f, 0.2f};
    auto expected = core::buildScenePhysics(moved);
    ASSERT_TRUE(expected.ok()) << expected.error().str();

    editor::Live live = liveOn(loaded, editor::PhysicsDevice::Cpu);
    ASSERT_TRUE(live.physics);
    std::filesystem::remove(dir / "rock.gltf");
    std::filesystem::remove_all(dir / ".grass-cache");
    auto followed = editor::followMotion(live, moved, /*settled=*/false);
    ASSERT_TRUE(followed.ok()) << followed.error().str();
    EXPECT_TRUE(live.physics->scene.colliders == expected->colliders);
}

// A rock re-exported from a modeller while the editor plays (its file changed on disk,
// project_file_watch.cpp) is packed again on a worker and its prop read there too, as the
// Editor does (ColliderPackingJob); the next follow takes both: the physics holds the spheres a
// fresh build of the new file gives, the prop is the new mesh, and the field is the one it was,
// its blades in motion. Before, the whole field grew again and its blades restarted from rest.
TEST_F(LivePhysicsTest, ARockChangedOnDiskIsPackedAgainWithoutTheFieldGrowingAgain) {
    const std::filesystem::path dir = scratchDir("live_physics_rock_changed");
    core::LoadedProject loaded = rockProject(dir);
    editor::Live live = liveOn(loaded, editor::PhysicsDevice::Cpu);
    ASSERT_TRUE(live.physics);
    live.physics->advanceTo(0.5, 1000);
    const core::Scene* field = live.scene.get();
    const std::size_t steps = live.physics->steps;

    // The rock made taller and narrower in the modeller.
    writeGltf(dir / "rock.gltf",
              singleMeshAsset(boxPrimitive({-0.1f, 0.0f, -0.1f}, {0.1f, 0.9f, 0.1f})));
    auto expected = core::buildScenePhysics(loaded);
    ASSERT_TRUE(expected.ok()) << expected.error().str();
    ASSERT_FALSE(live.physics->scene.colliders == expected->colliders) << "the old packing";
    EXPECT_FALSE(*editor::followMotion(live, loaded, true)) << "nothing is known to have changed";

    live.motion.forgetFiles({"rock.gltf"});
    EXPECT_FALSE(live.motion.packed(loaded.project.colliders));
    editor::ColliderPackingJob job(loaded, live.scene->groundOrigin, live.motion.packings, {},
                                   live.motion.changedFiles);
    job.wait();
    auto packed = job.take();
    ASSERT_TRUE(packed.ok()) << packed.error().str();
    ASSERT_EQ(packed->props.count("rock.gltf"), 1u) << "the prop's mesh read on the worker";
    live.motion.takeReadAhead(std::move(packed->packings), std::move(packed->props));
    ASSERT_TRUE(live.motion.packed(loaded.project.colliders));
    // The window reads no file for it now.
    std::filesystem::remove(dir / "rock.gltf");
    std::filesystem::remove_all(dir / ".grass-cache");
    auto followed = editor::followMotion(live, loaded, /*settled=*/true);
    ASSERT_TRUE(followed.ok()) << followed.error().str();
    EXPECT_TRUE(*followed);
    EXPECT_TRUE(live.physics->scene.colliders == expected->colliders);
    ASSERT_EQ(live.scene->props.size(), 1u);
    const core::Bounds bounds = core::meshBounds(live.scene->props[0].mesh);
    EXPECT_NEAR(bounds.max.y, 0.9f, 1e-5f);
    EXPECT_NEAR(bounds.max.x, 0.1f, 1e-5f);
    EXPECT_TRUE(live.motion.changedFiles.empty());
    EXPECT_EQ(live.scene.get(), field) << "the same field";
    EXPECT_EQ(live.physics->steps, steps) << "stepping on, not restarted";
    EXPECT_FALSE(*editor::followMotion(live, loaded, true)) << "followed once";
}

// A ball that sat on the grass for a while and is then moved away by an edit lets go of the
// blades it held: they rise within seconds, as after a fresh trail. Before (once an edit no longer
// grew the field again), η had grown under the still ball by d·d every step, and the blades where
// it stood stayed flat for η / decay seconds (~80 s after these 20 s).
TEST_F(LivePhysicsTest, BladesABallHeldDownRiseSoonAfterAnEditMovesItAway) {
    core::LoadedProject loaded = planeFieldProject({2.0f, 4, 60.0f, 0.3f, 0.5f});
    addBall(loaded, {0.0f, 0.15f, 0.0f}, 0.4f);  // sunk into the grass
    core::LoadedProject moved = loaded;
    moved.project.colliders[0].position = {0.0f, 3.0f, 0.0f};  // lifted out of reach
    for (const auto device : {editor::PhysicsDevice::Cpu, editor::PhysicsDevice::Gpu}) {
        editor::Live live = liveOn(loaded, device);
        ASSERT_TRUE(live.physics);
        editor::LivePhysics& physics = *live.physics;
        for (double t = 0.5; t <= 20.0; t += 0.5)
            physics.advanceTo(t, 1000);
        const float held = lowestTipNearCentre(rendererBlades(live, 0), 0.2f);
        ASSERT_TRUE(editor::followMotion(live, moved, /*settled=*/true).ok());
        if (physics.cpu) {
            const std::span<const float> eta = physics.cpu->eta(0);
            EXPECT_LE(*std::max_element(eta.begin(), eta.end()), editor::LivePhysics::RELEASED_ETA);
        }
        for (double t = 20.5; t <= 23.0; t += 0.5)
            physics.advanceTo(t, 1000);
        const float risen = lowestTipNearCentre(rendererBlades(live, 0), 0.2f);
        std::printf(
            "[ live physics ] %s: lowest tip where the ball stood %.3f m, 3 s after it "
            "was moved away %.3f m\n",
            editor::physicsDeviceName(device), double(held), double(risen));
        EXPECT_LT(held, 0.05f);
        EXPECT_GT(risen, 0.25f) << "the blades the ball held stayed down after it was moved";
    }
}

// A plane under 10 cm of snow (no wind, no collider) whose load bends the blades: 60 m/s² per
// metre of snow on an open blade.
core::LoadedProject snowyPlane(float loadGravity) {
    core::LoadedProject loaded = planeFieldProject({4.0f, 8, 40.0f, 0.3f, 0.5f});
    core::SnowParams& snow = loaded.project.snow;
    snow.enabled = 1u;
    snow.amountM = 0.1f;
    snow.fallDirection = {0.0f, -1.0f, 0.0f};
    snow.mapResolution = 256;
    snow.loadGravity = loadGravity;
    return loaded;
}

// A project as `grass render --time` simulates it (SceneSimulation), with its blades at rest.
struct RenderedField {
    core::Scene scene;
    std::vector<core::Blade> rest;
    std::optional<core::SceneSimulation> simulation;  // steps `scene`
};
std::unique_ptr<RenderedField> renderedField(const core::LoadedProject& loaded) {
    auto scene = core::buildScene(loaded);
    auto physics = core::buildScenePhysics(loaded);
    EXPECT_TRUE(scene.ok() && physics.ok());
    if (!scene.ok() || !physics.ok())
        return nullptr;
    auto field = std::make_unique<RenderedField>();
    field->scene = std::move(*scene);
    field->rest = field->scene.layers[0].patched.blades;
    field->simulation.emplace(field->scene, std::move(*physics));
    return field;
}

// Under snow, a ball moved by an edit shelters other ground: once the edit ends the blades are
// weighed again under it where it now stands, as a field grown with the ball there is weighed.
TEST_F(LivePhysicsTest, ABallMovedUnderSnowWeighsTheBladesAgainUnderItsNewShelter) {
    core::LoadedProject loaded = snowyPlane(60.0f);
    addBall(loaded, {-1.0f, 0.8f, 0.0f}, 0.5f);  // above the grass: a shelter, no crush
    core::LoadedProject moved = loaded;
    moved.project.colliders[0].position = {1.0f, 0.8f, 0.5f};
    const auto fresh = renderedField(moved);
    ASSERT_TRUE(fresh);
    const std::vector<float>& expected = fresh->simulation->physics().snowLoadPerMetre.at(0);

    editor::Live live = liveOn(loaded, editor::PhysicsDevice::Cpu);
    ASSERT_TRUE(live.physics && live.physics->scene.anySnowLoad());
    const std::vector<float> before = live.physics->scene.snowLoadPerMetre.at(0);
    ASSERT_NE(before, expected) << "the ball must shelter other blades where it goes";
    ASSERT_TRUE(editor::followMotion(live, moved, /*settled=*/false).ok());
    EXPECT_EQ(live.physics->scene.snowLoadPerMetre.at(0), before) << "weighed during the drag";
    ASSERT_TRUE(editor::followMotion(live, moved, /*settled=*/true).ok());
    EXPECT_EQ(live.physics->scene.snowLoadPerMetre.at(0), expected);
}

// The editor's live field bends under its snow as `grass render --time` bends it
// (SceneSimulation): before, the live physics never weighed the snow, so the editor's field stood
// upright under it, and auto sent a snowy scene to the compute shader (llvmpipe's slowest path,
// "physics behind") for a load it did not apply. Both devices, 1 s, against the render's steps.
TEST_F(LivePhysicsTest, TheLiveFieldBendsUnderItsSnowAsTheRenderedOneDoes) {
    const core::LoadedProject loaded = snowyPlane(60.0f);
    const auto field = renderedField(loaded);
    ASSERT_TRUE(field);
    const std::vector<core::Blade>& rest = field->rest;
    core::SceneSimulation& rendered = *field->simulation;
    ASSERT_TRUE(rendered.physics().anySnowLoad());

    editor::Live cpu = liveOn(loaded, editor::PhysicsDevice::Cpu);
    editor::Live gpu = liveOn(loaded, editor::PhysicsDevice::Gpu);
    editor::Live automatic = liveOn(loaded, editor::PhysicsDevice::Auto);
    EXPECT_EQ(automatic.physics->cpu.has_value(), gl::isSoftwareRenderer())
        << "snow does not keep a software renderer's physics off the CPU";
    EXPECT_TRUE(cpu.physics->timeIndependent) << "a load that neither grows nor melts";
    for (double t = 0.1; t <= 1.0 + 1e-9; t += 0.1) {
        cpu.physics->advanceTo(t, 1000);
        gpu.physics->advanceTo(t, 1000);
    }
    while (rendered.stepsDone() < cpu.physics->steps)
        rendered.step();
    ASSERT_EQ(gpu.physics->steps, cpu.physics->steps);
    const std::vector<core::Blade> a = rendererBlades(cpu, 0), b = rendererBlades(gpu, 0);
    const std::vector<core::Blade>& reference = field->scene.layers[0].patched.blades;
    float cpuError = 0.0f, gpuError = 0.0f, deepestDrop = 0.0f;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const float h = rest[i].h();
        if (!(h > 0.0f))
            continue;
        cpuError = std::max(cpuError, glm::length(a[i].v2() - reference[i].v2()) / h);
        gpuError = std::max(gpuError, glm::length(b[i].v2() - reference[i].v2()) / h);
        deepestDrop = std::max(deepestDrop, (rest[i].v2().y - reference[i].v2().y) / h);
    }
    // Without the load the same field settles under gravity alone: the snow must bend it more.
    editor::Live bare = liveOn(snowyPlane(0.0f), editor::PhysicsDevice::Cpu);
    bare.physics->advanceTo(1.0, 1000);
    const std::vector<core::Blade> unloaded = rendererBlades(bare, 0);
    float bareDrop = 0.0f;
    for (std::size_t i = 0; i < rest.size(); ++i)
        if (rest[i].h() > 0.0f)
            bareDrop = std::max(bareDrop, (rest[i].v2().y - unloaded[i].v2().y) / rest[i].h());
    std::printf(
        "[ live physics ] under snow: tips down by up to %.3f h (%.3f h without the load); "
        "live against rendered: cpu %.3g h, gpu %.3g h\n",
        double(deepestDrop), double(bareDrop), double(cpuError), double(gpuError));
    EXPECT_GT(deepestDrop, bareDrop + 0.05f) << "the snow bends the rendered field";
    EXPECT_LT(cpuError, 1e-3f);  // the CPU/GPU tolerance (docs/physics.md)
    EXPECT_LT(gpuError, 1e-3f);

    // An edit of the Snow section re-grows nothing: the live physics follows it, and the blades
    // rise once the snow weighs nothing.
    core::SnowParams weightless = loaded.project.snow;
    weightless.loadGravity = 0.0f;
    for (editor::Live* live : {&cpu, &gpu}) {
        EXPECT_TRUE(live->physics->followSnow(weightless, *live->scene));
        EXPECT_FALSE(live->physics->followSnow(weightless, *live->scene)) << "nothing new";
        EXPECT_FALSE(live->physics->scene.anySnowLoad());
        for (double t = 1.1; t <= 3.0 + 1e-9; t += 0.1)
            live->physics->advanceTo(t, 1000);
        const std::vector<core::Blade> risen = rendererBlades(*live, 0);
        float drop = 0.0f;
        for (std::size_t i = 0; i < rest.size(); ++i)
            if (rest[i].h() > 0.0f)
                drop = std::max(drop, (rest[i].v2().y - risen[i].v2().y) / rest[i].h());
        std::printf("[ live physics ] %s, the snow weightless: tips down by up to %.3f h\n",
                    live->physics->deviceLabel().c_str(), double(drop));
        EXPECT_LT(drop, bareDrop + 0.02f) << live->physics->deviceLabel();
    }
}

// The brush in winter: blades painted back into a bare patch bend under the snow as the field
// grown with them bends in grass render. Before, the live physics kept each slot's load from
// when the field was weighed, so they stood upright in the snow (both devices).
TEST_F(LivePhysicsTest, BladesTheBrushPaintsBackBendUnderTheSnow) {
    const core::LoadedProject loaded = snowyPlane(60.0f);
    const auto field = renderedField(loaded);
    ASSERT_TRUE(field);
    const std::vector<core::Blade>& rest = field->rest;
    core::SceneSimulation& rendered = *field->simulation;
    const float openX = -1.4f;
    for (const auto device : {editor::PhysicsDevice::Cpu, editor::PhysicsDevice::Gpu}) {
        // The field weighed with a bare patch (as when the eraser ran before the snow came).
        auto grown = editor::growField(loaded, true);
        ASSERT_TRUE(grown.ok()) << grown.error().str();
        paintDensityDab(*grown->scene, core::BrushMode::Subtract, openX);
        grown->physics->snowLoadPerMetre.clear();
        core::prepareSnowLoads(*grown->physics, *grown->scene);
        auto live = editor::bringUpLive(std::move(*grown), {}, device);
        ASSERT_TRUE(live.ok()) << live.error().str();
        // The brush paints the blades back: the field is the project's again, slot for slot.
        const core::RegrowReport back = paintDensityDab(*live->scene, core::BrushMode::Add, openX);
        ASSERT_FALSE(back.patches.empty());
        ASSERT_EQ(live->scene->layers[0].patched.blades, rest);
        live->renderer->uploadRegrown(0, back);
        live->physics->regrown(0, *live->scene, back.patches);
        for (double t = 0.1; t <= 1.0 + 1e-9; t += 0.1)
            live->physics->advanceTo(t, 1000);
        while (rendered.stepsDone() < live->physics->steps)
            rendered.step();
        ASSERT_EQ(rendered.stepsDone(), live->physics->steps);
        const std::vector<core::Blade> shown = rendererBlades(*live, 0);
        const std::vector<core::Blade>& reference = field->scene.layers[0].patched.blades;
        float worst = 0.0f;
        for (std::size_t i = 0; i < rest.size(); ++i)
            if (rest[i].h() > 0.0f)
                worst =
                    std::max(worst, glm::length(shown[i].v2() - reference[i].v2()) / rest[i].h());
        std::printf("[ live physics ] %s, blades painted back under snow: %.3g h from the render\n",
                    live->physics->deviceLabel().c_str(), double(worst));
        EXPECT_LT(worst, 1e-3f) << live->physics->deviceLabel();  // the CPU/GPU tolerance
    }
}

// A frame's steps stop once their wall-time budget is spent (one step at least), and what
// they could not step is said as dropped; without a budget the step cap alone stops them.
TEST_F(LivePhysicsTest, AFramesStepsStopAtTheirBudget) {
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/windy");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    editor::Live live = liveOn(*loaded, editor::PhysicsDevice::Cpu);
    editor::LivePhysics& physics = *live.physics;
    const double dt = physics.scene.params.dtS;
    // A budget spent by any step: one step, the rest of the second dropped.
    const double dropped = physics.advanceTo(1.0, 1000, 1e-9);
    EXPECT_EQ(physics.computedSteps, 1u);
    EXPECT_NEAR(dropped, 1.0 - dt, dt);
    // No budget: up to the cap.
    physics.advanceTo(2.0, 5);
    EXPECT_EQ(physics.computedSteps, 6u);
    // A budget no few steps spend: all the way to the clock.
    const std::size_t before = physics.computedSteps;
    EXPECT_EQ(physics.advanceTo(physics.timeS() + 10.5 * dt, 1000, 60000.0), 0.0);
    EXPECT_EQ(physics.computedSteps - before, 10u);
}

TEST_F(LivePhysicsTest, AutoPicksTheCpuOnSoftwareGlAndTheGpuElsewhere) {
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/windy");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    editor::Live live = liveOn(*loaded, editor::PhysicsDevice::Auto);
    ASSERT_TRUE(live.physics);
    EXPECT_EQ(live.physics->cpu.has_value(), gl::isSoftwareRenderer());
    EXPECT_EQ(live.physics->gpu.has_value(), !gl::isSoftwareRenderer());
}

}  // namespace
}  // namespace grass::test
