// Model only what a scene requires (issue 10, SPEC §13): a frame runs only the passes its
// features need, the renderer allocates snow maps, tip buffers, billboards and stem sets only
// once a frame uses them, and the GPU physics holds no wind or collider buffers for a scene
// without them. The pass list is what `grass render --stats` prints.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "render/physics_gpu.h"
#include "scene/scene.h"
#include "render/scene_renderer.h"
#include "support/plane_project.h"

namespace grass::test {
namespace {

using PassesGlTest = GlTest;
using Names = std::vector<std::string>;

struct Ran {
    Names passes;
    Names allocated;
};

class Frames {
public:
    Frames() {
        PlaneField field;
        field.sizeM = 2.0f;
        field.density = 40.0f;
        mLoaded = planeFieldProject(field);
        mLoaded.project.billboards.placement.density = 4.0f;
        auto scene = core::buildScene(mLoaded);
        EXPECT_TRUE(scene.ok()) << scene.error().str();
        mScene = std::move(*scene);
        auto renderer = render::SceneRenderer::create(mScene);
        EXPECT_TRUE(renderer.ok()) << renderer.error().str();
        mRenderer = std::move(*renderer);
    }
    Ran draw(const render::RenderOptions& options) {
        const core::OrbitCamera camera =
            core::OrbitCamera::lookAt({0.0f, 2.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 0.8f);
        gl::Framebuffer framebuffer(64, 64, 0);
        mRenderer->render(camera, 64, 64, framebuffer, options);
        const render::FrameTimings timings = mRenderer->lastTimings();
        return {timings.passes, timings.allocated};
    }
    render::RenderOptions options() const {
        return render::renderOptionsFor(mLoaded.project, true);
    }

private:
    core::LoadedProject mLoaded;
    core::Scene mScene;
    std::unique_ptr<render::SceneRenderer> mRenderer;
};

TEST_F(PassesGlTest, AFrameRunsAndAllocatesOnlyWhatItsFeaturesUse) {
    Frames frames;
    render::RenderOptions options = frames.options();
    options.technique = core::GrassTechnique::Blades;
    const Ran plain = frames.draw(options);
    // The occlusion test reads the frame's depth after its opaque pass (no second drawing of the
    // ground); under snow a pre-pass draws the ground without the snow surface.
    EXPECT_EQ(plain.passes, (Names{"opaque", "occlusion_depth", "cull", "blades"}));
    EXPECT_TRUE(plain.allocated.empty()) << "no snow, billboards or stem sets were drawn";

    options.cull.occlusion = false;
    EXPECT_EQ(frames.draw(options).passes, (Names{"opaque", "cull", "blades"}));
    options.cull.occlusion = true;

    options.snow.enabled = 1u;
    options.snow.amountM = 0.0f;  // on, but nothing lies: still no snow pass
    EXPECT_EQ(frames.draw(options).passes, plain.passes);
    EXPECT_TRUE(frames.draw(options).allocated.empty());

    options.snow.amountM = 0.1f;
    const Ran snowy = frames.draw(options);
    EXPECT_EQ(snowy.passes,
              (Names{"snow_depth", "opaque_snow", "occlusion_prepass", "cull_snow", "blades"}));
    EXPECT_EQ(snowy.allocated, (Names{"snow_map", "snow_programs", "tip_snow"}));

    // Drift (issue 30 item 2) runs its pass only while the snow drifts.
    options.snow.drift = 0.5f;
    options.snow.driftFollowsWind = 0u;
    options.snow.driftDirection = {1.0f, 0.0f, 0.0f};
    const Ran drifting = frames.draw(options);
    EXPECT_EQ(drifting.passes, (Names{"snow_depth", "snow_drift", "opaque_snow",
                                      "occlusion_prepass", "cull_snow", "blades"}));
    EXPECT_EQ(drifting.allocated, (Names{"snow_map", "snow_drift", "snow_programs", "tip_snow"}));
    options.snow.drift = 0.0f;
    EXPECT_EQ(frames.draw(options).passes, snowy.passes) << "no drift runs no drift pass again";

    options.snow.enabled = 0u;
    EXPECT_EQ(frames.draw(options).passes, plain.passes) << "snow off runs no snow pass again";

    options.technique = core::GrassTechnique::Hybrid;
    const Ran hybrid = frames.draw(options);
    EXPECT_EQ(hybrid.passes, (Names{"opaque", "occlusion_depth", "cull", "blades", "billboards"}));
    options.technique = core::GrassTechnique::Growth;
    const Ran growth = frames.draw(options);
    EXPECT_EQ(growth.passes, (Names{"opaque", "stem_sets"})) << "no blades, no cull";
    EXPECT_EQ(growth.allocated, (Names{"snow_map", "snow_drift", "snow_programs", "tip_snow",
                                       "billboards", "stem_sets"}))
        << "what was allocated stays for the next frame that needs it";

    // Sun shadows (issue 30 item 11): a depth pass and a map only while they are on.
    options.technique = core::GrassTechnique::Blades;
    options.sun.shadows = true;
    const Ran shaded = frames.draw(options);
    EXPECT_EQ(shaded.passes, (Names{"sun_shadow", "opaque", "occlusion_depth", "cull", "blades"}));
    EXPECT_EQ(shaded.allocated.back(), "sun_shadow_map");
    options.sun.shadows = false;
    EXPECT_EQ(frames.draw(options).passes, plain.passes) << "shadows off run no shadow pass";
}

TEST_F(PassesGlTest, PhysicsHoldsNoWindOrColliderBuffersWithoutThem) {
    PlaneField field;
    field.sizeM = 1.0f;
    field.density = 50.0f;
    auto scene = core::buildScene(planeFieldProject(field));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const std::vector<core::Blade>& blades = scene->layers.front().patched.blades;
    auto physics = render::PhysicsGpu::load();
    ASSERT_TRUE(physics.ok()) << physics.error().str();
    physics->reset(blades);
    gl::Buffer buffer = gl::Buffer::fromVector(blades, "passes test blades");
    const core::PhysicsParams params;
    physics->step(buffer, blades.size(), params, {}, {}, 0.0f);
    EXPECT_TRUE(physics->allocated().empty());

    core::WindSource wind;
    wind.strength = 2.0f;
    physics->step(buffer, blades.size(), params, {wind}, {}, 0.1f);
    EXPECT_EQ(physics->allocated(), (Names{"wind"}));
    core::SphereCollider ball{{0.0f, 0.2f, 0.0f}, 0.3f, {}};
    physics->step(buffer, blades.size(), params, {wind}, {ball}, 0.2f);
    EXPECT_EQ(physics->allocated(), (Names{"wind", "colliders"}));
}

}  // namespace
}  // namespace grass::test
