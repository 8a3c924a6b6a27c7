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
#include "render/scene_renderer.h"
#include "scene/scene.h"
#include "scene/scene_props.h"
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

    // The depth map of a scene nothing moved in is kept, not drawn again, until the snowfall's
    // view changes (its direction here).
    const Ran still = frames.draw(options);
    const Names kept{"snow_depth_kept", "opaque_snow", "occlusion_prepass", "cull_snow", "blades"};
    EXPECT_EQ(still.passes, kept);
    options.timeS = 5.0f;  // later, nothing moving: kept too
    EXPECT_EQ(frames.draw(options).passes, kept);
    options.snow.fallDirection = {0.3f, -1.0f, 0.0f};
    EXPECT_EQ(frames.draw(options).passes, snowy.passes) << "another view draws its map";
    EXPECT_EQ(frames.draw(options).passes, kept);

    // Drift (issue 30 item 2) runs its pass only while the snow drifts.
    options.snow.drift = 0.5f;
    options.snow.driftFollowsWind = 0u;
    options.snow.driftDirection = {1.0f, 0.0f, 0.0f};
    const Ran drifting = frames.draw(options);
    EXPECT_EQ(drifting.passes, (Names{"snow_depth_kept", "snow_drift", "opaque_snow",
                                      "occlusion_prepass", "cull_snow", "blades"}));
    EXPECT_EQ(drifting.allocated, (Names{"snow_map", "snow_drift", "snow_programs", "tip_snow"}));
    options.snow.drift = 0.0f;
    EXPECT_EQ(frames.draw(options).passes, kept) << "no drift runs no drift pass again";

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
    EXPECT_EQ(frames.draw(options).passes,
              (Names{"sun_shadow_kept", "opaque", "occlusion_depth", "cull", "blades"}))
        << "the sun's map of a still scene is kept";
    options.sun.shadows = false;
    EXPECT_EQ(frames.draw(options).passes, plain.passes) << "shadows off run no shadow pass";
}

// The snow's depth map of the renderer's last frame, as stored (depth / depth range).
std::vector<float> snowDepth(const render::SceneRenderer& renderer) {
    const render::SnowPass* pass = renderer.snowPass();
    EXPECT_NE(pass, nullptr);
    if (!pass)
        return {};
    GLint side = 0;
    glGetTextureLevelParameteriv(pass->depthTexture().id(), 0, GL_TEXTURE_WIDTH, &side);
    std::vector<float> depth(std::size_t(side) * std::size_t(side));
    glGetTextureImage(pass->depthTexture().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(depth.size() * sizeof(float)), depth.data());
    return depth;
}

// A kept snow map is the map of the props where they stand: a ball moved by the gizmo draws the
// map again, and it is the map a fresh renderer draws of the moved scene.
TEST_F(PassesGlTest, ASnowMapIsKeptOnlyWhileThePropsStayWhereTheyWere) {
    PlaneField field;
    field.sizeM = 2.0f;
    field.density = 20.0f;
    core::LoadedProject loaded = planeFieldProject(field);
    core::ColliderDesc ball;
    ball.name = "ball";
    ball.position = {0.0f, 0.4f, 0.0f};
    ball.radiusM = 0.3f;
    loaded.project.colliders.push_back(ball);
    auto scene = core::buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    auto renderer = render::SceneRenderer::create(*scene);
    ASSERT_TRUE(renderer.ok()) << renderer.error().str();
    render::RenderOptions options = render::renderOptionsFor(loaded.project, true);
    options.snow.enabled = 1u;
    options.snow.amountM = 0.1f;
    options.snow.mapResolution = 128;
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0.0f, 2.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 0.8f);
    gl::Framebuffer framebuffer(64, 64, 0);
    const auto firstPass = [&](render::SceneRenderer& r) {
        r.render(camera, 64, 64, framebuffer, options);
        const render::FrameTimings timings = r.lastTimings();
        return timings.passes.empty() ? std::string() : timings.passes.front();
    };
    EXPECT_EQ(firstPass(**renderer), "snow_depth");
    const std::vector<float> before = snowDepth(**renderer);
    EXPECT_EQ(firstPass(**renderer), "snow_depth_kept");
    ball.position.x = 0.5f;
    core::placeSceneProp(scene->props.front(), ball);
    EXPECT_EQ(firstPass(**renderer), "snow_depth") << "the ball moved";
    const std::vector<float> moved = snowDepth(**renderer);
    EXPECT_NE(moved, before) << "the ball's shadow in the map moved with it";
    auto fresh = render::SceneRenderer::create(*scene);
    ASSERT_TRUE(fresh.ok()) << fresh.error().str();
    EXPECT_EQ(firstPass(**fresh), "snow_depth");
    EXPECT_EQ(snowDepth(**fresh), moved);
    EXPECT_EQ(firstPass(**renderer), "snow_depth_kept");
    EXPECT_EQ(snowDepth(**renderer), moved);
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
