// The hybrid technique (SPEC §8): geometric blades near the camera cross-fade into star
// billboards far away without a visible pop. With the camera fixed, the cross-fade band is
// moved towards the camera in small steps: a cross-fade changes each pixel a little per step,
// a hard switch flips whole blades. The test measures the share of pixels that jump by more than
// JUMP levels between steps and requires the cross-fade to stay far below the hard switch.
#include <gtest/gtest.h>

#include <algorithm>

#include "gl_context_fixture.h"
#include "render/offscreen_render.h"
#include "support/image_compare.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using HybridTest = GlTest;

// A jump a viewer sees as a pop: more than one of four MSAA samples of a blade pixel turning
// into billboard or ground (one sample is ≤ 1/4 of the ~120-level contrast).
constexpr int JUMP = 48;

core::Scene hybridScene() {
    core::LoadedProject loaded = planeFieldProject({14.0f, 2, 30.0f, 0.3f, 0.5f}, sourceDir());
    auto scene = core::buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return scene.ok() ? std::move(*scene) : core::Scene{};
}

gl::Rgba8Image renderHybrid(const core::Scene& scene, glm::vec2 crossFade) {
    core::OrbitCamera camera;
    camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    camera.distance = 5.0f;
    camera.pitchRad = 0.3f;
    camera.nearPlane = 0.05f;
    camera.farPlane = 100.0f;
    render::OffscreenRequest request;
    request.width = request.height = 128;
    request.frames = 1;
    request.options.technique = core::GrassTechnique::Hybrid;
    request.options.billboards.crossFadeM = crossFade;
    auto result = render::renderOffscreen(scene, camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(result->image) : gl::Rgba8Image{};
}

// Largest share of jumping pixels between consecutive steps of the band [start, start + width].
double worstJumpShare(const core::Scene& scene, float width) {
    double worst = 0.0;
    gl::Rgba8Image previous;
    for (float start = 7.0f; start >= 3.0f; start -= 0.25f) {
        gl::Rgba8Image image = renderHybrid(scene, {start, start + width});
        if (!previous.pixels.empty())
            worst = std::max(worst, compareImages(previous.pixels, image.pixels, JUMP).differingShare);
        previous = std::move(image);
    }
    return worst;
}

TEST_F(HybridTest, CrossFadeDoesNotPopWhereAHardSwitchDoes) {
    const core::Scene scene = hybridScene();
    const double smooth = worstJumpShare(scene, 3.0f);
    const double hard = worstJumpShare(scene, 0.001f);
    std::printf("[ hybrid ] worst share of pixels jumping > %d levels per 0.25 m step: "
                "cross-fade %.4f, hard switch %.4f\n",
                JUMP, smooth, hard);
    EXPECT_GT(hard, 0.01) << "the hard switch must show (else the scene tests nothing)";
    EXPECT_LT(smooth, 0.3 * hard);
}

// Blades are culled beyond the band (the far field costs only billboards) and counted as
// distance culling.
TEST_F(HybridTest, BladesEndAtTheFarEdgeOfTheCrossFade) {
    const core::Scene scene = hybridScene();
    core::OrbitCamera camera;
    camera.distance = 5.0f;
    camera.pitchRad = 0.3f;
    render::OffscreenRequest request;
    request.width = request.height = 64;
    request.frames = 1;
    request.options.cull.collectStats = true;
    request.options.cull.distance = false;
    auto blades = render::renderOffscreen(scene, camera, request);
    request.options.technique = core::GrassTechnique::Hybrid;
    request.options.billboards.crossFadeM = {2.0f, 4.0f};
    auto hybrid = render::renderOffscreen(scene, camera, request);
    ASSERT_TRUE(blades.ok() && hybrid.ok());
    EXPECT_LT(hybrid->lastFrame.cull.drawn, blades->lastFrame.cull.drawn / 2);
    EXPECT_GT(hybrid->lastFrame.cull.culledDistance, 0u);
    EXPECT_GT(hybrid->lastFrame.billboardsDrawn, 0u);
}

}  // namespace
}  // namespace grass::test
