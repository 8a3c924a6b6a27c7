// LightingBlock: the lighting of a frame as the shaders read it, in the std140 uniform block
// LightingBlock of shaders/include/lighting_block.glsl: the sun and the sky/ground ambient of
// lighting.glsl (the wrapped Lambert) and the grass lighting of SPEC §10 (grass_lighting.glsl).
// The scene renderer uploads it once a frame and every program that lights a surface reads it;
// the raw export writes its values (core/export/runtime_block.h) and the reference runtime
// (editor/runtime) uploads them as they are. GL-free and GLM-only, so both can share it.
// Colours linear RGB; the sun direction is the way the light travels, unit length; metres.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace grass::core {

// LIGHTING_BLOCK_BINDING in shaders/include/lighting_block.glsl.
inline constexpr std::uint32_t LIGHTING_BLOCK_BINDING = 0;

// Members pair a vec3 with a float so that std140 puts them where C++ does; the GLSL block
// declares them in this order under these names with a `u` prefix (uSunDirection, ...).
struct LightingBlock {
    static constexpr std::uint32_t BINDING = LIGHTING_BLOCK_BINDING;
    glm::vec3 sunDirection{0.0f, -1.0f, 0.0f};
    float terrainNormalWeight = 0.0f;
    glm::vec3 sunColor{0.0f};  // colour × intensity
    float specular = 0.0f;
    glm::vec3 skyColor{0.0f};
    float transmission = 0.0f;
    glm::vec3 groundColor{0.0f};
    float transmissionDistortion = 0.0f;
    glm::vec3 diffuseLow{0.0f};
    float transmissionPower = 0.0f;
    glm::vec3 diffuseMid{0.0f};
    float sss = 0.0f;
    glm::vec3 diffuseHigh{0.0f};
    float sssIntensity = 0.0f;
    glm::vec2 specularFadeM{0.0f};
    // 1: the grass lighting of SPEC §10; 0: the wrapped Lambert.
    std::int32_t grassLighting = 0;
    // The water of a field's mean blade, for billboards and stem sets, which stand for many
    // blades: the middle of GrassLightingDesc::water.
    float fieldWater = 0.0f;
    // Sun shadows (scene/sun_shadow.h): the sun's depth-map view (OrthoSnowView) and the bias;
    // sunShadows 0: off, nothing is looked up (and runtimes, which draw none, leave it so).
    glm::vec3 sunShadowOrigin{0.0f};
    float sunShadowSizeM = 1.0f;
    glm::vec3 sunShadowRight{1.0f, 0.0f, 0.0f};
    float sunShadowDepthRangeM = 1.0f;
    glm::vec3 sunShadowUp{0.0f, 0.0f, 1.0f};
    std::int32_t sunShadows = 0;
    glm::vec3 sunShadowForward{0.0f, -1.0f, 0.0f};
    float sunShadowBiasM = 0.0f;
    bool operator==(const LightingBlock&) const = default;
};
static_assert(sizeof(LightingBlock) == 192, "LightingBlock must be twelve vec4 (std140)");
static_assert(offsetof(LightingBlock, sunColor) == 16 && offsetof(LightingBlock, skyColor) == 32 &&
                  offsetof(LightingBlock, groundColor) == 48 &&
                  offsetof(LightingBlock, diffuseLow) == 64 &&
                  offsetof(LightingBlock, diffuseHigh) == 96 &&
                  offsetof(LightingBlock, specularFadeM) == 112 &&
                  offsetof(LightingBlock, grassLighting) == 120 &&
                  offsetof(LightingBlock, fieldWater) == 124 &&
                  offsetof(LightingBlock, sunShadowOrigin) == 128 &&
                  offsetof(LightingBlock, sunShadows) == 172 &&
                  offsetof(LightingBlock, sunShadowBiasM) == 188,
              "LightingBlock offsets must match shaders/include/lighting_block.glsl");

}  // namespace grass::core
