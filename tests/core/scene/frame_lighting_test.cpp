// The lighting block a frame uploads (core::frameLighting): what the project's settings become.
#include "scene/frame_lighting.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "scene/grass_lighting_formulas.h"

namespace grass::core {
namespace {

// GLSL leaves smoothstep(near, far, d) undefined for near ≥ far, so a project whose specular
// fade is empty or reversed ([5, 5], [5, 2]) would light differently on every GPU. The block
// turns it into a switch at `near`: no specular nearer, full specular beyond.
TEST(FrameLighting, AnEmptyOrReversedSpecularFadeSwitchesOnAtItsNearDistance) {
    for (const glm::vec2 fade : {glm::vec2(5.0f, 5.0f), glm::vec2(5.0f, 2.0f)}) {
        GrassLightingDesc lighting;
        lighting.specularFadeM = fade;
        const LightingBlock block =
            frameLighting(lighting, SunDesc{}, glm::vec3(0.5f), glm::vec3(0.2f));
        EXPECT_EQ(block.specularFadeM.x, 5.0f);
        EXPECT_GT(block.specularFadeM.y, block.specularFadeM.x);
        EXPECT_EQ(glm::smoothstep(block.specularFadeM.x, block.specularFadeM.y, 4.99f), 0.0f);
        EXPECT_EQ(glm::smoothstep(block.specularFadeM.x, block.specularFadeM.y, 5.01f), 1.0f);
    }
    // A proper fade passes through untouched.
    GrassLightingDesc lighting;
    lighting.specularFadeM = {0.5f, 6.0f};
    const LightingBlock block =
        frameLighting(lighting, SunDesc{}, glm::vec3(0.5f), glm::vec3(0.2f));
    EXPECT_EQ(block.specularFadeM, glm::vec2(0.5f, 6.0f));
}

// Each model reaches the shaders as its own uGrassLighting value (grass_lighting.glsl).
TEST(FrameLighting, EachLightingModelHasItsShaderValue) {
    const auto valueOf = [](LightingModel model) {
        GrassLightingDesc lighting;
        lighting.model = model;
        return frameLighting(lighting, SunDesc{}, glm::vec3(0.5f), glm::vec3(0.2f)).grassLighting;
    };
    EXPECT_EQ(valueOf(LightingModel::Simple), SIMPLE_LIGHTING);
    EXPECT_EQ(valueOf(LightingModel::Grass), GRASS_LIGHTING);
    EXPECT_EQ(valueOf(LightingModel::Article), ARTICLE_LIGHTING);
}

}  // namespace
}  // namespace grass::core
