// The uniform blocks the renderer uploads (render/lighting_block.h, snow_block.h,
// snow_view_block.h) are laid out by the driver exactly as their C++ structs: the block's size
// and binding, the number of members, and every member's offset are read back from linked
// programs (glGetProgramResourceiv) and compared with sizeof, BINDING and offsetof. A member added,
// moved or retyped on one side only fails here.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "gl/program.h"
#include "gl_context_fixture.h"
#include "render/lighting_block.h"
#include "render/snow_block.h"
#include "render/snow_view_block.h"

namespace grass::test {
namespace {

using UniformBlockLayout = GlTest;

struct Member {
    const char* glslName;
    std::size_t offset;  // offsetof in the C++ struct
};

const Member LIGHTING_MEMBERS[] = {
    {"uSunDirection", offsetof(render::LightingBlock, sunDirection)},
    {"uTerrainNormalWeight", offsetof(render::LightingBlock, terrainNormalWeight)},
    {"uSunColor", offsetof(render::LightingBlock, sunColor)},
    {"uSpecular", offsetof(render::LightingBlock, specular)},
    {"uSkyColor", offsetof(render::LightingBlock, skyColor)},
    {"uTransmission", offsetof(render::LightingBlock, transmission)},
    {"uGroundColor", offsetof(render::LightingBlock, groundColor)},
    {"uTransmissionDistortion", offsetof(render::LightingBlock, transmissionDistortion)},
    {"uDiffuseLow", offsetof(render::LightingBlock, diffuseLow)},
    {"uTransmissionPower", offsetof(render::LightingBlock, transmissionPower)},
    {"uDiffuseMid", offsetof(render::LightingBlock, diffuseMid)},
    {"uSss", offsetof(render::LightingBlock, sss)},
    {"uDiffuseHigh", offsetof(render::LightingBlock, diffuseHigh)},
    {"uSssIntensity", offsetof(render::LightingBlock, sssIntensity)},
    {"uSpecularFade", offsetof(render::LightingBlock, specularFadeM)},
    {"uGrassLighting", offsetof(render::LightingBlock, grassLighting)},
    {"uFieldWater", offsetof(render::LightingBlock, fieldWater)},
    {"uSunShadowOrigin", offsetof(render::LightingBlock, sunShadowOrigin)},
    {"uSunShadowSizeM", offsetof(render::LightingBlock, sunShadowSizeM)},
    {"uSunShadowRight", offsetof(render::LightingBlock, sunShadowRight)},
    {"uSunShadowDepthRangeM", offsetof(render::LightingBlock, sunShadowDepthRangeM)},
    {"uSunShadowUp", offsetof(render::LightingBlock, sunShadowUp)},
    {"uSunShadows", offsetof(render::LightingBlock, sunShadows)},
    {"uSunShadowForward", offsetof(render::LightingBlock, sunShadowForward)},
    {"uSunShadowBiasM", offsetof(render::LightingBlock, sunShadowBiasM)},
};

const Member SNOW_MEMBERS[] = {
    {"uSnowColor", offsetof(render::SnowBlock, color)},
    {"uSnowAmountM", offsetof(render::SnowBlock, amountM)},
    {"uSnowUp", offsetof(render::SnowBlock, up)},
    {"uSnowNoiseA", offsetof(render::SnowBlock, noiseA)},
    {"uSnowNoiseB", offsetof(render::SnowBlock, noiseB)},
    {"uSnowNoiseScaleM", offsetof(render::SnowBlock, noiseScaleM)},
    {"uSnowInclineNoise", offsetof(render::SnowBlock, inclineNoise)},
    {"uSnowRadiusTexels", offsetof(render::SnowBlock, radiusTexels)},
    {"uSnowBoundaryRadiusTexels", offsetof(render::SnowBlock, boundaryRadiusTexels)},
    {"uSnowBiasM", offsetof(render::SnowBlock, biasM)},
    {"uSnowOctaves", offsetof(render::SnowBlock, octaves)},
    {"uSnowSamples", offsetof(render::SnowBlock, samples)},
    {"uSnowEnabled", offsetof(render::SnowBlock, enabled)},
    {"uSnowDrift", offsetof(render::SnowBlock, drift)},
    {"uSnowDriftReachM", offsetof(render::SnowBlock, driftReachM)},
    {"uSnowPad2", offsetof(render::SnowBlock, pad2)},
    {"uSnowDriftDirection", offsetof(render::SnowBlock, driftDirection)},
    {"uSnowPad3", offsetof(render::SnowBlock, pad3)},
};

const Member SNOW_VIEW_MEMBERS[] = {
    {"uSnowOrigin", offsetof(render::SnowViewBlock, origin)},
    {"uSnowSizeM", offsetof(render::SnowViewBlock, sizeM)},
    {"uSnowRight", offsetof(render::SnowViewBlock, right)},
    {"uSnowDepthRangeM", offsetof(render::SnowViewBlock, depthRangeM)},
    {"uSnowUpAxis", offsetof(render::SnowViewBlock, upAxis)},
    {"uSnowResolution", offsetof(render::SnowViewBlock, resolution)},
    {"uSnowForward", offsetof(render::SnowViewBlock, forward)},
    {"uSnowViewPad", offsetof(render::SnowViewBlock, pad)},
};

// Every program that reads a block lays it out alike under std140; these are the renderer's own
// programs that declare them all: the snow surface (lighting, snow, snow view) and the snow depth
// pass (snow view alone).
gl::Program loadSnowSurfaceProgram() {
    auto program = gl::Program::load({{GL_VERTEX_SHADER, "mesh_snow.vert"},
                                      {GL_TESS_CONTROL_SHADER, "mesh_snow.tesc"},
                                      {GL_TESS_EVALUATION_SHADER, "mesh_snow.tese"},
                                      {GL_FRAGMENT_SHADER, "mesh.frag"}},
                                     "layout test: mesh under snow", {"GRASS_SNOW"});
    EXPECT_TRUE(program.ok()) << program.error().str();
    return program.ok() ? std::move(*program) : gl::Program();
}

// Compares the block `blockName` of `program` with the C++ struct's size, binding and members.
void expectLayout(const gl::Program& program, const char* blockName, std::size_t size,
                  std::uint32_t binding, std::span<const Member> members) {
    ASSERT_NE(program.id(), 0u);
    const auto block = glGetProgramResourceIndex(program.id(), GL_UNIFORM_BLOCK, blockName);
    ASSERT_NE(block, GL_INVALID_INDEX) << blockName << " is not an active block";
    const GLenum blockProperties[] = {GL_BUFFER_DATA_SIZE, GL_BUFFER_BINDING,
                                      GL_NUM_ACTIVE_VARIABLES};
    GLint blockValues[3] = {-1, -1, -1};
    glGetProgramResourceiv(program.id(), GL_UNIFORM_BLOCK, block, 3, blockProperties, 3, nullptr,
                           blockValues);
    EXPECT_EQ(blockValues[0], static_cast<GLint>(size)) << blockName << " size";
    EXPECT_EQ(blockValues[1], static_cast<GLint>(binding)) << blockName << " binding";
    EXPECT_EQ(blockValues[2], static_cast<GLint>(members.size())) << blockName << " members";
    for (const Member& member : members) {
        const auto index = glGetProgramResourceIndex(program.id(), GL_UNIFORM, member.glslName);
        ASSERT_NE(index, GL_INVALID_INDEX) << member.glslName << " is not in " << blockName;
        const GLenum properties[] = {GL_OFFSET, GL_BLOCK_INDEX};
        GLint values[2] = {-1, -1};
        glGetProgramResourceiv(program.id(), GL_UNIFORM, index, 2, properties, 2, nullptr, values);
        EXPECT_EQ(values[0], static_cast<GLint>(member.offset)) << member.glslName << " offset";
        EXPECT_EQ(values[1], static_cast<GLint>(block)) << member.glslName << " block";
    }
}

TEST_F(UniformBlockLayout, LightingBlockMatchesItsStruct) {
    expectLayout(loadSnowSurfaceProgram(), "LightingBlock", sizeof(render::LightingBlock),
                 render::LIGHTING_BLOCK_BINDING, LIGHTING_MEMBERS);
}

TEST_F(UniformBlockLayout, LightingBlockMatchesItsStructInTheGrassPrograms) {
    struct Pair {
        const char* vertex;
        const char* fragment;
    };
    for (const Pair pair :
         {Pair{"blade_strip.vert", "blade.frag"}, Pair{"billboard.vert", "billboard.frag"},
          Pair{"stem_set.vert", "stem_set.frag"}}) {
        auto program = gl::Program::load(
            {{GL_VERTEX_SHADER, pair.vertex}, {GL_FRAGMENT_SHADER, pair.fragment}},
            "layout test: grass");
        ASSERT_TRUE(program.ok()) << program.error().str();
        SCOPED_TRACE(pair.fragment);
        expectLayout(*program, "LightingBlock", sizeof(render::LightingBlock),
                     render::LIGHTING_BLOCK_BINDING, LIGHTING_MEMBERS);
    }
}

TEST_F(UniformBlockLayout, SnowBlockMatchesItsStruct) {
    expectLayout(loadSnowSurfaceProgram(), "SnowBlock", sizeof(render::SnowBlock),
                 render::SNOW_BLOCK_BINDING, SNOW_MEMBERS);
}

TEST_F(UniformBlockLayout, SnowViewBlockMatchesItsStruct) {
    expectLayout(loadSnowSurfaceProgram(), "SnowViewBlock", sizeof(render::SnowViewBlock),
                 render::SNOW_VIEW_BLOCK_BINDING, SNOW_VIEW_MEMBERS);
    auto depthPass = gl::Program::load({{GL_VERTEX_SHADER, "snow_depth.vert"}}, "layout test");
    ASSERT_TRUE(depthPass.ok()) << depthPass.error().str();
    expectLayout(*depthPass, "SnowViewBlock", sizeof(render::SnowViewBlock),
                 render::SNOW_VIEW_BLOCK_BINDING, SNOW_VIEW_MEMBERS);
}

TEST_F(UniformBlockLayout, SnowMapSamplerIsOnTheSnowMapUnit) {
    const gl::Program program = loadSnowSurfaceProgram();
    ASSERT_NE(program.id(), 0u);
    const GLint location = glGetUniformLocation(program.id(), "uSnowDepth");
    ASSERT_GE(location, 0);
    GLint unit = -1;
    glGetUniformiv(program.id(), location, &unit);
    EXPECT_EQ(unit, static_cast<GLint>(render::SNOW_MAP_UNIT));
    const GLint drift = glGetUniformLocation(program.id(), "uSnowDriftMap");
    ASSERT_GE(drift, 0);
    glGetUniformiv(program.id(), drift, &unit);
    EXPECT_EQ(unit, static_cast<GLint>(render::SNOW_DRIFT_UNIT));
}

}  // namespace
}  // namespace grass::test
