// Level of detail and the V fold of SPEC §7 on the GPU: the cull pass sorts blades into LODs by
// distance (counts shift monotonically towards coarse LODs as the camera backs off, and add up
// to the drawn count), coarse LODs change the picture little, and the fold gives a blade seen
// edge-on a visible V on both geometry paths.
#include <gtest/gtest.h>

#include <array>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "blade/blade.h"
#include "blade/strip_batch.h"
#include "gl/framebuffer.h"
#include "render/scene_renderer.h"
#include "gl_context_fixture.h"
#include "render/offscreen_render.h"
#include "scatter/patches.h"
#include "support/image_compare.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using LodTest = GlTest;

render::OffscreenResult renderWith(const core::Scene& scene, const core::OrbitCamera& camera,
                                   float lodDistanceM,
                                   render::GeometryPath path = render::GeometryPath::Strips,
                                   int size = 128, float lodBlend = core::LOD_BLEND) {
    render::OffscreenRequest request;
    request.width = request.height = size;
    request.frames = 1;
    request.options.geometry = path;
    request.options.cull.orientation = request.options.cull.distance = false;
    request.options.cull.occlusion = false;
    request.options.cull.collectStats = true;
    request.options.cull.lodDistanceM = lodDistanceM;
    request.options.lodBlend = lodBlend;
    auto result = render::renderOffscreen(scene, camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(*result) : render::OffscreenResult{};
}

// Mean |a − b| over RGB, in levels (the golden-image metric).
double meanAbsDifference(const gl::Rgba8Image& a, const gl::Rgba8Image& b) {
    return compareImages(a.pixels, b.pixels, 48).meanAbs;
}

core::OrbitCamera cameraAt(float distance) {
    core::OrbitCamera camera;
    camera.target = glm::vec3(0.0f, 0.2f, 0.0f);
    camera.distance = distance;
    camera.pitchRad = 0.35f;
    camera.nearPlane = 0.05f;
    camera.farPlane = 200.0f;
    return camera;
}

TEST_F(LodTest, BladesMoveToCoarserLodsAsTheCameraBacksOff) {
    auto scene = core::buildScene(planeFieldProject({6.0f, 2, 60.0f, 0.3f, 0.5f}, sourceDir()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    std::size_t previousFull = SIZE_MAX;
    double previousQuarter = 0.0;
    for (float distance : {2.0f, 4.0f, 8.0f, 16.0f, 32.0f}) {
        const auto frame = renderWith(*scene, cameraAt(distance), 2.0f);
        const render::CullStats& stats = frame.lastFrame.cull;
        ASSERT_GT(stats.drawn, 0u) << distance;
        EXPECT_EQ(stats.drawnPerLod[0] + stats.drawnPerLod[1] + stats.drawnPerLod[2], stats.drawn);
        const auto drawn = static_cast<double>(stats.drawn);
        const double full = static_cast<double>(stats.drawnPerLod[0]) / drawn;
        const double quarter = static_cast<double>(stats.drawnPerLod[2]) / drawn;
        std::printf("[ lod ] camera %.0f m: full %zu, half %zu, quarter %zu\n", distance,
                    stats.drawnPerLod[0], stats.drawnPerLod[1], stats.drawnPerLod[2]);
        EXPECT_LE(stats.drawnPerLod[0], previousFull) << distance;
        EXPECT_GE(quarter, previousQuarter) << distance;
        previousFull = stats.drawnPerLod[0];
        previousQuarter = quarter;
        if (distance >= 32.0f) {
            EXPECT_GT(quarter, 0.9) << "32 m away every blade is beyond 3 × 2 m";
        }
        if (distance <= 2.0f) {
            EXPECT_GT(full, 0.05) << "blades under the camera stand within 2 m";
        }
    }
    // LOD off: everything at full detail.
    const auto off = renderWith(*scene, cameraAt(32.0f), 0.0f);
    EXPECT_EQ(off.lastFrame.cull.drawnPerLod[0], off.lastFrame.cull.drawn);
}

// The blades in a LOD's morph band are listed and drawn apart (core::lodBlending): the cull
// counts them in the LOD's blending commands, the last LOD never blends, a hard switch lists
// none, and splitting them off draws the same blades and the same picture as drawing every
// blade without the split would (a hard switch differs from the blend only inside the bands).
TEST_F(LodTest, BladesInAMorphBandAreDrawnApartWithTheBlend) {
    auto scene = core::buildScene(planeFieldProject({8.0f, 2, 80.0f, 0.3f, 0.5f}, sourceDir()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    // 2.5 m back: the 2 m LOD distance's bands ([1.5, 2) m and [4, 6) m) both lie in view.
    const core::OrbitCamera camera = cameraAt(2.5f);
    for (const auto path : {render::GeometryPath::Strips, render::GeometryPath::Tessellation}) {
        const auto blended = renderWith(*scene, camera, 2.0f, path, 128, 0.25f);
        const auto hard = renderWith(*scene, camera, 2.0f, path, 128, 0.0f);
        const render::CullStats& b = blended.lastFrame.cull;
        const render::CullStats& h = hard.lastFrame.cull;
        std::printf("[ lod ] blending in the bands: %zu of %zu (LOD 0), %zu of %zu (LOD 1)\n",
                    b.blendingPerLod[0], b.drawnPerLod[0], b.blendingPerLod[1], b.drawnPerLod[1]);
        for (int lod = 0; lod < 2; ++lod) {
            EXPECT_GT(b.blendingPerLod[lod], 0u) << lod;
            EXPECT_LT(b.blendingPerLod[lod], b.drawnPerLod[lod]) << lod << ": a quarter band";
        }
        EXPECT_EQ(b.blendingPerLod[2], 0u) << "the last LOD has nothing to blend into";
        EXPECT_EQ(b.drawnPerLod, h.drawnPerLod) << "the same blades at the same LODs";
        EXPECT_EQ(h.blendingPerLod, (std::array<std::size_t, core::LOD_COUNT>{}));
        // Every blade is drawn once: drawn twice or lost, the blended picture would differ from
        // the hard switch's far more than the blend moves blades inside the bands.
        const double difference = meanAbsDifference(blended.image, hard.image);
        EXPECT_GT(difference, 0.0) << "the blend moved nothing";
        EXPECT_LT(difference, 1.0);
    }
}

// The strips are drawn 64 blades to an instance (core/blade/strip_batch.h): the cull counts each
// class's batches as it lists its blades, so every class of a field whose counts are no multiple
// of 64 has ceil(blades / 64) batches, and the batches draw what the tessellation path draws
// (in batches of 64 single-vertex patches) at every LOD, blending or not: a lost or doubled
// blade, a batch of the wrong LOD's index list, a batch missing on either path or a partial batch
// drawing its padding would change the picture.
TEST_F(LodTest, StripBatchesDrawEveryListedBladeOnce) {
    auto scene = core::buildScene(planeFieldProject({8.0f, 2, 80.0f, 0.3f, 0.5f}, sourceDir()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const core::OrbitCamera camera = cameraAt(2.5f);
    const auto strips = renderWith(*scene, camera, 2.0f, render::GeometryPath::Strips, 128);
    const auto tess = renderWith(*scene, camera, 2.0f, render::GeometryPath::Tessellation, 128);
    const render::CullStats& stats = strips.lastFrame.cull;
    for (int lod = 0; lod < core::LOD_COUNT; ++lod) {
        const std::size_t blending = stats.blendingPerLod[std::size_t(lod)];
        const std::size_t before = stats.drawnPerLod[std::size_t(lod)] - blending;
        std::printf("[ lod ] LOD %d: %zu blades in %zu batches, %zu blending in %zu\n", lod,
                    before, stats.stripBatches[std::size_t(lod)], blending,
                    stats.stripBatches[std::size_t(core::LOD_COUNT + lod)]);
        EXPECT_EQ(stats.stripBatches[std::size_t(lod)],
                  core::stripBatches(std::uint32_t(before)))
            << lod;
        EXPECT_EQ(stats.stripBatches[std::size_t(core::LOD_COUNT + lod)],
                  core::stripBatches(std::uint32_t(blending)))
            << lod;
    }
    EXPECT_GT(stats.stripBatches[1], 1u) << "several batches, or the test shows little";
    EXPECT_GT(stats.stripBatches[2], 0u) << "the quarter LOD in view";
    const ImageDifference difference = compareImages(strips.image.pixels, tess.image.pixels, 48);
    std::printf("[ lod ] batched strips vs tessellation: %.4f of pixels differ, mean %.3f\n",
                difference.differingShare, difference.meanAbs);
    EXPECT_LT(difference.differingShare, 0.005);
    EXPECT_LT(difference.meanAbs, 0.5);
    EXPECT_EQ(stats.drawnPerLod, tess.lastFrame.cull.drawnPerLod);
}

// The last batch of a class is partly padding, on both paths (64 blades of strips or 64
// patches an instance): its blades past the survivors must draw nothing, whatever the visible
// list holds beyond them. One renderer draws a near view first (long lists), then a far one,
// whose shorter lists leave the near view's entries behind them: the far picture must be a fresh
// renderer's (an extra blade of the stale entries would show).
TEST_F(LodTest, ABatchsPaddingDrawsNothing) {
    core::LoadedProject loaded = planeFieldProject({8.0f, 2, 80.0f, 0.3f, 0.5f}, sourceDir());
    auto scene = core::buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    for (const auto path : {render::GeometryPath::Strips, render::GeometryPath::Tessellation}) {
        SCOPED_TRACE(render::geometryPathLabel(path));
        render::RenderOptions options = render::renderOptionsFor(loaded.project, true);
        options.geometry = path;
        options.cull.orientation = options.cull.distance = options.cull.occlusion = false;
        options.cull.collectStats = true;
        options.cull.lodDistanceM = 2.0f;
        const auto draw = [&](render::SceneRenderer& renderer, const core::OrbitCamera& camera) {
            gl::Framebuffer framebuffer(128, 128, 0);
            renderer.render(camera, 128, 128, framebuffer, options);
            return std::make_pair(framebuffer.readPixels(), renderer.lastTimings().cull);
        };
        auto reused = render::SceneRenderer::create(*scene);
        auto fresh = render::SceneRenderer::create(*scene);
        ASSERT_TRUE(reused.ok() && fresh.ok());
        const auto [nearImage, nearStats] = draw(**reused, cameraAt(1.0f));
        const auto [farImage, farStats] = draw(**reused, cameraAt(2.5f));
        const auto [freshImage, freshStats] = draw(**fresh, cameraAt(2.5f));
        // Stale entries lie in a padding where a class's near list outran a far list that ends
        // inside a batch.
        int classesWithStalePadding = 0;
        for (int lod = 0; lod < core::LOD_COUNT; ++lod) {
            const std::size_t l = std::size_t(lod);
            const std::array<std::size_t, 2> nearCounts{
                nearStats.drawnPerLod[l] - nearStats.blendingPerLod[l],
                nearStats.blendingPerLod[l]};
            const std::array<std::size_t, 2> farCounts{
                farStats.drawnPerLod[l] - farStats.blendingPerLod[l], farStats.blendingPerLod[l]};
            for (std::size_t c = 0; c < 2; ++c) {
                std::printf("[ lod ] %s LOD %d%s: near view %zu blades, far view %zu\n",
                            render::geometryPathLabel(path), lod, c ? " blending" : "",
                            nearCounts[c], farCounts[c]);
                if (nearCounts[c] > farCounts[c] && farCounts[c] % core::STRIP_BATCH_BLADES != 0)
                    ++classesWithStalePadding;
            }
        }
        ASSERT_GT(classesWithStalePadding, 0) << "the near view must leave entries in a padding";
        EXPECT_EQ(farStats.drawnPerLod, freshStats.drawnPerLod);
        const ImageDifference difference = compareImages(farImage.pixels, freshImage.pixels, 0);
        EXPECT_EQ(difference.differingShare, 0.0) << "mean " << difference.meanAbs;
    }
}

// The default LOD distance draws nearly what full detail draws: coarse segments only straighten
// the curve between vertices of blades that are a few pixels tall. Tolerance: a mean absolute
// difference of 2 levels of 255 per channel (the culling test allows 4 for thinning a field);
// a wrong segment count (e.g. LOD 2 everywhere at close range) measures above it.
TEST_F(LodTest, DefaultLodChangesThePictureLittle) {
    auto scene = core::buildScene(planeFieldProject({8.0f, 2, 80.0f, 0.3f, 0.5f}, sourceDir()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const core::OrbitCamera camera = cameraAt(9.0f);
    const auto full = renderWith(*scene, camera, 0.0f, render::GeometryPath::Strips, 192);
    const auto lod = renderWith(*scene, camera, render::CullSettings{}.lodDistanceM,
                                render::GeometryPath::Strips, 192);
    const auto coarse = renderWith(*scene, camera, 0.01f, render::GeometryPath::Strips, 192);
    const double lodDiff = meanAbsDifference(full.image, lod.image);
    const double coarseDiff = meanAbsDifference(full.image, coarse.image);
    std::printf("[ lod ] mean abs diff vs full detail: default LOD %.3f, all quarter %.3f\n",
                lodDiff, coarseDiff);
    EXPECT_LT(lodDiff, 2.0);
    EXPECT_GT(lod.lastFrame.cull.drawnPerLod[1] + lod.lastFrame.cull.drawnPerLod[2], 0u);
    EXPECT_GT(coarseDiff, lodDiff);
}

// One wide quad blade seen exactly along its width direction: a flat blade would be a line a
// pixel wide; the V fold stands the midrib w/2 off the edges at the root, so the blade covers
// a wedge. Both paths draw it, and both leave it out at the far LODs.
TEST_F(LodTest, FoldShowsWhenABladeIsSeenEdgeOn) {
    core::Scene scene;
    core::SurfaceMeshBuilder builder;
    scene.mesh = builder.take();
    const std::vector<core::Blade> blades{
        core::makeRestBlade({0, 0, 0}, {0, 1, 0}, 0.5f, 0.08f, 1.0f, 0.0f)};
    core::LayerField field;
    field.name = "fold";
    field.patched = core::buildPatches(blades, 32);
    field.liveBlades = 1;
    field.rootColor = field.tipColor = {0.2f, 0.8f, 0.1f};
    field.shape = core::BladeShape::Quad;
    scene.layers.push_back(std::move(field));
    scene.bounds = core::Bounds{{-1, 0, -1}, {1, 1, 1}};
    // Look along the blade's width direction (theta = 0 about +Y), level with its middle.
    const glm::vec3 width = core::widthDirection({0.0f, 1.0f, 0.0f}, 0.0f);
    const glm::vec3 target(0.0f, 0.25f, 0.0f);
    core::OrbitCamera camera = core::OrbitCamera::lookAt(target + 1.2f * width, target, 0.7853982f);
    camera.nearPlane = 0.05f;
    camera.farPlane = 10.0f;
    const glm::vec3 toBlade = glm::normalize(target - camera.position());
    ASSERT_GT(std::abs(glm::dot(toBlade, width)), 0.999f) << "the camera must look along the width";
    for (auto path : {render::GeometryPath::Strips, render::GeometryPath::Tessellation}) {
        const auto frame = renderWith(scene, camera, 0.0f, path);
        const double share = grassPixelShare(frame.image.pixels);
        std::printf("[ fold ] %s: edge-on blade covers %.4f of the image\n",
                    render::geometryPathLabel(path), share);
        // The wedge: 0.04 m deep at the root tapering to 0 at the tip, 0.5 m tall, seen from
        // 1.2 m with a 45° field of view: about 0.5·0.04·0.5 / (2·1.2·tan 22.5°)² ≈ 1 % of the
        // image. A flat blade covers the one-pixel line: < 0.5 %.
        EXPECT_GT(share, 0.006) << render::geometryPathLabel(path);
        // Beyond FOLDED_LODS the blade is drawn by its two edges alone (a far blade is a few
        // pixels wide, its fold invisible): seen edge-on it is the one-pixel line.
        const auto far = renderWith(scene, camera, 0.01f, path);
        ASSERT_EQ(far.lastFrame.cull.drawnPerLod[2], 1u);
        const double farShare = grassPixelShare(far.image.pixels);
        std::printf("[ fold ] %s, quarter segments: edge-on blade covers %.4f of the image\n",
                    render::geometryPathLabel(path), farShare);
        EXPECT_LT(farShare, 0.005) << render::geometryPathLabel(path);
    }
}

// No popping (issue 30 item 12). A patch of blades 0.15 m across, their roots 8 ± 0.075 m from
// the camera, seen through a narrow lens so they fill the image, drawn with the switch just
// beyond them and just before them (the LOD distance ±1.5 %): every blade changes LOD and
// nothing else moves. Hard
// switches change the picture by the whole difference between the two LODs (8 folded segments
// against 4 flat ones, or 4 against 2). Blended, a blade has reached the coarser surface when it
// switches, and what is left is the morph moving by 3 % of the LOD's range over its quarter-wide
// band: 6–9 % of the way between the two LODs (measured: 2–12 % of the hard change; into LOD 1
// also the change from per-pixel to per-vertex light, core::defaultPixelLitLods). Both switches (LOD 0 → 1 at d, 1 → 2 at 3d), both
// geometry paths.
TEST_F(LodTest, BladesDoNotPopWhereTheLodChanges) {
    auto scene = core::buildScene(planeFieldProject({0.15f, 2, 1600.0f, 0.3f, 0.5f}, sourceDir()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    core::OrbitCamera camera = cameraAt(8.0f);
    camera.target = glm::vec3(0.0f);  // the roots 8 m away; the blades fill the upper half
    camera.fovYRad = 0.09f;           // 0.72 m across at 8 m
    for (auto path : {render::GeometryPath::Strips, render::GeometryPath::Tessellation}) {
        for (const int switchTo : {1, 2}) {
            // The switch into LOD `switchTo` at 8 m: d = 8 m, or 3d = 8 m.
            const float d = switchTo == 1 ? 8.0f : 8.0f / 3.0f;
            double diff[2];
            for (int blended = 0; blended < 2; ++blended) {
                const float blend = blended ? core::LOD_BLEND : 0.0f;
                const auto finer = renderWith(*scene, camera, 1.015f * d, path, 192, blend);
                const auto coarser = renderWith(*scene, camera, 0.985f * d, path, 192, blend);
                EXPECT_EQ(finer.lastFrame.cull.drawnPerLod[std::size_t(switchTo - 1)],
                          finer.lastFrame.cull.drawn);
                EXPECT_EQ(coarser.lastFrame.cull.drawnPerLod[std::size_t(switchTo)],
                          coarser.lastFrame.cull.drawn);
                diff[blended] = meanAbsDifference(finer.image, coarser.image);
            }
            std::printf("[ lod ] %s, into LOD %d: mean abs change hard %.4f, blended %.4f\n",
                        render::geometryPathLabel(path), switchTo, diff[0], diff[1]);
            // The blades cover about a quarter of the image, the sky the rest: a hard switch
            // measured 0.32–0.50 over the whole image.
            EXPECT_GT(diff[0], 0.2) << "the two LODs must differ visibly for the test to mean much";
            EXPECT_LT(diff[1], 0.25 * diff[0]) << render::geometryPathLabel(path) << switchTo;
        }
    }
}

}  // namespace
}  // namespace grass::test

namespace grass::test {
namespace {

// Regression: llvmpipe drew large non-instanced patch draws wrongly (whole regions missing,
// streaks between far blades) beyond ~10k patches at level 8; the tessellation path draws 64
// patches an instance instead (core::PATCH_BATCH_BLADES). On a 20k-blade field both paths must
// draw the same image
// (the same curve and shape code; tolerance as the golden tests: 0.5 % of pixels may differ).
TEST_F(LodTest, TessellationMatchesStripsOnALargeField) {
    auto scene = core::buildScene(planeFieldProject({4.0f, 2, 1250.0f, 0.15f, 0.25f}, sourceDir()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    ASSERT_GE(scene->totalBlades(), 19000u);
    const core::OrbitCamera camera = cameraAt(4.0f);
    const auto strips = renderWith(*scene, camera, 0.0f, render::GeometryPath::Strips, 128);
    const auto tess = renderWith(*scene, camera, 0.0f, render::GeometryPath::Tessellation, 128);
    const double share =
        compareImages(strips.image.pixels, tess.image.pixels, 48).differingShare;
    std::printf("[ lod ] 20k blades, tess vs strips at 8: %.4f of pixels differ\n", share);
    EXPECT_LT(share, 0.005);
    EXPECT_EQ(tess.lastFrame.cull.drawn, strips.lastFrame.cull.drawn);
}

}  // namespace
}  // namespace grass::test
