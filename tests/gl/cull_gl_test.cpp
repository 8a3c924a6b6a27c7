// The per-blade cull pass (SPEC §6): occlusion removes what an opaque wall hides and nothing in
// front of it, culling changes the picture little while drawing far fewer blades, distance
// thinning falls with distance, and the per-test counts add up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "blade/blade.h"
#include "gl_context_fixture.h"
#include "render/offscreen_render.h"
#include "scatter/patches.h"
#include "support/image_compare.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using CullTest = GlTest;

render::CullSettings onlyTests(bool orientation, bool frustum, bool distance, bool occlusion) {
    render::CullSettings cull;
    cull.orientation = orientation;
    cull.frustum = frustum;
    cull.distance = distance;
    cull.occlusion = occlusion;
    cull.collectStats = true;
    return cull;
}

render::OffscreenResult renderWith(const core::Scene& scene, const core::OrbitCamera& camera,
                                   const render::CullSettings& cull, int size = 128) {
    render::OffscreenRequest request;
    request.width = request.height = size;
    request.frames = 1;
    request.options.cull = cull;
    auto result = render::renderOffscreen(scene, camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(*result) : render::OffscreenResult{};
}

// A 4 m × 3 m vertical wall in the plane z = 0 (the only opaque mesh) and two 16 × 16 grids of
// short blades on the floor y = 0: one in front of the wall (z in [1, 2]), one behind it
// (z in [−2, −1]). Both grids lie within x in [−1, 1], well inside the wall's silhouette.
core::Scene wallScene(std::size_t* front, std::size_t* behind) {
    core::SurfaceMeshBuilder builder;
    const glm::vec3 normal(0, 0, 1);
    const auto a = builder.addVertex({-2, 0, 0}, normal, {0, 0});
    const auto b = builder.addVertex({2, 0, 0}, normal, {1, 0});
    const auto c = builder.addVertex({2, 3, 0}, normal, {1, 1});
    const auto d = builder.addVertex({-2, 3, 0}, normal, {0, 1});
    builder.addTriangle(a, b, c);
    builder.addTriangle(a, c, d);
    core::Scene scene;
    scene.mesh = builder.take();
    std::vector<core::Blade> blades;
    for (int side = 0; side < 2; ++side)
        for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 16; ++j) {
                const float x = -1.0f + 2.0f * static_cast<float>(i) / 15.0f;
                const float z = (side == 0 ? 1.0f : -2.0f) + static_cast<float>(j) / 15.0f;
                // Width along x (theta = 0 for up = +Y is the x axis): faces the camera.
                blades.push_back(core::makeRestBlade({x, 0, z}, {0, 1, 0}, 0.3f, 0.02f, 1.0f,
                                                     0.5f * static_cast<float>(i % 3)));
            }
    *front = *behind = 256;
    core::LayerField field;
    field.name = "test";
    field.patched = core::buildPatches(blades, 32);
    field.liveBlades = blades.size();
    field.rootColor = {0.1f, 0.3f, 0.05f};
    field.tipColor = {0.4f, 0.8f, 0.2f};
    scene.layers.push_back(std::move(field));
    scene.bounds = core::Bounds{{-2, 0, -2}, {2, 3, 2}};
    return scene;
}

TEST_F(CullTest, OcclusionRemovesBladesBehindAWallAndNoneInFront) {
    std::size_t front = 0, behind = 0;
    const core::Scene scene = wallScene(&front, &behind);
    // Eye level 1 m, 6 m in front of the wall: the wall (up to 3 m) hides the far grid fully.
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0, 1, 6}, {0, 0.5f, 0}, glm::radians(45.0f));
    const auto result = renderWith(scene, camera, onlyTests(false, false, false, true));
    const render::CullStats& stats = result.lastFrame.cull;
    EXPECT_EQ(stats.bladesIn, front + behind);
    EXPECT_EQ(stats.culledOcclusion, behind);
    EXPECT_EQ(stats.drawn, front);

    // Seen from high above (20 m; the sight line to the far grid clears the wall's top at
    // 8.6 m), nothing is hidden.
    const core::OrbitCamera above =
        core::OrbitCamera::lookAt({0, 20, 2}, {0, 0, 0}, glm::radians(45.0f));
    const auto open = renderWith(scene, above, onlyTests(false, false, false, true));
    EXPECT_EQ(open.lastFrame.cull.culledOcclusion, 0u);
    EXPECT_EQ(open.lastFrame.cull.drawn, front + behind);
}

// An 8 m × 8 m plane of ~19k blades, seen from 0.8 m above one edge looking across it: half
// the field is behind or beside the camera.
core::Scene fieldScene() {
    const core::LoadedProject loaded =
        planeFieldProject({8.0f, 8, 300.0f, 0.3f, 0.5f}, sourceDir());
    auto scene = core::buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return std::move(*scene);
}

