// Incremental re-growth on the GPU (issue 6): after a brush stroke, core::regrowLayerRegion
// changes a few patches and SceneRenderer::uploadRegrown re-uploads only those; the live
// renderer must then draw exactly what a renderer built fresh from the repainted scene draws,
// for the blades, the stem sets and the billboards (which follow the layers' maps, issue 30
// item 3).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "maps/brush.h"
#include "maps/texel_surface.h"
#include "render/scene_renderer.h"
#include "support/image_compare.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

constexpr int SIDE = 96;

using RegrowGlTest = GlTest;

core::OrbitCamera topCamera() {
    core::OrbitCamera camera;
    camera.target = glm::vec3(0.0f);
    camera.distance = 2.4f;
    camera.pitchRad = 1.0f;
    camera.nearPlane = 0.05f;
    camera.farPlane = 20.0f;
    return camera;
}

std::vector<std::uint8_t> draw(render::SceneRenderer& renderer, core::GrassTechnique technique) {
    gl::Framebuffer framebuffer(SIDE, SIDE, 4);
    render::RenderOptions options;
    options.geometry = render::GeometryPath::Strips;
    options.technique = technique;
    renderer.render(topCamera(), SIDE, SIDE, framebuffer, options);
    return framebuffer.readPixels().pixels;
}

TEST_F(RegrowGlTest, UploadingRegrownPatchesDrawsWhatAFreshRendererDraws) {
    core::LoadedProject loaded = planeFieldProject({1.6f, 4, 300.0f, 0.15f, 0.25f}, sourceDir());
    core::GrassLayer& layer = loaded.project.layers.front();
    layer.growth.enabled = true;
    layer.mapResolution = {32, 32};
    loaded.project.render.patchSize = 32;  // ~30 patches, so a stroke re-grows a part of them
    auto built = core::buildScene(loaded);
    ASSERT_TRUE(built.ok()) << built.error().str();
    core::Scene scene = std::move(*built);
    core::LayerField& field = scene.layers.front();
    // Maps start absent (1 everywhere); painting needs real texels.
    field.source.maps.density = core::makeConstantMap(32, 32, 1.0f);
    field.source.maps.soil = core::makeConstantMap(32, 32, 1.0f);

    auto live = render::SceneRenderer::create(scene);
    ASSERT_TRUE(live.ok()) << live.error().str();
    const auto bladesBefore = draw(**live, core::GrassTechnique::Blades);
    draw(**live, core::GrassTechnique::Growth);  // uploads the stem sets before the paint
    const auto billboardsBefore = draw(**live, core::GrassTechnique::Billboards);

    // Clear a path of density and poison the soil across the middle of the field.
    const core::TexelSurface surface(scene.mesh, 32, 32);
    core::BrushSettings brush;
    brush.radiusM = 0.25f;
    brush.strength = 1.0f;
    brush.mode = core::BrushMode::Set;
    brush.setValue = 0.0f;
    const std::vector<glm::vec3> stroke{{-0.6f, 0.0f, 0.0f}, {0.6f, 0.0f, 0.2f}};
    const core::PaintRecord density =
        core::paintStroke(field.source.maps.density, surface, brush, stroke);
    const core::PaintRecord soil = core::paintStroke(field.source.maps.soil, surface, brush, stroke);
    ASSERT_FALSE(density.empty());
    core::Bounds touched = density.touchedBounds;
    touched.min = glm::min(touched.min, soil.touchedBounds.min);
    touched.max = glm::max(touched.max, soil.touchedBounds.max);
    const std::size_t liveBefore = field.liveBlades;
    auto report = core::regrowLayerRegion(field, touched, 1.6f / 32.0f, loaded.project.lighting);
    ASSERT_TRUE(report.ok()) << report.error().str();
    EXPECT_LT(field.liveBlades, liveBefore);
    EXPECT_LT(report->patches.size(), field.patched.patches.size());
    (*live)->uploadRegrown(0, *report);

    // A fresh renderer draws the scene's billboards as a rebuild would make them follow the maps.
    core::refreshBillboards(scene);
    auto fresh = render::SceneRenderer::create(scene);
    ASSERT_TRUE(fresh.ok()) << fresh.error().str();
    for (const auto technique : {core::GrassTechnique::Blades, core::GrassTechnique::Growth,
                                 core::GrassTechnique::Billboards}) {
        SCOPED_TRACE(std::string(core::grassTechniqueName(technique)));
        const auto fromLive = draw(**live, technique);
        const auto fromFresh = draw(**fresh, technique);
        const ImageDifference same = compareImages(fromLive, fromFresh, 0);
        EXPECT_EQ(same.maxChannel, 0) << "the uploaded patches must match a fresh upload";
    }
    // And the paint shows: the path is bare now.
    const ImageDifference painted =
        compareImages(draw(**live, core::GrassTechnique::Blades), bladesBefore, 24);
    std::printf("[ regrow ] %zu of %zu patches re-grown, %zu blades re-baked; %.1f %% of the "
                "pixels changed\n",
                report->patches.size(), field.patched.patches.size(), report->rebakedBlades,
                100.0 * painted.differingShare);
    EXPECT_GT(painted.differingShare, 0.02);
    // The billboards lost the path too. The project's technique is blades, so the scene kept them
    // unplaced and each renderer placed its own on its first billboard frame
    // (core::placedBillboards); placed again here, they count what the renderers drew.
    const ImageDifference farPainted = compareImages(
        draw(**live, core::GrassTechnique::Billboards), billboardsBefore, 24);
    ASSERT_TRUE(scene.billboards.unplaced.has_value());
    const auto billboards = core::placedBillboards(scene);
    ASSERT_TRUE(billboards.ok()) << billboards.error().str();
    std::printf("[ regrow ] billboards: %zu of %zu placed live; %.1f %% of the pixels changed\n",
                billboards->objects.size(), billboards->placed.size(),
                100.0 * farPainted.differingShare);
    EXPECT_LT(billboards->objects.size(), billboards->placed.size());
    EXPECT_GT(farPainted.differingShare, 0.02);
}

