#include "scene/grass_lighting_formulas.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

// Each function transcribes its GLSL namesake line for line (glm::mix and glm::smoothstep are
// GLSL's definitions); keep them so, or the GL test that compares the two fails.

float ggxD(float nh, float alpha) {
    const float a2 = alpha * alpha;
    const float d = nh * nh * (a2 - 1.0f) + 1.0f;
    return a2 / (GRASS_PI * d * d);
}

float schlickF(float nv) {
    return GRASS_F0 + (1.0f - GRASS_F0) * std::pow(std::max(1.0f - nv, 0.0f), 5.0f);
}

glm::vec3 diffuseRamp(float nl, const LightingBlock& lighting) {
    return nl > 0.0f ? glm::mix(lighting.diffuseMid, lighting.diffuseHigh, nl)
                     : glm::mix(lighting.diffuseLow, lighting.diffuseMid, nl + 1.0f);
}

float specularLobes(glm::vec3 n, glm::vec3 toLight, glm::vec3 toEye, float water, float article) {
    const float cosine = glm::mix(std::max(glm::dot(n, toLight), 0.0f), 1.0f, article);
    const glm::vec3 halfway = toLight + toEye;
    const float nh = glm::dot(halfway, halfway) > 1e-12f
                         ? std::max(glm::dot(n, glm::normalize(halfway)), 0.0f)
                         : 0.0f;
    const float f = schlickF(std::max(glm::dot(n, toEye), 0.0f));
    const float r = std::max(water, 0.02f);
    const float lobes = 0.5f * ggxD(nh, glm::mix(r, r * r, article)) +
                        0.3f * ggxD(nh, glm::mix(0.5f * r, 0.25f * r * r, article)) +
                        0.2f * ggxD(nh, glm::mix(0.25f * r, 0.0625f * r * r, article));
    return std::min(lobes * f * cosine, glm::mix(4.0f, 3.0e38f, article));
}

glm::vec3 grassLighting(const GrassSurface& s, const LightingBlock& lighting) {
    const float article = lighting.grassLighting == ARTICLE_LIGHTING ? 1.0f : 0.0f;
    const glm::vec3 toLight = -lighting.sunDirection;
    const glm::vec3 sssNormal =
        glm::normalize(glm::mix(s.terrainNormal, s.blurredNormal, lighting.sssIntensity));
    const glm::vec3 diffuseNormal =
        glm::normalize(glm::mix(s.bladeNormal, sssNormal, lighting.terrainNormalWeight));

    const glm::vec3 diffuse =
        s.albedo * lighting.sunColor *
        glm::mix(lighting.diffuseLow, diffuseRamp(glm::dot(diffuseNormal, toLight), lighting),
                 s.sunVisibility);

    const float fade =
        glm::smoothstep(lighting.specularFadeM.x, lighting.specularFadeM.y, s.eyeDistance);
    const float specular =
        s.height * specularLobes(s.bladeNormal, toLight, s.toEye, s.water, article) +
        specularLobes(s.terrainNormal, toLight, s.toEye, s.water, article);
    const glm::vec3 specularTerm =
        lighting.sunColor * (lighting.specular * fade * specular * s.sunVisibility);

    const glm::vec3 fakeN =
        -glm::normalize(glm::mix(s.bladeNormal, toLight, lighting.transmissionDistortion));
    const float through =
        std::pow(std::clamp(glm::dot(fakeN, s.toEye), 0.0f, 1.0f), lighting.transmissionPower);
    const glm::vec3 transmissionTerm =
        lighting.transmission * through * s.ao * s.sunVisibility * lighting.sunColor * s.albedo;

    const float wrapped = std::clamp(0.5f + 0.5f * glm::dot(sssNormal, toLight), 0.0f, 1.0f);
    const glm::vec3 sssLight = glm::mix(glm::vec3(wrapped * wrapped),
                                        diffuseRamp(glm::dot(sssNormal, toLight), lighting), article);
    const glm::vec3 sssTerm =
        lighting.sss * sssLight * s.sunVisibility * lighting.sunColor * s.albedo;

    const glm::vec3 lit = glm::mix(diffuse, specularTerm + transmissionTerm + sssTerm, s.water);
    const glm::vec3 ambient =
        glm::mix(lighting.groundColor, lighting.skyColor, 0.5f + 0.5f * sssNormal.y) * 0.35f *
        s.albedo;
    return lit * glm::mix(1.0f, s.ao, 0.5f - 0.5f * article) + (1.0f - article) * ambient * s.ao;
}

}  // namespace grass::core
