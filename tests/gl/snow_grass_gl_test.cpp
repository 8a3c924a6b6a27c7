// Snow meets grass on the GPU (SPEC §11, issue 9): the cull pass buries blades shorter than the
// snow at their roots (the drawn count drops, and turning snow off restores it) and whitens the
// tips of the rest by their exposure, both held to the CPU reference of core/snow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "maps/map_image.h"
#include "scene/scene.h"
#include "render/scene_renderer.h"
#include "snow/snow.h"
#include "support/plane_project.h"

namespace grass::test {
namespace {

using SnowGrassGlTest = GlTest;

constexpr int SIZE = 96;

// Every blade goes through the cull (no test removes any), so only snow can cull.
render::RenderOptions allBladesOptions(const core::Project& project) {
    render::RenderOptions options = render::renderOptionsFor(project, true);
    options.cull.frustum = options.cull.orientation = false;
    options.cull.distance = options.cull.occlusion = false;
    options.cull.collectStats = true;
    return options;
}

// A project's scene and a renderer over it, with every blade going through the cull.
struct DrawnField {
    core::Scene scene;
    std::unique_ptr<render::SceneRenderer> renderer;
    render::RenderOptions options;
};

// On the heap: the renderer keeps a pointer to the scene.
std::unique_ptr<DrawnField> drawnField(const core::LoadedProject& loaded) {
    auto drawn = std::make_unique<DrawnField>();
    auto scene = core::buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    if (!scene.ok())
        return nullptr;
    drawn->scene = std::move(*scene);
    auto renderer = render::SceneRenderer::create(drawn->scene);
    EXPECT_TRUE(renderer.ok()) << renderer.error().str();
    if (!renderer.ok())
        return nullptr;
    drawn->renderer = std::move(*renderer);
    drawn->options = allBladesOptions(loaded.project);
    return drawn;
}

struct Frame {
    render::CullStats cull;
    std::vector<float> tipSnow;
};

Frame renderFrame(render::SceneRenderer& renderer, const render::RenderOptions& options) {
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0.0f, 5.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 0.9f);
    gl::Framebuffer framebuffer(SIZE, SIZE, 0);
    renderer.render(camera, SIZE, SIZE, framebuffer, options);
    glFinish();
    return {renderer.lastTimings().cull, renderer.readTipSnow(0)};
}

// The GPU depth map of the last frame as a core::SnowDepthMap (the GL snow test holds it equal
// to the CPU rasteriser), so the CPU functions can be evaluated on exactly the GPU's map.
core::SnowDepthMap readDepthMap(const render::SnowPass& pass, int resolution) {
    core::SnowDepthMap map;
    map.view = pass.view();
    map.resolution = resolution;
    map.depthM.resize(std::size_t(resolution) * std::size_t(resolution));
    glGetTextureImage(pass.depthTexture().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(map.depthM.size() * sizeof(float)), map.depthM.data());
    for (float& depth : map.depthM)
        depth = depth < 1.0f ? depth * map.view.depthRangeM : core::SNOW_MAP_EMPTY;
    return map;
}

// A 3 m plane of blades 5 to 40 cm tall: snow of a few centimetres buries some of them.
core::LoadedProject shortAndTallBlades(float density) {
    PlaneField plane;
    plane.sizeM = 3.0f;
    plane.resolution = 4;
    plane.density = density;
    plane.heightMinM = 0.05f;
    plane.heightMaxM = 0.4f;
    return planeFieldProject(plane);
}

TEST_F(SnowGrassGlTest, BuriedBladesAreCulledAndSnowOffRestoresTheCount) {
    const core::LoadedProject loaded = shortAndTallBlades(300.0f);
    const auto drawn = drawnField(loaded);
    ASSERT_NE(drawn, nullptr);
    render::SceneRenderer& renderer = *drawn->renderer;
    const core::Scene& scene = drawn->scene;
    render::RenderOptions& options = drawn->options;

    const Frame bare = renderFrame(renderer, options);
    ASSERT_GT(bare.cull.bladesIn, 1000u);
    EXPECT_EQ(bare.cull.drawn, bare.cull.bladesIn);
    EXPECT_EQ(bare.cull.culledSnow, 0u);

    core::SnowParams& snow = options.snow;
    snow.enabled = 1u;
    snow.amountM = 0.25f;
    snow.mapResolution = 512;
    const Frame snowy = renderFrame(renderer, options);
    EXPECT_EQ(snowy.cull.bladesIn, bare.cull.bladesIn);
    EXPECT_GT(snowy.cull.culledSnow, bare.cull.bladesIn / 10) << "short blades vanish";
    EXPECT_LT(snowy.cull.drawn, bare.cull.drawn);
    EXPECT_EQ(snowy.cull.drawn + snowy.cull.culledSnow, snowy.cull.bladesIn);

    // The CPU reference on the same map: blades shorter than As·Fe·Zn at their roots.
    const render::SnowPass* pass = renderer.snowPass();
    ASSERT_NE(pass, nullptr);
    const core::SnowDepthMap map = readDepthMap(*pass, snow.mapResolution);
    std::size_t buried = 0;
    for (const core::Blade& blade : scene.layers.front().patched.blades) {
        if (!(blade.h() > 0.0f))
            continue;
        const float fe = core::snowBoundaryExposure(map, blade.v0(), blade.up(), snow);
        buried += core::bladeBuriedBySnow(blade.h(), core::snowDepthAt(blade.v0(), fe, snow));
    }
    // Only blades within float rounding of the snow surface may be judged differently.
    const auto difference =
        std::max(buried, snowy.cull.culledSnow) - std::min(buried, snowy.cull.culledSnow);
    EXPECT_LE(difference, bare.cull.bladesIn / 500)
        << "CPU " << buried << " GPU " << snowy.cull.culledSnow;

    snow.amountM = 20.0f;  // deeper than any blade except where the noise nearly cancels Zn
    const Frame deep = renderFrame(renderer, options);
    EXPECT_LT(deep.cull.drawn, bare.cull.bladesIn / 50);

    snow.enabled = 0u;
    const Frame restored = renderFrame(renderer, options);
    EXPECT_EQ(restored.cull.drawn, bare.cull.drawn);
    EXPECT_EQ(restored.cull.culledSnow, 0u);
}

// The editor shows the map being painted over the surface while snow lies. The overlay once
// shared the snow map's texture unit: the opaque pass bound it there and the cull read the
// painted map as the snow's depth, burying nothing. The overlay now changes no blade's fate.
TEST_F(SnowGrassGlTest, APaintOverlayLeavesTheSnowBurialAlone) {
    const core::LoadedProject loaded = shortAndTallBlades(300.0f);
    const auto drawn = drawnField(loaded);
    ASSERT_NE(drawn, nullptr);
    render::SceneRenderer& renderer = *drawn->renderer;
    render::RenderOptions& options = drawn->options;
    options.snow.enabled = 1u;
    options.snow.amountM = 0.25f;
    options.snow.mapResolution = 512;
    const Frame plain = renderFrame(renderer, options);
    ASSERT_GT(plain.cull.culledSnow, plain.cull.bladesIn / 10);

    core::MapImage painted;
    painted.width = painted.height = 8;
    painted.texels.assign(64, 0.0f);  // read as depth: the sky's own height, nothing sheltered
    renderer.setMapOverlay(&painted);
    const Frame overlaid = renderFrame(renderer, options);
    EXPECT_EQ(overlaid.cull.culledSnow, plain.cull.culledSnow);
    EXPECT_EQ(overlaid.tipSnow, plain.tipSnow);
}

TEST_F(SnowGrassGlTest, ExposedTipsWhitenAndShelteredTipsDoNot) {
    PlaneField plane;
    plane.sizeM = 4.0f;
    plane.resolution = 8;
    plane.density = 60.0f;
    core::LoadedProject loaded = planeFieldProject(plane);
    addBall(loaded, {0.0f, 1.4f, 0.0f}, 0.8f);
    const auto drawn = drawnField(loaded);
    ASSERT_NE(drawn, nullptr);
    render::SceneRenderer& renderer = *drawn->renderer;
    const core::Scene& scene = drawn->scene;
    render::RenderOptions& options = drawn->options;
    core::SnowParams& snow = options.snow;
    snow.enabled = 1u;
    snow.amountM = 0.01f;  // too thin to bury any blade: every tip is judged
    snow.mapResolution = 512;
    snow.fallDirection = {0.0f, -1.0f, 0.0f};
    const Frame frame = renderFrame(renderer, options);
    ASSERT_EQ(frame.cull.culledSnow, 0u);
    const core::SnowDepthMap map = readDepthMap(*renderer.snowPass(), snow.mapResolution);
    const auto& blades = scene.layers.front().patched.blades;
    ASSERT_EQ(frame.tipSnow.size(), blades.size());

    std::size_t exposedWhite = 0, exposed = 0, shelteredWhite = 0, sheltered = 0, mismatched = 0;
    std::size_t live = 0;
    for (std::size_t i = 0; i < blades.size(); ++i) {
        if (!(blades[i].h() > 0.0f))
            continue;
        ++live;
        const float cpu = core::bladeTipSnow(
            core::exposureCoefficient(map, blades[i].v2(), core::snowUp(snow), snow.samples,
                                      snow.sampleRadiusTexels, snow.depthBiasM),
            snow);
        // One jittered sample more or less where a sample sits on a texel edge.
        mismatched += std::abs(cpu - frame.tipSnow[i]) > 1.01f / float(snow.samples);
        const glm::vec3 root = blades[i].v0();
        const float fromAxis = std::hypot(root.x, root.z);
        if (fromAxis < 0.5f) {
            ++sheltered;
            shelteredWhite += frame.tipSnow[i] > 0.5f;
        } else if (fromAxis > 1.2f) {
            ++exposed;
            exposedWhite += frame.tipSnow[i] > 0.99f;
        }
    }
    EXPECT_LE(mismatched, live / 200);
    ASSERT_GT(sheltered, 20u);
    ASSERT_GT(exposed, 200u);
    EXPECT_EQ(shelteredWhite, 0u) << "under the ball no snow reaches the tips";
    EXPECT_EQ(exposedWhite, exposed) << "in the open every tip carries snow";
}

// The picture carries the tips' snow (the blade programs' GRASS_SNOW_TIPS variant, drawn while
// snow lies): tall blades seen from low down stand against the sky above the horizon, where no
// snow-covered ground can show, so pixels of the snow's colour there are whitened tips. A
// magenta snow keeps them apart from the sky and the grass; unlit (albedo view), so the colour
// is the mix of paper eq. 3 alone.
TEST_F(SnowGrassGlTest, TheTipsSnowShowsInThePicture) {
    PlaneField plane;
    plane.sizeM = 4.0f;
    plane.resolution = 4;
    plane.density = 100.0f;
    plane.heightMinM = 0.5f;
    plane.heightMaxM = 0.8f;
    const auto drawn = drawnField(planeFieldProject(plane));
    ASSERT_NE(drawn, nullptr);
    render::RenderOptions options = drawn->options;
    options.albedoView = true;
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0.0f, 0.3f, 2.6f}, {0.0f, 0.3f, -2.0f}, 0.9f);
    const auto magentaAboveHorizon = [&](const render::RenderOptions& frameOptions) {
        gl::Framebuffer framebuffer(SIZE, SIZE, 0);
        drawn->renderer->render(camera, SIZE, SIZE, framebuffer, frameOptions);
        const gl::Rgba8Image image = framebuffer.readPixels();
        std::size_t count = 0;
        // Rows from the top (readPixels): the upper half holds sky and the blades' tops.
        for (int y = 0; y < SIZE / 2 - 2; ++y)
            for (int x = 0; x < SIZE; ++x) {
                const std::uint8_t* p = &image.pixels[4 * (std::size_t(y) * SIZE + std::size_t(x))];
                count += p[0] > 150 && p[1] < 110 && p[2] > 150 ? 1u : 0u;
            }
        return count;
    };
    const std::size_t without = magentaAboveHorizon(options);
    options.snow.enabled = 1u;
    options.snow.amountM = 0.01f;  // too thin to bury a blade
    options.snow.fallDirection = {0.0f, -1.0f, 0.0f};
    options.snow.snowColor = {1.0f, 0.0f, 1.0f};
    const std::size_t with = magentaAboveHorizon(options);
    std::printf("[ snow ] magenta pixels above the horizon: %zu without snow, %zu with\n", without,
                with);
    EXPECT_EQ(without, 0u);
    // Without the tips' snow in the shading none at all (measured); with it ~50 pixels.
    EXPECT_GT(with, 20u) << "the tips carry no snow in the picture";
}

