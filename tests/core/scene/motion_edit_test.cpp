// Edits that move only what moves a field (core/scene/motion_edit.h), and the packings a caller
// keeps to build the physics of such an edit again without reading a file
// (ColliderPackings, core/scene/scene_physics.h).
#include "scene/motion_edit.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/scene_physics.h"
#include "support/gltf_writer.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

Project windAndBall() {
    LoadedProject loaded = test::planeFieldProject({2.0f, 2, 50.0f, 0.3f, 0.5f});
    test::addBall(loaded, {0.0f, 0.5f, 0.0f}, 0.4f);
    loaded.project.wind.push_back(WindDesc{});
    return loaded.project;
}

TEST(MotionEdit, MovingOrResizingWindAndCollidersLeavesTheFieldAsItIs) {
    const Project before = windAndBall();
    EXPECT_TRUE(onlyMotionChanged(before, before));
    Project moved = before;
    moved.colliders[0].position.x += 0.7f;
    moved.colliders[0].radiusM = 0.9f;
    moved.colliders[0].path = {{0.0f, {0.0f, 0.5f, 0.0f}}, {2.0f, {1.0f, 0.5f, 0.0f}}};
    moved.colliders[0].color = glm::vec3(0.2f);
    moved.colliders[0].name = "boulder";
    moved.wind[0].source.strength *= 3.0f;
    moved.wind.push_back(WindDesc{});  // a wind source added
    EXPECT_TRUE(onlyMotionChanged(before, moved));
    Project windless = before;
    windless.wind.clear();
    EXPECT_TRUE(onlyMotionChanged(before, windless));
}

TEST(MotionEdit, CollidersAddedDeletedOrRemadeAreMotionEditsWithOtherProps) {
    const Project before = windAndBall();
    Project moved = before;
    moved.colliders[0].position.x += 0.7f;
    moved.colliders[0].radiusM = 0.9f;
    EXPECT_TRUE(sameProps(before.colliders, moved.colliders));
    Project added = before;
    added.colliders.push_back(added.colliders[0]);  // another prop to draw
    EXPECT_TRUE(onlyMotionChanged(before, added));
    EXPECT_FALSE(sameProps(before.colliders, added.colliders));
    Project deleted = before;
    deleted.colliders.clear();
    EXPECT_TRUE(onlyMotionChanged(before, deleted));
    EXPECT_FALSE(sameProps(before.colliders, deleted.colliders));
    Project mesh = before;
    mesh.colliders[0].shape = ColliderShape::Mesh;
    mesh.colliders[0].file = "rock.glb";
    EXPECT_TRUE(onlyMotionChanged(before, mesh));
    EXPECT_FALSE(sameProps(before.colliders, mesh.colliders));
    Project packing = mesh;
    packing.colliders[0].sphereCount = 64;
    EXPECT_FALSE(sameProps(mesh.colliders, packing.colliders));
}

TEST(MotionEdit, WhatTheFieldIsGrownFromIsNoMotionEdit) {
    const Project before = windAndBall();
    Project denser = before;
    denser.colliders[0].position.x += 0.7f;
    denser.layers[0].scatter.density *= 2.0f;
    EXPECT_FALSE(onlyMotionChanged(before, denser));
    Project gravity = before;
    gravity.physics.gravity.w = 3.0f;  // placement rules measure slopes against it
    EXPECT_FALSE(onlyMotionChanged(before, gravity));
    Project snowy = before;
    snowy.snow.enabled = 1u;
    EXPECT_FALSE(onlyMotionChanged(before, snowy));
}

// A quality preset changes how the physics steps (draft 1/30 s substeps, balanced 1/60, high
// 1/240, one AO kernel for all three): the field is the same, and the live physics follows it.
// Before, each such choice grew the whole field again and its blades restarted from rest.
TEST(MotionEdit, HowThePhysicsStepsIsAMotionEdit) {
    const Project before = windAndBall();
    Project stepped = before;
    stepped.physics.maxSubstepS = 1.0f / 240.0f;
    stepped.physics.maxSubsteps = 4;
    stepped.physics.dtS = 1.0f / 30.0f;
    stepped.physics.etaDecayPerS = 0.2f;
    stepped.physics.crushedRecoveryFloor = 0.2f;
    EXPECT_TRUE(onlyMotionChanged(before, stepped));
    Project down = stepped;
    down.physics.gravityMode = GravityMode::Centre;  // the field leans another way as it grows
    EXPECT_FALSE(onlyMotionChanged(before, down));
}

TEST(MotionEdit, PlacementFollowsCollidersOnlyWhereALayerClearsTheGroundUnderThem) {
    Project project = windAndBall();
    EXPECT_FALSE(placementFollowsColliders(project));
    project.layers[0].rules.clearanceM = 0.1f;  // clearance around named parts only
    EXPECT_FALSE(placementFollowsColliders(project));
    project.layers.push_back(project.layers[0]);
    project.layers[1].rules.clearColliders = true;
    EXPECT_TRUE(placementFollowsColliders(project));
}

// The physics of a moved mesh collider built with the packings of an earlier build is the
// physics built afresh, sphere for sphere and bound for bound, and reads neither the mesh nor
// the cache: with both files gone it still builds.
TEST(MotionEdit, KeptPackingsBuildAMovedMeshColliderWithoutItsFiles) {
    const std::filesystem::path dir = test::scratchDir("motion_edit_packings");
    test::writeGltf(dir / "rock.gltf", test::singleMeshAsset(test::boxPrimitive(
                                           {-0.3f, 0.0f, -0.2f}, {0.3f, 0.4f, 0.2f})));
    LoadedProject loaded = test::planeFieldProject({2.0f, 2, 50.0f, 0.3f, 0.5f}, dir);
    ColliderDesc rock;
    rock.name = "rock";
    rock.shape = ColliderShape::Mesh;
    rock.file = "rock.gltf";
    rock.sphereCount = 24;
    loaded.project.colliders = {rock};

    ColliderPackings packings;
    auto first = buildScenePhysics(loaded, glm::dvec3(0.0), &packings);
    ASSERT_TRUE(first.ok()) << first.error().str();
    ASSERT_EQ(packings.byFile.size(), 1u);
    EXPECT_FALSE(first->notes.empty());  // what the packing did is said once

    LoadedProject moved = loaded;
    moved.project.colliders[0].position = {0.4f, -0.1f, 0.3f};
    moved.project.colliders[0].scale = 1.7f;
    moved.project.colliders[0].path = {{0.0f, {0.4f, -0.1f, 0.3f}}, {1.0f, {-0.4f, 0.0f, 0.2f}}};
    auto fresh = buildScenePhysics(moved);
    ASSERT_TRUE(fresh.ok()) << fresh.error().str();

    std::filesystem::remove(dir / "rock.gltf");
    std::filesystem::remove_all(dir / ".grass-cache");
    EXPECT_FALSE(buildScenePhysics(moved).ok()) << "the files are gone";
    auto kept = buildScenePhysics(moved, glm::dvec3(0.0), &packings);
    ASSERT_TRUE(kept.ok()) << kept.error().str();
    EXPECT_TRUE(kept->notes.empty());
    ASSERT_EQ(kept->colliders.size(), fresh->colliders.size());
    EXPECT_TRUE(kept->colliders == fresh->colliders);
    EXPECT_NE(kept->colliders, first->colliders);
}

}  // namespace
}  // namespace grass::core
