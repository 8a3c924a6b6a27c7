// The LightingBlock of a frame (scene/lighting_block.h) from a project's settings: shared by the
// scene renderer, which uploads it, and the raw export, which writes it for runtimes.
#pragma once

#include <glm/glm.hpp>

#include "project/project.h"
#include "scene/lighting_block.h"

namespace grass::core {

// The shortest specular fade (m): a fade whose far distance is not beyond its near one is
// widened to this, a switch at `near`.
inline constexpr float MIN_SPECULAR_FADE_M = 1e-3f;

// The block of a frame lit by `sun` (a zero direction shines straight down) under the sky and
// ground colours of the render settings.
LightingBlock frameLighting(const GrassLightingDesc& lighting, const SunDesc& sun,
                            glm::vec3 skyColor, glm::vec3 groundColor);

}  // namespace grass::core