// --time: As(t) = clamp(As + (accumulation − melt)·t, 0, max). Snow that starts at nothing
// buries blades once enough has fallen, and snow that melts away gives the snow-free frame back.
TEST_F(SnowGrassGlTest, SnowAccumulatesAndMeltsOverTime) {
    const core::LoadedProject loaded = shortAndTallBlades(200.0f);
    const auto drawn = drawnField(loaded);
    ASSERT_NE(drawn, nullptr);
    render::SceneRenderer& renderer = *drawn->renderer;
    render::RenderOptions& options = drawn->options;
    core::SnowParams& snow = options.snow;
    snow.enabled = 1u;
    snow.amountM = 0.0f;
    snow.accumulationRate = 0.01f;  // 1 cm a second
    snow.mapResolution = 512;
    std::vector<std::size_t> buried;
    for (const float t : {0.0f, 10.0f, 30.0f}) {
        options.timeS = t;
        buried.push_back(renderFrame(renderer, options).cull.culledSnow);
    }
    EXPECT_EQ(buried[0], 0u) << "no snow has fallen at t = 0";
    EXPECT_GT(buried[1], 0u);
    EXPECT_GT(buried[2], buried[1]) << "deeper snow buries more";

    snow.amountM = 0.3f;
    snow.accumulationRate = 0.0f;
    snow.meltRate = 0.01f;  // gone after 30 s
    options.timeS = 5.0f;
    EXPECT_GT(renderFrame(renderer, options).cull.culledSnow, 0u);
    options.timeS = 40.0f;
    const Frame melted = renderFrame(renderer, options);
    EXPECT_EQ(melted.cull.culledSnow, 0u);
    EXPECT_EQ(melted.cull.drawn, melted.cull.bladesIn);
}

}  // namespace
}  // namespace grass::test
