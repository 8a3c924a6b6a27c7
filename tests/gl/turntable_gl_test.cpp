// Turntable renders (editor/render/turntable_render.h): view 0 is the plain render pixel for
// pixel, each view is what the plain render draws from that view's camera (the renderer carries
// nothing from one view to the next), and a failing sink stops the turn.
#include <gtest/gtest.h>

#include "gl_context_fixture.h"
#include "render/offscreen_render.h"
#include "scene/turntable.h"
#include "support/test_paths.h"
#include "render/turntable_render.h"

namespace grass::test {
namespace {

using TurntableTest = GlTest;

struct TinyScene {
    core::LoadedProject loaded;
    core::Scene scene;
    core::OrbitCamera camera;
    render::OffscreenRequest request;
};

// The CLI tests' tiny project (a 2 m plane, 80 blades) at its own 64 × 48 without MSAA:
// milliseconds per view on llvmpipe.
TinyScene tinyScene() {
    TinyScene tiny;
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/tiny");
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    tiny.loaded = std::move(*loaded);
    auto scene = core::buildScene(tiny.loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    tiny.scene = std::move(*scene);
    auto camera = render::projectCamera(tiny.loaded.project, "");
    EXPECT_TRUE(camera.ok());
    tiny.camera = *camera;
    tiny.request.width = tiny.loaded.project.render.width;
    tiny.request.height = tiny.loaded.project.render.height;
    tiny.request.msaaSamples = 0;
    tiny.request.frames = 1;
    tiny.request.options = render::renderOptionsFor(tiny.loaded.project, true);
    return tiny;
}

std::vector<gl::Rgba8Image> turn(const TinyScene& tiny, int frameCount) {
    std::vector<gl::Rgba8Image> images;
    auto sink = [&](int frame, const gl::Rgba8Image& image, const render::FrameTimings&,
                    double) -> Result<void> {
        EXPECT_EQ(frame, static_cast<int>(images.size()));
        images.push_back(image);
        return {};
    };
    auto turned = render::renderTurntable(tiny.scene, tiny.camera, tiny.request, frameCount, sink);
    EXPECT_TRUE(turned.ok()) << turned.error().str();
    return images;
}

gl::Rgba8Image plainRender(const TinyScene& tiny, const core::OrbitCamera& camera) {
    auto rendered = render::renderOffscreen(tiny.scene, camera, tiny.request);
    EXPECT_TRUE(rendered.ok()) << rendered.error().str();
    return rendered.ok() ? rendered->image : gl::Rgba8Image{};
}

// Exact equality, no threshold: the same scene, camera and options on the same driver draw the
// same pixels; any difference means the turn changed something besides the camera.
TEST_F(TurntableTest, FirstViewIsThePlainRenderPixelForPixel) {
    const TinyScene tiny = tinyScene();
    const std::vector<gl::Rgba8Image> views = turn(tiny, 4);
    ASSERT_EQ(views.size(), 4u);
    const gl::Rgba8Image plain = plainRender(tiny, tiny.camera);
    ASSERT_EQ(views[0].width, plain.width);
    ASSERT_EQ(views[0].height, plain.height);
    EXPECT_TRUE(views[0].pixels == plain.pixels);
    EXPECT_GT(grassPixelShare(views[0].pixels), 0.0) << "the view shows no grass at all";
}

TEST_F(TurntableTest, EachViewIsThePlainRenderFromItsOrbitCamera) {
    const TinyScene tiny = tinyScene();
    const std::vector<gl::Rgba8Image> views = turn(tiny, 4);
    ASSERT_EQ(views.size(), 4u);
    for (int k = 1; k < 4; ++k) {
        const gl::Rgba8Image plain = plainRender(tiny, core::turntableCamera(tiny.camera, k, 4));
        EXPECT_TRUE(views[static_cast<std::size_t>(k)].pixels == plain.pixels) << "view " << k;
        // The field is scattered at random, so a quarter turn must show other blades.
        EXPECT_FALSE(views[static_cast<std::size_t>(k)].pixels == views[0].pixels)
            << "view " << k << " is view 0: the camera did not turn";
    }
}

TEST_F(TurntableTest, AFailingSinkStopsTheTurnWithItsError) {
    const TinyScene tiny = tinyScene();
    int calls = 0;
    auto sink = [&](int frame, const gl::Rgba8Image&, const render::FrameTimings&,
                    double) -> Result<void> {
        ++calls;
        if (frame == 1)
            return makeError("out_0001.png", "disk full");
        return {};
    };
    auto turned = render::renderTurntable(tiny.scene, tiny.camera, tiny.request, 5, sink);
    ASSERT_FALSE(turned.ok());
    EXPECT_EQ(turned.error().str(), "out_0001.png: disk full");
    EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace grass::test
