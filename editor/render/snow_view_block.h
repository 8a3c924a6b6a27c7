// SnowViewBlock: the orthographic view of the snow depth map (SPEC §11, core::OrthoSnowView) and
// the map's resolution, in the std140 uniform block SnowViewBlock of
// shaders/include/snow_view_block.glsl. The snow depth pass uploads it when it renders the map
// (SnowPass::run) and draws through it; the snow shaders that sample the map read it too. World
// space, metres.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "snow/snow_map.h"

namespace grass::render {

// SNOW_VIEW_BLOCK_BINDING in shaders/include/snow_view_block.glsl.
inline constexpr std::uint32_t SNOW_VIEW_BLOCK_BINDING = 2;

// The GLSL block declares these members in this order, with a uSnow prefix (uSnowOrigin, ...;
// the view's up axis is uSnowUpAxis, apart from the snow's up uSnowUp).
struct SnowViewBlock {
    static constexpr std::uint32_t BINDING = SNOW_VIEW_BLOCK_BINDING;
    glm::vec3 origin{0.0f};
    float sizeM = 1.0f;
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    float depthRangeM = 1.0f;
    glm::vec3 upAxis{0.0f, 0.0f, 1.0f};
    std::int32_t resolution = 0;
    glm::vec3 forward{0.0f, -1.0f, 0.0f};
    float pad = 0.0f;
};
static_assert(sizeof(SnowViewBlock) == 64, "SnowViewBlock must be four vec4 (std140)");
static_assert(offsetof(SnowViewBlock, right) == 16 && offsetof(SnowViewBlock, depthRangeM) == 28 &&
                  offsetof(SnowViewBlock, upAxis) == 32 &&
                  offsetof(SnowViewBlock, resolution) == 44 &&
                  offsetof(SnowViewBlock, forward) == 48,
              "SnowViewBlock offsets must match shaders/include/snow_view_block.glsl");

SnowViewBlock snowViewBlock(const core::OrthoSnowView& view, int resolution);

}  // namespace grass::render
