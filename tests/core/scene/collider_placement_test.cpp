// The field after its colliders moved, where a layer clears the ground under them
// (scene/collider_placement.h): the patches whose candidates changed grow again, and the result
// is the field a fresh build with the colliders where they now stand grows.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "scene/collider_placement.h"
#include "scene/scene.h"
#include "support/plane_project.h"

namespace grass::core {
namespace {

// Two layers on a 16 m plane, hybrid (placed billboards): the first clears the ground under the
// colliders and leans among denser neighbours, the second does neither; a ball of radius 0.8 sunk
// to its centre at `ball`.
LoadedProject ballField(glm::vec3 ball) {
    LoadedProject loaded = test::planeFieldProject({16.0f, 4, 40.0f});
    GrassLayer& cleared = loaded.project.layers.front();
    cleared.rules.clearColliders = true;
    cleared.rules.clearanceM = 0.2f;
    cleared.bending.neighboursDeg = 30.0f;
    cleared.bending.neighbourRadiusM = 0.2f;
    GrassLayer other = cleared;
    other.name = "other";
    other.rules = {};
    other.bending = {};
    loaded.project.layers.push_back(other);
    loaded.project.billboards.placement.density = 20.0f;
    loaded.project.render.technique = GrassTechnique::Hybrid;
    test::addBall(loaded, ball, 0.8f);
    return loaded;
}

Scene built(const LoadedProject& loaded) {
    auto scene = buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return std::move(*scene);
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(CollidersPlacement, AMovedBallGrowsTheFieldAFreshBuildGrowsWhereItNowStands) {
    const LoadedProject before = ballField({-2.5f, 0.0f, 0.0f});
    const LoadedProject after = ballField({2.2f, 0.0f, 0.5f});
    Scene scene = built(before);
    const Scene fresh = built(after);
    ASSERT_EQ(scene.layers.size(), 2u);
    const std::vector<Blade> otherBefore = scene.layers[1].patched.blades;
    // The ball moved, as the editor's followMotion moves its prop.
    placeSceneProp(scene.props[0], after.project.colliders[0]);
    auto changed = followColliderPlacement(scene, after.project);
    ASSERT_TRUE(changed.ok()) << changed.error().str();
    ASSERT_EQ(changed->size(), 1u) << "only the layer that clears the colliders";
    EXPECT_EQ(changed->front().first, 0u);
    const std::size_t patches = scene.layers[0].patched.patches.size();
    EXPECT_GT(changed->front().second.patches.size(), 0u);
    EXPECT_LT(changed->front().second.patches.size(), patches / 3) << "a part of the field";
    EXPECT_GT(changed->front().second.bladesAddedOrRemoved, 0u);
    for (std::size_t i = 0; i < scene.layers.size(); ++i) {
        const LayerField& got = scene.layers[i];
        const LayerField& want = fresh.layers[i];
        EXPECT_TRUE(sameBits(got.patched.blades, want.patched.blades)) << "layer " << i;
        EXPECT_TRUE(sameBits(got.shading, want.shading)) << "layer " << i;
        EXPECT_TRUE(sameBits(got.wilt, want.wilt)) << "layer " << i;
        EXPECT_EQ(got.liveBlades, want.liveBlades) << "layer " << i;
        EXPECT_EQ(got.source.ruleFactors, want.source.ruleFactors) << "layer " << i;
    }
    EXPECT_TRUE(sameBits(scene.layers[1].patched.blades, otherBefore)) << "the other layer kept";
    ASSERT_EQ(scene.billboards.objects.size(), fresh.billboards.objects.size());
    for (std::size_t i = 0; i < fresh.billboards.objects.size(); ++i)
        EXPECT_EQ(scene.billboards.objects[i].centre, fresh.billboards.objects[i].centre);
    // Nothing more to follow where nothing moved.
    auto again = followColliderPlacement(scene, after.project);
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(again->empty());
}

// A field whose billboards are not placed yet (blades drawn) places them, once asked, as a
// fresh build with the ball where it now stands would.
TEST(CollidersPlacement, UnplacedBillboardsArePlacedWhereTheBallNowStands) {
    LoadedProject before = ballField({-1.5f, 0.0f, 0.0f});
    LoadedProject after = ballField({1.2f, 0.0f, 0.5f});
    before.project.render.technique = after.project.render.technique = GrassTechnique::Blades;
    Scene scene = built(before);
    Scene fresh = built(after);
    ASSERT_TRUE(scene.billboards.unplaced.has_value());
    placeSceneProp(scene.props[0], after.project.colliders[0]);
    ASSERT_TRUE(followColliderPlacement(scene, after.project).ok());
    ASSERT_TRUE(placeBillboards(scene).ok());
    ASSERT_TRUE(placeBillboards(fresh).ok());
    ASSERT_EQ(scene.billboards.objects.size(), fresh.billboards.objects.size());
    for (std::size_t i = 0; i < fresh.billboards.objects.size(); ++i)
        EXPECT_EQ(scene.billboards.objects[i].centre, fresh.billboards.objects[i].centre);
}

}  // namespace
}  // namespace grass::core
