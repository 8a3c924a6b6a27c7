// A glTF terrain's base-colour texture shows in the renderer's picture: the opaque pass draws a
// textured terrain with the program variant that holds the texture lookups (mesh.frag with
// GRASS_MESH_TEXTURES) and an untextured one without them, so a scene pays for lookups only when
// it has a texture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl_context_fixture.h"
#include "project/project.h"
#include "render/scene_renderer.h"
#include "scene/scene.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using SurfaceTextureTest = GlTest;

TEST_F(SurfaceTextureTest, ATexturedTerrainShowsItsTextureAndAPlainOneItsColour) {
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/textured_stone");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    ASSERT_FALSE(scene->look.baseTexture.pixels.empty()) << "the stone's texture was not read";
    scene->layers.clear();  // the terrain alone
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0.0f, 2.0f, 3.0f}, glm::vec3(0.0f), glm::radians(45.0f));
    render::RenderOptions options;
    options.albedoView = true;  // the surface's own colour, unlit
    const auto draw = [&](const core::Scene& drawn) {
        auto renderer = render::SceneRenderer::create(drawn);
        EXPECT_TRUE(renderer.ok()) << renderer.error().str();
        gl::Framebuffer target(96, 96, 0);
        (*renderer)->render(camera, 96, 96, target, options);
        return target.readPixels();
    };
    const gl::Rgba8Image textured = draw(*scene);
    core::Scene plain = *scene;
    plain.look.baseTexture = {};
    const gl::Rgba8Image untextured = draw(plain);

    // The plain stone is one colour wherever it shows; the textured one varies over it, so
    // many pixels differ between the two pictures.
    std::size_t differing = 0;
    for (std::size_t i = 0; i + 3 < textured.pixels.size(); i += 4) {
        int delta = 0;
        for (std::size_t c = 0; c < 3; ++c)
            delta = std::max(delta, std::abs(int(textured.pixels[i + c]) - int(untextured.pixels[i + c])));
        differing += delta > 24 ? 1u : 0u;
    }
    EXPECT_GT(differing, textured.pixels.size() / 4 / 20) << "the texture does not show";
}

TEST_F(SurfaceTextureTest, OnlyTheTexturedMeshProgramHoldsTheLookups) {
    const auto load = [](std::vector<std::string> defines) {
        return gl::Program::load(
            {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}}, "mesh", defines);
    };
    auto plain = load({});
    auto textured = load({"GRASS_MESH_TEXTURES"});
    ASSERT_TRUE(plain.ok()) << plain.error().str();
    ASSERT_TRUE(textured.ok()) << textured.error().str();
    for (const char* sampler : {"uBaseTexture", "uMapOverlay"}) {
        EXPECT_EQ(glGetUniformLocation(plain->id(), sampler), -1) << sampler;
        EXPECT_GE(glGetUniformLocation(textured->id(), sampler), 0) << sampler;
    }
}

}  // namespace
}  // namespace grass::test