// Billboards too many to place (10 million asked for by the billboard density) for a field
// drawn by blades: the scene keeps them unplaced, and a renderer switched to billboards draws
// none and says why once, for the status bar (before, only on stderr).
// The editor's re-grow after an edit of the layers makes a renderer for the new field on the same
// surface (editor/app/live_scene.h): it shares the surface mesh already on the GPU instead of
// uploading it again, and draws what a renderer of its own draws, also once the renderer it
// shared with is gone.
TEST_F(RegrowGlTest, ARendererOnTheSameSurfaceSharesItsMeshAndDrawsTheSame) {
    core::LoadedProject loaded = planeFieldProject({1.6f, 4, 300.0f, 0.15f, 0.25f}, sourceDir());
    auto first = core::buildScene(loaded);
    ASSERT_TRUE(first.ok()) << first.error().str();
    loaded.project.layers.front().scatter.density = 600.0f;
    auto second = core::regrowOnSameSurface(loaded, *first);
    ASSERT_TRUE(second.ok()) << second.error().str();

    auto own = render::SceneRenderer::create(*second);
    ASSERT_TRUE(own.ok()) << own.error().str();
    const auto expected = draw(**own, core::GrassTechnique::Blades);
    own->reset();
    auto before = render::SceneRenderer::create(*first);
    ASSERT_TRUE(before.ok()) << before.error().str();
    const auto firstPicture = draw(**before, core::GrassTechnique::Blades);
    auto shared = render::SceneRenderer::create(*second, before->get());
    ASSERT_TRUE(shared.ok()) << shared.error().str();
    EXPECT_EQ(&(*shared)->surfaceMesh(), &(*before)->surfaceMesh());
    EXPECT_TRUE(draw(**shared, core::GrassTechnique::Blades) == expected);
    before->reset();  // the field before the edit goes; its surface mesh stays for the new one
    const auto after = draw(**shared, core::GrassTechnique::Blades);
    EXPECT_TRUE(after == expected);
    EXPECT_GT(compareImages(after, firstPicture, 0).differingShare, 0.01)
        << "twice the density draws another picture";
}

// In the editor's window the billboards T asks for are placed on a worker (seconds on a large
// mesh) while the frames go on without them; once in, they draw what a renderer that placed them
// in the frame draws (scripts, `grass render`). 200,000 billboards here: far longer to place
// than a frame takes to ask.
TEST_F(RegrowGlTest, BillboardsPlacedInTheBackgroundDrawWhatTheFrameThatAskedDraws) {
    core::LoadedProject loaded = planeFieldProject({20.0f, 4, 2.0f}, sourceDir());
    loaded.project.billboards.placement.density = 500.0f;
    auto scene = core::buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    ASSERT_TRUE(scene->billboards.unplaced) << "a field of blades leaves them unplaced";

    auto inFrame = render::SceneRenderer::create(*scene);
    ASSERT_TRUE(inFrame.ok()) << inFrame.error().str();
    const auto expected = draw(**inFrame, core::GrassTechnique::Billboards);
    ASSERT_GT((*inFrame)->lastTimings().billboardsDrawn, 0u);
    EXPECT_FALSE((*inFrame)->placingBillboards());

    auto background = render::SceneRenderer::create(*scene);
    ASSERT_TRUE(background.ok()) << background.error().str();
    (*background)->placeBillboardsInBackground(true);
    const auto first = draw(**background, core::GrassTechnique::Billboards);
    ASSERT_TRUE((*background)->placingBillboards());
    EXPECT_EQ((*background)->lastTimings().billboardsDrawn, 0u) << "none until they are placed";
    EXPECT_GT(compareImages(first, expected, 0).differingShare, 0.01);
    for (int frame = 0; frame < 3000 && (*background)->placingBillboards(); ++frame) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        draw(**background, core::GrassTechnique::Billboards);
    }
    ASSERT_FALSE((*background)->placingBillboards()) << "still placing after 30 s";
    EXPECT_TRUE(draw(**background, core::GrassTechnique::Billboards) == expected);
    EXPECT_EQ((*background)->lastTimings().billboardsDrawn,
              (*inFrame)->lastTimings().billboardsDrawn);
}

TEST_F(RegrowGlTest, ARendererThatCannotPlaceBillboardsSaysWhyOnce) {
    core::LoadedProject loaded = planeFieldProject({100.0f, 4, 0.0f}, sourceDir());
    loaded.project.billboards.placement.density = 1000.0f;
    auto scene = core::buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    auto renderer = render::SceneRenderer::create(*scene);
    ASSERT_TRUE(renderer.ok()) << renderer.error().str();
    draw(**renderer, core::GrassTechnique::Blades);
    EXPECT_TRUE((*renderer)->takeNotes().empty()) << "blades need no billboards";
    draw(**renderer, core::GrassTechnique::Billboards);
    const std::vector<std::string> notes = (*renderer)->takeNotes();
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes.front().find("billboards not drawn"), std::string::npos) << notes.front();
    EXPECT_NE(notes.front().find("/billboards/density"), std::string::npos) << notes.front();
    draw(**renderer, core::GrassTechnique::Billboards);
    EXPECT_TRUE((*renderer)->takeNotes().empty()) << "said once, not every frame";
}

}  // namespace
}  // namespace grass::test
