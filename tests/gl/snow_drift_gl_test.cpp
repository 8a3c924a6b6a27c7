// Snow drift on the GPU (issue 30 item 2) held to the CPU reference of core/snow/snow_drift.h:
// the compute pass's drift cells equal core::computeSnowDriftMap over the same depth map, and a
// snow that does not drift runs no drift pass at all.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gl_context_fixture.h"
#include "render/mesh_gpu.h"
#include "render/snow_pass.h"
#include "scene/scene.h"
#include "snow/snow_drift.h"
#include "support/plane_project.h"

namespace grass::test {
namespace {

using SnowDriftGlTest = GlTest;

constexpr int RES = 256;

// A 4 m plane with a 0.6 m ball over its centre: the ball shelters a lee.
struct BallScene {
    core::Scene scene;
    core::OrthoSnowView view;
};

BallScene ballScene() {
    PlaneField field;
    field.sizeM = 4.0f;
    field.resolution = 8;
    field.density = 2.0f;
    core::LoadedProject loaded = planeFieldProject(field);
    addBall(loaded, {0.0f, 0.7f, 0.0f}, 0.6f);
    auto scene = core::buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    core::Bounds bounds{{-2.0f, 0.0f, -2.0f}, {2.0f, 1.4f, 2.0f}};
    return {std::move(*scene), core::makeOrthoSnowView({0.1f, -1.0f, 0.05f}, bounds, 0.1f)};
}

core::SnowParams drifting(float drift) {
    core::SnowParams params;
    params.enabled = 1u;
    params.drift = drift;
    params.driftReachM = 1.5f;
    params.driftFollowsWind = 0u;
    params.driftDirection = {1.0f, 0.0f, 0.3f};
    return params;
}

void runDepth(render::SnowPass& pass, const BallScene& ball) {
    render::MeshGpu plane(ball.scene.mesh), sphere(ball.scene.props.front().mesh);
    const glm::mat4 model = ball.scene.props.front().modelAt(0.0f);
    pass.run(ball.view, RES, [&](const gl::Program& program) {
        program.set("uModel", glm::mat4(1.0f));
        plane.draw();
        program.set("uModel", model);
        sphere.draw();
    });
}

// The GPU's depth map as the CPU reference holds one: metres, SNOW_MAP_EMPTY where cleared.
core::SnowDepthMap readDepth(const render::SnowPass& pass, const core::OrthoSnowView& view) {
    std::vector<float> depth(std::size_t(RES) * RES);
    glGetTextureImage(pass.depthTexture().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(depth.size() * sizeof(float)), depth.data());
    core::SnowDepthMap map;
    map.view = view;
    map.resolution = RES;
    map.depthM.resize(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i)
        map.depthM[i] = depth[i] < 1.0f ? depth[i] * view.depthRangeM : core::SNOW_MAP_EMPTY;
    return map;
}

TEST_F(SnowDriftGlTest, TheDriftCellsMatchTheCpuReference) {
    const BallScene ball = ballScene();
    ASSERT_EQ(ball.scene.props.size(), 1u);
    auto pass = render::SnowPass::create();
    ASSERT_TRUE(pass.ok()) << pass.error().str();
    runDepth(*pass, ball);
    const core::SnowParams params = drifting(0.8f);
    EXPECT_TRUE(pass->bind(params, 0.2f));
    const int cells = RES / core::SNOW_DRIFT_CELL_TEXELS;
    ASSERT_EQ(pass->driftCells(), cells);
    std::vector<float> gpu(std::size_t(cells) * cells);
    glGetTextureImage(pass->driftTexture().id(), 0, GL_RED, GL_FLOAT,
                      GLsizei(gpu.size() * sizeof(float)), gpu.data());

    const core::SnowDepthMap map = readDepth(*pass, ball.view);
    const core::SnowDriftMap cpu = core::computeSnowDriftMap(
        map, params, core::snowDriftMapDirection(ball.view, params.driftDirection));
    ASSERT_EQ(cpu.factor.size(), gpu.size());
    // Same kernel, same depths: only a sample whose position rounds to the other side of a texel
    // border (a last-bit difference of the two compilers) may pick another texel.
    std::size_t differ = 0, lee = 0, scoured = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        differ += std::abs(gpu[i] - cpu.factor[i]) > 1e-4f ? 1 : 0;
        lee += cpu.factor[i] > 1.2f ? 1 : 0;
        scoured += cpu.factor[i] < 0.8f ? 1 : 0;
    }
    EXPECT_LE(differ, gpu.size() / 200) << differ << " of " << gpu.size() << " cells differ";
    // The ball both shelters a lee and has a windward side: the comparison covers both.
    EXPECT_GT(lee, 10u);
    EXPECT_GT(scoured, 2u);
}

TEST_F(SnowDriftGlTest, SnowWithoutDriftRunsNoDriftPass) {
    const BallScene ball = ballScene();
    auto pass = render::SnowPass::create();
    ASSERT_TRUE(pass.ok()) << pass.error().str();
    runDepth(*pass, ball);
    EXPECT_FALSE(pass->bind(drifting(0.0f), 0.2f));
    EXPECT_EQ(pass->driftCells(), 0);
    core::SnowParams along = drifting(1.0f);
    along.driftDirection = {0.1f, -1.0f, 0.05f};  // along the fall: no direction across the map
    EXPECT_FALSE(pass->bind(along, 0.2f));
    EXPECT_EQ(pass->driftCells(), 0);
}

}  // namespace
}  // namespace grass::test
