// SnowBlock: the snow settings of a frame (SPEC §11) as the snow shaders read them, in the std140
// uniform block SnowBlock of shaders/include/snow_block.glsl: core::SnowParams with the amount As
// at the scene's time, "up" as the snow sees it and the sample radii in depth-map texels. The
// snow pass uploads it once a frame while snow lies (SnowPass::bind); the snow surface and the
// snow cull read it. Metres, linear RGB.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "snow/snow_map.h"
#include "snow/snow_params.h"

namespace grass::render {

// SNOW_BLOCK_BINDING in shaders/include/snow_block.glsl.
inline constexpr std::uint32_t SNOW_BLOCK_BINDING = 1;
// The texture unit of the snow depth map: SNOW_MAP_UNIT in shaders/include/snow.glsl.
inline constexpr std::uint32_t SNOW_MAP_UNIT = 6;
// The texture unit of the drift factors per cell: SNOW_DRIFT_UNIT in shaders/include/snow.glsl.
inline constexpr std::uint32_t SNOW_DRIFT_UNIT = 12;

// The GLSL block declares these members in this order, with a uSnow prefix (uSnowColor, ...).
struct SnowBlock {
    static constexpr std::uint32_t BINDING = SNOW_BLOCK_BINDING;
    glm::vec3 color{0.0f};  // Cs
    float amountM = 0.0f;   // As at the scene's time
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float noiseA = 0.0f;
    float noiseB = 0.0f;
    float noiseScaleM = 1.0f;
    float inclineNoise = 0.0f;
    float radiusTexels = 0.0f;
    float boundaryRadiusTexels = 0.0f;  // max(sample radius, boundary falloff / texel)
    float biasM = 0.0f;
    std::int32_t octaves = 1;
    std::int32_t samples = 1;
    std::int32_t enabled = 0;  // 0 or 1
    float drift = 0.0f;        // 0 when the snow does not drift (core::snowDrifts)
    float driftReachM = 0.0f;
    std::int32_t pad2 = 0;
    glm::vec2 driftDirection{0.0f};  // unit, across the depth map
    glm::vec2 pad3{0.0f};
};
static_assert(sizeof(SnowBlock) == 96, "SnowBlock must be six vec4 (std140)");
static_assert(offsetof(SnowBlock, up) == 16 && offsetof(SnowBlock, noiseB) == 32 &&
                  offsetof(SnowBlock, boundaryRadiusTexels) == 48 &&
                  offsetof(SnowBlock, samples) == 60 && offsetof(SnowBlock, enabled) == 64 &&
                  offsetof(SnowBlock, drift) == 68 && offsetof(SnowBlock, driftDirection) == 80,
              "SnowBlock offsets must match shaders/include/snow_block.glsl");

// The block for snow `params` lying `amountM` deep, sampled from a depth map of `view` at
// `resolution`² texels (0: no map yet, and the block says snow is off). The drift goes the way
// params.driftDirection says (the caller resolves the wind first: core::snowWithWindDrift).
SnowBlock snowBlock(const core::SnowParams& params, float amountM, const core::OrthoSnowView& view,
                    int resolution);

}  // namespace grass::render
