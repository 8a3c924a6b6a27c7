// The grass lighting of SPEC §10 (article 003) on the CPU: a one-to-one twin of
// shaders/include/grass_lighting.glsl, function for function, same names and argument order, so
// unit tests can pin its formulas (tests/core/scene/grass_lighting_formulas_test.cpp) and a GL
// test can run the GLSL on the same inputs (tests/gl/formula_twins_gl_test.cpp). The renderer
// never calls it: a change to the GLSL must be made here too, or the GL test fails.
// Vectors are world space and unit length unless noted; the sun direction in LightingBlock is
// the way the light travels; colours linear RGB; distances metres.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/lighting_block.h"

namespace grass::core {

// GRASS_PI and GRASS_F0 in shaders/include/grass_lighting.glsl.
inline constexpr float GRASS_PI = 3.14159265358979f;
// Schlick's reflectance at normal incidence: 4 %, a dielectric (the article's 0.04).
inline constexpr float GRASS_F0 = 0.04f;

// GrassSurface of grass_lighting.glsl: what a blade's pixel knows about itself.
struct GrassSurface {
    glm::vec3 albedo{0.0f};
    glm::vec3 bladeNormal{0.0f, 1.0f, 0.0f};    // facing the viewer
    glm::vec3 terrainNormal{0.0f, 1.0f, 0.0f};  // the surface normal under the blade
    glm::vec3 blurredNormal{0.0f, 1.0f, 0.0f};  // baked, Gaussian-blurred terrain normal
    float ao = 1.0f;                            // baked grass AO, 1 = open
    float water = 0.0f;                         // baked, 1 = young and wet
    float height = 0.0f;                        // 0 root, 1 tip
    glm::vec3 toEye{0.0f, 1.0f, 0.0f};          // normalized
    float eyeDistance = 0.0f;                   // metres
    float sunVisibility = 1.0f;                 // 0 in the sun's shadow .. 1 lit (sun_shadow.h)
    bool operator==(const GrassSurface&) const = default;
};

// GGX normal distribution D(n·h) = α² / (π ((n·h)² (α² − 1) + 1)²) with α the roughness itself
// (not its square); its peak, at n·h = 1, is 1 / (π α²).
float ggxD(float nh, float alpha);

// Fresnel-Schlick on n·v (as the article writes it): F0 + (1 − F0)(1 − n·v)⁵; n·v in [0, 1].
float schlickF(float nv);

// LightingBlock::grassLighting values: the wrapped Lambert, SPEC §10 as we draw it, and the
// article's model as written (LightingModel::Simple, Grass, Article).
inline constexpr std::int32_t SIMPLE_LIGHTING = 0;
inline constexpr std::int32_t GRASS_LIGHTING = 1;
inline constexpr std::int32_t ARTICLE_LIGHTING = 2;

// The diffuse ramp: n·l ∈ [−1, 0] maps diffuseLow → diffuseMid, [0, 1] diffuseMid → diffuseHigh.
glm::vec3 diffuseRamp(float nl, const LightingBlock& lighting);

// The three lobes 0.5·D(r) + 0.3·D(r/2) + 0.2·D(r/4), r = max(water, 0.02), times F(n·v).
// Ours (article = 0): α = r, times n·l (0 where the light is behind `n`), at most 4. The
// article's (article = 1): α = r², no n·l factor, no clamp.
float specularLobes(glm::vec3 n, glm::vec3 toLight, glm::vec3 toEye, float water, float article);

// The lit colour of a grass pixel under `lighting` (the LightingBlock the GLSL reads as
// uniforms): the diffuse ramp, specular, transmission and SSS terms of SPEC §10 mixed by water;
// ours darkens it by the AO and adds the sky/ground ambient, the article's
// (lighting.grassLighting == ARTICLE_LIGHTING) does neither and lights its SSS term with the
// ramp through the SSS normal instead of our wrapped light.
glm::vec3 grassLighting(const GrassSurface& s, const LightingBlock& lighting);

}  // namespace grass::core
