#include "scene/frame_lighting.h"

#include <algorithm>

#include "scene/grass_lighting_formulas.h"

namespace grass::core {

LightingBlock frameLighting(const GrassLightingDesc& lighting, const SunDesc& sun,
                            glm::vec3 skyColor, glm::vec3 groundColor) {
    LightingBlock block;
    block.sunDirection = glm::length(sun.direction) > 0.0f ? glm::normalize(sun.direction)
                                                           : glm::vec3(0.0f, -1.0f, 0.0f);
    block.sunColor = sun.color * sun.intensity;
    block.skyColor = skyColor;
    block.groundColor = groundColor;
    block.grassLighting = lighting.model == LightingModel::Grass     ? GRASS_LIGHTING
                          : lighting.model == LightingModel::Article ? ARTICLE_LIGHTING
                                                                     : SIMPLE_LIGHTING;
    block.diffuseLow = lighting.diffuseLow;
    block.diffuseMid = lighting.diffuseMid;
    block.diffuseHigh = lighting.diffuseHigh;
    block.terrainNormalWeight = lighting.terrainNormalWeight;
    block.specular = lighting.specular;
    // GLSL's smoothstep is undefined for near ≥ far (and the project reader takes any two
    // non-negative distances): an empty or reversed fade switches the specular on at `near`, the
    // same on every GPU and in the C++ twin.
    const float nearM = lighting.specularFadeM.x;
    block.specularFadeM = {nearM, std::max(lighting.specularFadeM.y, nearM + MIN_SPECULAR_FADE_M)};
    block.transmission = lighting.transmission;
    block.transmissionDistortion = lighting.transmissionDistortion;
    block.transmissionPower = lighting.transmissionPower;
    block.sss = lighting.sss;
    block.sssIntensity = lighting.sssIntensity;
    block.fieldWater = 0.5f * (lighting.water.x + lighting.water.y);
    return block;
}

}  // namespace grass::core
