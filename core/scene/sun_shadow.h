// Sun shadows (issue 30 item 11): the surface and the colliders shade the grass, the ground and
// the colliders. The sun's depth map is the snow's machinery pointed along the light: an
// orthographic view covering the casters (core/snow/snow_map.h), rendered by the snow depth
// program; shaders/include/sun_shadow.glsl looks it up with the same 2×2 bilinear
// percentage-closer filter as sunVisibility here, its CPU twin. Shadow is the sun's share only:
// the sky's ambient still reaches a shaded blade. World space, metres.
#pragma once

#include "project/project.h"
#include "scene/lighting_block.h"
#include "snow/snow_map.h"

namespace grass::core {

struct Scene;

// The sun's view over the surface and the colliders where they stand at timeS: the snow map's
// view (sceneSnowView) looking along the light.
OrthoSnowView sceneSunView(const Scene& scene, const SunDesc& sun, float timeS);

// The CPU twin of the sun's depth map: the snow's reference rasteriser along the light.
SnowDepthMap sceneSunDepthMap(const Scene& scene, const SunDesc& sun, float timeS);

// How far below the nearest caster a point must lie to be in shadow: two texels of the map
// along the light, so a surface never shades itself by the rounding of its own depth (acne),
// while a blade a few centimetres under a rock is still shaded.
float sunShadowBiasM(const OrthoSnowView& view, int resolution);

// Turns the block's shadows on with the sun's view (the lighting shaders then read the map
// bound on SUN_SHADOW_UNIT).
void enableSunShadows(LightingBlock& block, const OrthoSnowView& view, int resolution);

// The sun's share reaching `p`, 0 (in shadow) to 1 (lit): the map's four texels around p, each
// lit where p's depth minus the bias is not beyond the texel's nearest caster, weighted
// bilinearly. 1 outside the map.
float sunVisibility(const SnowDepthMap& map, glm::vec3 p, float biasM);

}  // namespace grass::core