core::OrbitCamera acrossField() {
    return core::OrbitCamera::lookAt({1.0f, 0.8f, 1.5f}, {-2.0f, 0.0f, -2.5f}, glm::radians(50.0f));
}

TEST_F(CullTest, CulledImageStaysCloseWhileDrawingFewerBlades) {
    const core::Scene scene = fieldScene();
    ASSERT_LE(scene.totalBlades(), 20000u);
    render::CullSettings all = onlyTests(true, true, true, true);
    all.maxDistanceM = 30.0f;
    const auto culled = renderWith(scene, acrossField(), all, 256);
    const auto full = renderWith(scene, acrossField(), onlyTests(false, false, false, false), 256);
    ASSERT_EQ(culled.image.pixels.size(), full.image.pixels.size());
    ASSERT_FALSE(full.image.pixels.empty());
    EXPECT_EQ(full.lastFrame.cull.drawn, scene.totalBlades());
    const double drawnShare =
        static_cast<double>(culled.lastFrame.cull.drawn) / static_cast<double>(scene.totalBlades());
    double sum = 0.0;
    std::size_t off = 0;
    const auto& a = culled.image.pixels;
    const auto& b = full.image.pixels;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        int worst = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int diff = std::abs(int(a[i + c]) - int(b[i + c]));
            sum += diff;
            worst = std::max(worst, diff);
        }
        if (worst > 16)
            ++off;
    }
    const double pixels = static_cast<double>(a.size() / 4);
    const double mean = sum / (pixels * 3.0);
    const double offShare = static_cast<double>(off) / pixels;
    RecordProperty("drawn_share", std::to_string(drawnShare));
    RecordProperty("mean_abs_diff", std::to_string(mean));
    RecordProperty("off_share", std::to_string(offShare));
    const render::CullStats& stats = culled.lastFrame.cull;
    std::printf(
        "[ cull ] %zu blades, drawn %.3f (culled: patch %zu, orientation %zu, frustum %zu, "
        "distance %zu, occlusion %zu), mean abs diff %.3f, %.4f of pixels off > 16\n",
        scene.totalBlades(), drawnShare, stats.culledPatch, stats.culledOrientation,
        stats.culledFrustum, stats.culledDistance, stats.culledOcclusion, mean, offShare);
    // Measured (llvmpipe, 256², 4× MSAA): 21 % of the blades drawn, mean 0.50/255, 1.2 % of
    // pixels off by more than 16/255. Most culled blades are off screen (no pixel changes);
    // the rest are edge-on slivers (orientation) and every few far blades (distance), which
    // change scattered thin pixels, never whole regions. Thresholds at about 3× the measured
    // difference leave room for driver changes, and are still tighter than the strip-vs-
    // tessellation test (mean 2/255, 3 % off): a cull pass that drops visible blades in bulk
    // (a wrong frustum or occlusion test) bares soil over whole regions and fails both.
    EXPECT_EQ(stats.culledOcclusion, 0u) << "grass on the visible (flat) ground is not hidden";
    EXPECT_LT(drawnShare, 0.35);
    EXPECT_LT(mean, 1.5);
    EXPECT_LT(offShare, 0.04);
    EXPECT_GT(grassPixelShare(b), 0.2) << "the test view must show grass";
}

// Occlusion by the terrain itself, read from the frame's own depth after its opaque pass (4×
// MSAA, resolved): the blades behind the hills go, and the picture stays what it is with no
// occlusion test at all. Before, a pre-pass drew the terrain a second time for this depth.
TEST_F(CullTest, HillsHideTheBladesBehindThemAndThePictureStays) {
    core::LoadedProject loaded = planeFieldProject({12.0f, 48, 60.0f, 0.2f, 0.35f}, sourceDir());
    loaded.project.mesh.procedural.shape = core::ProceduralShape::Hills;
    loaded.project.mesh.procedural.hillHeight = 2.5f;
    auto scene = core::buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    // Low over one edge, looking across the hills.
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0.0f, 1.2f, 6.5f}, {0.0f, 0.0f, 0.0f}, glm::radians(50.0f));
    const auto occluded = renderWith(*scene, camera, onlyTests(false, false, false, true), 256);
    const auto all = renderWith(*scene, camera, onlyTests(false, false, false, false), 256);
    const render::CullStats& stats = occluded.lastFrame.cull;
    const double hiddenShare =
        static_cast<double>(stats.culledOcclusion) / static_cast<double>(scene->totalBlades());
    const ImageDifference difference = compareImages(occluded.image.pixels, all.image.pixels, 16);
    std::printf("[ cull ] hills: %zu blades, %.3f hidden, mean abs diff %.4f, %.5f of pixels off\n",
                scene->totalBlades(), hiddenShare, difference.meanAbs, difference.differingShare);
    EXPECT_GT(hiddenShare, 0.05) << "the hills hide some of the field from this camera";
    EXPECT_LT(difference.meanAbs, 0.05);
    EXPECT_LT(difference.differingShare, 0.001);
}

