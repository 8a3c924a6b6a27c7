// The editor's map overlay (issue 27 item 4): the terrain shows the map being painted, purple at
// 0 and yellow at 1, in its UV space, and nothing once the overlay is taken away.
#include <gtest/gtest.h>

#include "gl_context_fixture.h"
#include "gl/framebuffer.h"
#include "render/scene_renderer.h"
#include "scene/scene.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using MapOverlayTest = GlTest;

struct Shares {
    double purple = 0.0, yellow = 0.0;
};

// Of the image's pixels, the share that reads purple (blue well over green) and yellow (red and
// green well over blue): the overlay's two ends, whatever the terrain's own colour under them.
Shares overlayShares(const gl::Rgba8Image& image) {
    Shares shares;
    const std::size_t pixels = image.pixels.size() / 4;
    for (std::size_t i = 0; i < pixels; ++i) {
        const int r = image.pixels[4 * i], g = image.pixels[4 * i + 1], b = image.pixels[4 * i + 2];
        shares.purple += b > g + 40 && r > g + 20 ? 1.0 : 0.0;
        shares.yellow += r > b + 60 && g > b + 60 ? 1.0 : 0.0;
    }
    shares.purple /= double(pixels);
    shares.yellow /= double(pixels);
    return shares;
}

TEST_F(MapOverlayTest, TheTerrainShowsTheMapAndThenNothing) {
    core::LoadedProject loaded;
    loaded.folder = sourceDir();
    loaded.project.mesh.procedural.size = 2.0f;
    loaded.project.mesh.procedural.resolution = 4;
    auto scene = core::buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    scene->layers.clear();  // the terrain alone
    // Straight down on the plane, which fills the middle of the view.
    const core::OrbitCamera camera = core::OrbitCamera::lookAt({0.0f, 3.0f, 0.001f}, glm::vec3(0.0f),
                                                               glm::radians(45.0f));
    auto renderer = render::SceneRenderer::create(*scene);
    ASSERT_TRUE(renderer.ok()) << renderer.error().str();
    gl::Framebuffer target(96, 96, 0);
    render::RenderOptions options;
    options.albedoView = true;  // the unlit colour: the overlay's, not the sun's
    const auto draw = [&] {
        (*renderer)->render(camera, 96, 96, target, options);
        return overlayShares(target.readPixels());
    };
    const Shares plain = draw();
    EXPECT_LT(plain.purple, 0.01);
    EXPECT_LT(plain.yellow, 0.01);

    // Half the map 0, half 1 (along u): the plane shows both ends in about equal parts.
    core::MapImage map = core::makeConstantMap(64, 64, 1.0f);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 32; ++x)
            map.texels[std::size_t(y * 64 + x)] = 0.0f;
    (*renderer)->setMapOverlay(&map);
    const Shares shown = draw();
    EXPECT_GT(shown.purple, 0.15) << shown.purple;
    EXPECT_GT(shown.yellow, 0.15) << shown.yellow;
    EXPECT_NEAR(shown.purple, shown.yellow, 0.1);

    // A map never painted reads 1: all yellow.
    core::MapImage unpainted;
    (*renderer)->setMapOverlay(&unpainted);
    const Shares ones = draw();
    EXPECT_LT(ones.purple, 0.01);
    EXPECT_GT(ones.yellow, 0.3);

    (*renderer)->setMapOverlay(nullptr);
    const Shares gone = draw();
    EXPECT_LT(gone.purple, 0.01);
    EXPECT_LT(gone.yellow, 0.01);
}

}  // namespace
}  // namespace grass::test
