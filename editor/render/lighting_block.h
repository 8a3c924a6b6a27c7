// lightingBlock(): a frame's LightingBlock (core/scene/lighting_block.h, the std140 block of
// shaders/include/lighting_block.glsl) from the project's sun, grass lighting, sky and ground.
// The scene renderer uploads it once a frame (gl::UniformBlock).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/frame_lighting.h"

namespace grass::render {

// The block itself is core's (core/scene/lighting_block.h): the raw export writes it and the
// reference runtime (editor/runtime) uploads it without this library.
using core::LightingBlock;
inline constexpr std::uint32_t LIGHTING_BLOCK_BINDING = core::LIGHTING_BLOCK_BINDING;

// core::frameLighting under the name the renderer has always called it.
inline LightingBlock lightingBlock(const core::GrassLightingDesc& lighting,
                                   const core::SunDesc& sun, glm::vec3 skyColor,
                                   glm::vec3 groundColor) {
    return core::frameLighting(lighting, sun, skyColor, groundColor);
}

}  // namespace grass::render