TEST_F(CullTest, DistanceThinningFallsAsTheCameraMovesAway) {
    const core::Scene scene = fieldScene();
    render::CullSettings distance = onlyTests(false, false, true, false);
    distance.maxDistanceM = 40.0f;
    distance.distanceClasses = 8;
    std::size_t previous = scene.totalBlades();
    std::size_t first = 0;
    for (int step = 0; step < 5; ++step) {
        // Beyond the field's +z edge (z = 4) and moving further along +z: every blade's
        // horizontal distance grows, so no blade comes back.
        const float z = 5.0f + 8.0f * static_cast<float>(step);
        const core::OrbitCamera camera =
            core::OrbitCamera::lookAt({0, 2, z}, {0, 0, 0}, glm::radians(45.0f));
        const auto result = renderWith(scene, camera, distance, 64);
        const std::size_t drawn = result.lastFrame.cull.drawn;
        EXPECT_LE(drawn, previous) << "camera at z = " << z;
        if (step == 0)
            first = drawn;
        previous = drawn;
    }
    EXPECT_LT(previous, first / 2) << "from 5 m to 37 m of 40 m most blades must go";
}

// No patch pops: the thinning keeps blade i by its index class and its own distance, so a
// camera move removes the blades of one class in thin rings, scattered over the field. Then the
// largest drop between steps shrinks with the step; a pop (a patch or a whole class switching
// at once) would stay the same size however small the step. Halving the step must bring the
// largest drop well down (to about half; required: below 3/4), and the count must only fall.
std::size_t largestThinningDrop(const core::Scene& scene, float stepM) {
    render::CullSettings distance = onlyTests(false, false, true, false);
    distance.maxDistanceM = 12.0f;
    std::size_t previous = 0, largestDrop = 0;
    const int steps = static_cast<int>(std::lround(2.0f / stepM));
    for (int step = 0; step <= steps; ++step) {
        const float z = 5.0f + stepM * static_cast<float>(step);
        const core::OrbitCamera camera =
            core::OrbitCamera::lookAt({0, 2, z}, {0, 0, 0}, glm::radians(45.0f));
        const std::size_t drawn = renderWith(scene, camera, distance, 32).lastFrame.cull.drawn;
        if (step > 0) {
            EXPECT_LE(drawn, previous) << "camera at z = " << z;
            largestDrop = std::max(largestDrop, previous > drawn ? previous - drawn : 0);
        }
        previous = drawn;
    }
    return largestDrop;
}

TEST_F(CullTest, DistanceThinningShrinksWithTheStepWithoutPops) {
    const core::Scene scene = fieldScene();
    const std::size_t coarse = largestThinningDrop(scene, 0.25f);
    const std::size_t fine = largestThinningDrop(scene, 0.125f);
    std::printf("[ cull ] largest drop of drawn blades per camera step: 0.25 m %zu, 0.125 m %zu\n",
                coarse, fine);
    EXPECT_GT(coarse, 0u) << "the sweep must thin the field";
    EXPECT_LT(static_cast<double>(fine), 0.75 * static_cast<double>(coarse));
}

TEST_F(CullTest, CountsAddUp) {
    const core::Scene scene = fieldScene();
    const core::OrbitCamera cameras[] = {acrossField(), core::frameBounds(scene.bounds, 0.8f)};
    for (const auto& camera : cameras)
        for (int mask = 0; mask < 16; mask += 5) {
            render::CullSettings cull =
                onlyTests((mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0, (mask & 8) != 0);
            cull.maxDistanceM = 20.0f;
            const auto result = renderWith(scene, camera, cull, 64);
            const render::CullStats& stats = result.lastFrame.cull;
            EXPECT_EQ(stats.bladesIn, scene.totalBlades()) << "tests " << mask;
            EXPECT_EQ(stats.bladesIn, stats.drawn + stats.culledTotal()) << "tests " << mask;
            // A test that is off removes nothing.
            EXPECT_TRUE(cull.frustum || stats.culledPatch + stats.culledFrustum == 0);
            EXPECT_TRUE(cull.orientation || stats.culledOrientation == 0);
            EXPECT_TRUE(cull.distance || stats.culledDistance == 0);
            EXPECT_TRUE(cull.occlusion || stats.culledOcclusion == 0);
        }
}

}  // namespace
}  // namespace grass::test
