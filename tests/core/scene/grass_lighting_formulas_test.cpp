// The grass lighting formulas of SPEC §10 (core/scene/grass_lighting_formulas.h, the twin of
// shaders/include/grass_lighting.glsl) pinned to hand-computed values: a wrong constant, a
// swapped term or a dropped factor changes one of these numbers. Each grassLighting test turns
// every term off but the one it pins (zero colours and weights), so the sum is that term alone.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/grass_lighting_formulas.h"

namespace grass::core {
namespace {

constexpr float PI = std::numbers::pi_v<float>;
// Float arithmetic over a few normalizations and a pow: a few ULP of values near 1.
constexpr float TOLERANCE = 1e-5f;

const glm::vec3 UP{0.0f, 1.0f, 0.0f};
// specularLobes' last argument: our lobes, or the article's.
constexpr float OURS = 0.0f;
constexpr float ARTICLE = 1.0f;

// A unit vector in the xy plane at `degrees` from +y towards +x.
glm::vec3 tilted(float degrees) {
    const float rad = glm::radians(degrees);
    return {std::sin(rad), std::cos(rad), 0.0f};
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = TOLERANCE) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// White sun straight down (towards -y), every other term and colour off. The specular fade
// spans 0 to 1 m (smoothstep's edges must differ, or 0/0 makes the specular term NaN even at
// zero strength).
LightingBlock sunOnly() {
    LightingBlock block;
    block.sunDirection = -UP;
    block.sunColor = glm::vec3(1.0f);
    block.specularFadeM = {0.0f, 1.0f};
    return block;
}

// A white, open (AO 1), dry blade facing up at the root, seen from above, 2 m away (the
// specular fully faded in).
GrassSurface whiteSurface() {
    GrassSurface s;
    s.albedo = glm::vec3(1.0f);
    s.toEye = UP;
    s.eyeDistance = 2.0f;
    return s;
}

// The three lobes' sum Σ wᵢ·D(n·h, rᵢ) with r = (1, 1/2, 1/4) (water 1) when the light, the eye
// and so the half vector all lie `degrees` from the normal: specularLobes / (F(n·v)·n·l).
float lobeSumAt(float degrees) {
    const glm::vec3 dir = tilted(degrees);
    const float cosine = dir.y;
    return specularLobes(UP, dir, dir, 1.0f, OURS) / (schlickF(cosine) * cosine);
}

TEST(GrassLightingFormulas, SchlickIsF0FacingAndOneAtGrazing) {
    EXPECT_NEAR(schlickF(1.0f), 0.04f, 1e-7f);
    EXPECT_NEAR(schlickF(0.0f), 1.0f, 1e-7f);
    // (1 − 0.5)⁵ = 1/32: the fifth power, not the fourth (1/16).
    EXPECT_NEAR(schlickF(0.5f), 0.04f + 0.96f / 32.0f, 1e-7f);
    EXPECT_EQ(GRASS_F0, 0.04f);
}

// n·v of two unit vectors can round just above 1; GLSL's pow of the negative base 1 − n·v would
// be undefined (a NaN pixel on some GPUs), so the base is clamped: F0 exactly.
TEST(GrassLightingFormulas, SchlickStaysF0WhenNvRoundsAboveOne) {
    EXPECT_EQ(schlickF(1.0f + 1e-6f), GRASS_F0);
    EXPECT_EQ(schlickF(1.5f), GRASS_F0);
}

TEST(GrassLightingFormulas, GgxPeakIsOneOverPiAlphaSquared) {
    // α is the roughness itself: D(1, α) = 1/(π α²), not 1/(π α⁴).
    EXPECT_NEAR(ggxD(1.0f, 0.5f), 1.0f / (PI * 0.25f), 1e-5f);
    EXPECT_NEAR(ggxD(1.0f, 0.2f), 1.0f / (PI * 0.04f), 1e-4f);
    // Away from the peak: a² / (π (n·h² (a² − 1) + 1)²); at n·h = 0.5, α = 0.5: 0.25/(π·0.8125²).
    EXPECT_NEAR(ggxD(0.5f, 0.5f), 0.25f / (PI * 0.8125f * 0.8125f), 1e-6f);
    // At n·h = 0 the distribution is α²/π.
    EXPECT_NEAR(ggxD(0.0f, 0.5f), 0.25f / PI, 1e-6f);
}

TEST(GrassLightingFormulas, LobesAtThePeakSumTheirWeightedPeaks) {
    // Light = eye = normal: n·h = n·v = n·l = 1, F = F0. Water 1 → roughness 1, 1/2, 1/4, peaks
    // 1/π, 4/π, 16/π: 0.5·1 + 0.3·4 + 0.2·16 = 4.9 (any two weights swapped gives another sum).
    EXPECT_NEAR(specularLobes(UP, UP, UP, 1.0f, OURS), 0.04f * 4.9f / PI, 1e-6f);
}

TEST(GrassLightingFormulas, LobeWeightsAreHalfThreeTenthsAndOneFifth) {
    // The sum Σ wᵢ·D(n·h, r/2^i) at three angles is a 3×3 linear system in the weights, each
    // column one lobe's own response (its D): solving it recovers every weight on its own.
    const float degrees[3] = {0.0f, 40.0f, 70.0f};
    glm::mat3 response(0.0f);  // response[lobe][angle]: column-major, a column per lobe
    glm::vec3 sums(0.0f);
    for (int a = 0; a < 3; ++a) {
        const float nh = std::cos(glm::radians(degrees[a]));
        for (int lobe = 0; lobe < 3; ++lobe)
            response[lobe][a] = ggxD(nh, std::ldexp(1.0f, -lobe));
        sums[a] = lobeSumAt(degrees[a]);
    }
    const glm::vec3 weights = glm::inverse(response) * sums;
    EXPECT_NEAR(weights[0], 0.5f, 1e-4f);
    EXPECT_NEAR(weights[1], 0.3f, 1e-4f);
    EXPECT_NEAR(weights[2], 0.2f, 1e-4f);
    EXPECT_NEAR(weights[0] + weights[1] + weights[2], 1.0f, 1e-4f);
}

TEST(GrassLightingFormulas, LobesScaleWithFresnelOnNvAndWithNl) {
    // Light and eye 60° from the normal: n·h = n·v = n·l = 1/2, F = 0.04 + 0.96/32.
    const glm::vec3 dir = tilted(60.0f);
    const float d = 0.5f * ggxD(0.5f, 1.0f) + 0.3f * ggxD(0.5f, 0.5f) + 0.2f * ggxD(0.5f, 0.25f);
    EXPECT_NEAR(specularLobes(UP, dir, dir, 1.0f, OURS), d * (0.04f + 0.96f / 32.0f) * 0.5f, 1e-6f);
}

TEST(GrassLightingFormulas, FresnelTakesNvNotNl) {
    // Light along the normal, eye 60° off: n·l = 1, n·v = 1/2, the half vector 30° off. Schlick
    // on n·l would give F0 = 0.04 here, on n·v it gives 0.04 + 0.96/32.
    const glm::vec3 eye = tilted(60.0f);
    const float nh = std::cos(glm::radians(30.0f));
    const float d = 0.5f * ggxD(nh, 1.0f) + 0.3f * ggxD(nh, 0.5f) + 0.2f * ggxD(nh, 0.25f);
    EXPECT_NEAR(specularLobes(UP, UP, eye, 1.0f, OURS), d * (0.04f + 0.96f / 32.0f), 1e-6f);
}

TEST(GrassLightingFormulas, LobesVanishWithTheLightBehind) {
    EXPECT_EQ(specularLobes(UP, -UP, UP, 1.0f, OURS), 0.0f);
    EXPECT_EQ(specularLobes(UP, glm::vec3(1.0f, 0.0f, 0.0f), UP, 1.0f, OURS), 0.0f);
}

TEST(GrassLightingFormulas, LobesAreClampedAtFour) {
    // Dry (roughness 0.02): the peak is 0.04·4.9/(π·0.02²) ≈ 156, clamped to 4.
    EXPECT_EQ(specularLobes(UP, UP, UP, 0.0f, OURS), 4.0f);
}

TEST(GrassLightingFormulas, RoughnessIsFlooredAtTwoHundredths) {
    // 30° off the peak the dry lobes are far below the clamp: water 0 and 0.01 act as 0.02.
    const glm::vec3 dir = tilted(30.0f);
    const float nh = dir.y;
    const float expected =
        (0.5f * ggxD(nh, 0.02f) + 0.3f * ggxD(nh, 0.01f) + 0.2f * ggxD(nh, 0.005f)) * schlickF(nh) *
        nh;
    EXPECT_NEAR(specularLobes(UP, dir, dir, 0.0f, OURS), expected, 1e-9f);
    EXPECT_NEAR(specularLobes(UP, dir, dir, 0.01f, OURS), expected, 1e-9f);
    EXPECT_NEAR(expected, 4.1415e-5f, 1e-8f);
}

TEST(GrassLightingFormulas, DiffuseRampRunsLowMidHigh) {
    LightingBlock block = sunOnly();
    block.diffuseLow = {1.0f, 0.0f, 0.0f};
    block.diffuseMid = {0.0f, 1.0f, 0.0f};
    block.diffuseHigh = {0.0f, 0.0f, 1.0f};
    GrassSurface s = whiteSurface();
    const auto rampAt = [&](float degrees) {
        s.bladeNormal = tilted(degrees);
        return grassLighting(s, block);
    };
    // N·L = 1, 1/2, 0, −1/2, −1.
    expectNear(rampAt(0.0f), {0.0f, 0.0f, 1.0f});
    expectNear(rampAt(60.0f), {0.0f, 0.5f, 0.5f});
    expectNear(rampAt(90.0f), {0.0f, 1.0f, 0.0f});
    expectNear(rampAt(120.0f), {0.5f, 0.5f, 0.0f});
    expectNear(rampAt(180.0f), {1.0f, 0.0f, 0.0f});
}

TEST(GrassLightingFormulas, DiffuseNormalLeansTowardsTheSssNormal) {
    LightingBlock block = sunOnly();
    block.diffuseMid = {0.0f, 1.0f, 0.0f};
    block.diffuseHigh = {0.0f, 0.0f, 1.0f};
    GrassSurface s = whiteSurface();
    s.bladeNormal = {1.0f, 0.0f, 0.0f};  // N·L = 0 alone: mid
    s.terrainNormal = {0.0f, 0.0f, 1.0f};
    s.blurredNormal = UP;  // N·L = 1
    // Halfway from the blade normal to the blurred normal (SSS intensity 1): 45°, N·L = √½.
    block.sssIntensity = 1.0f;
    block.terrainNormalWeight = 0.5f;
    const float nl = std::sqrt(0.5f);
    expectNear(grassLighting(s, block), {0.0f, 1.0f - nl, nl});
    // SSS intensity 0 takes the terrain normal, which the sun grazes: mid again.
    block.sssIntensity = 0.0f;
    expectNear(grassLighting(s, block), {0.0f, 1.0f, 0.0f});
}

TEST(GrassLightingFormulas, DiffuseIsAlbedoTimesSunTimesRamp) {
    LightingBlock block = sunOnly();
    block.sunColor = {2.0f, 1.0f, 0.5f};
    block.diffuseHigh = glm::vec3(0.5f);
    GrassSurface s = whiteSurface();
    s.albedo = {0.2f, 0.4f, 0.8f};
    expectNear(grassLighting(s, block), {0.2f, 0.2f, 0.2f});
}

TEST(GrassLightingFormulas, SpecularFadesInWithEyeDistance) {
    LightingBlock block = sunOnly();
    block.specular = 1.0f;
    block.specularFadeM = {10.0f, 30.0f};
    GrassSurface s = whiteSurface();
    s.water = 1.0f;  // the wet mix: specular alone, no diffuse
    // Blade and terrain normals both up, at the tip: twice the lobes at the peak.
    s.height = 1.0f;
    const float full = 2.0f * specularLobes(UP, UP, UP, 1.0f, OURS);
    s.eyeDistance = 10.0f;
    expectNear(grassLighting(s, block), glm::vec3(0.0f));
    s.eyeDistance = 20.0f;  // smoothstep's middle
    expectNear(grassLighting(s, block), glm::vec3(0.5f * full));
    s.eyeDistance = 25.0f;  // t = 3/4: 3t² − 2t³ = 27/32
    expectNear(grassLighting(s, block), glm::vec3(27.0f / 32.0f * full));
    s.eyeDistance = 30.0f;
    expectNear(grassLighting(s, block), glm::vec3(full));
}

TEST(GrassLightingFormulas, BladeSpecularGrowsWithHeightTerrainSpecularDoesNot) {
    LightingBlock block = sunOnly();
    block.specular = 2.0f;
    block.sunColor = {1.0f, 0.5f, 0.25f};
    GrassSurface s = whiteSurface();
    s.water = 1.0f;
    const float peak = specularLobes(UP, UP, UP, 1.0f, OURS);
    // The terrain normal faces away from the sun: only the blade's lobes light it, × height.
    s.terrainNormal = -UP;
    s.height = 0.25f;
    expectNear(grassLighting(s, block), 2.0f * 0.25f * peak * block.sunColor);
    // The blade normal faces away: the terrain's lobes alone, whatever the height.
    s.terrainNormal = UP;
    s.bladeNormal = -UP;
    s.toEye = UP;
    expectNear(grassLighting(s, block), 2.0f * peak * block.sunColor);
}

TEST(GrassLightingFormulas, TransmissionFollowsTheArticleTimesAo) {
    // The sun behind the blade (toLight (0, 0.6, −0.8)), the blade normal +z, distortion 1/2:
    // fakeN = −normalize((0, 0.3, 0.1)); the eye at (0, −0.6, 0.8) sees dot(fakeN, V) = 1/√10,
    // and power 2 makes it 1/10.
    LightingBlock block = sunOnly();
    block.sunDirection = {0.0f, -0.6f, 0.8f};
    block.transmission = 3.0f;
    block.transmissionDistortion = 0.5f;
    block.transmissionPower = 2.0f;
    GrassSurface s = whiteSurface();
    s.albedo = {0.5f, 1.0f, 0.25f};
    s.bladeNormal = {0.0f, 0.0f, 1.0f};
    s.terrainNormal = {0.0f, 0.0f, 1.0f};  // lit by no lobe from this eye: n·l < 0
    s.blurredNormal = s.terrainNormal;
    s.toEye = {0.0f, -0.6f, 0.8f};
    s.water = 1.0f;
    // T = 3 · 0.1 · ao · albedo, then lit · mix(1, ao, 1/2): dense grass (low AO) passes less.
    s.ao = 1.0f;
    expectNear(grassLighting(s, block), 0.3f * s.albedo);
    s.ao = 0.5f;
    expectNear(grassLighting(s, block), 0.3f * 0.5f * 0.75f * s.albedo);
    s.ao = 0.0f;
    expectNear(grassLighting(s, block), glm::vec3(0.0f));
}

TEST(GrassLightingFormulas, SssIsWrappedLightSquaredOnTheSssNormal) {
    LightingBlock block = sunOnly();
    block.sss = 2.0f;
    block.sssIntensity = 0.0f;  // the terrain normal itself
    GrassSurface s = whiteSurface();
    s.water = 1.0f;
    s.bladeNormal = {0.0f, 0.0f, 1.0f};  // no blade lobe, no diffuse at water 1
    s.toEye = {0.0f, 0.0f, 1.0f};
    // Terrain normal 60° from the sun: wrapped = 0.5 + 0.5·0.5 = 3/4, squared 9/16. The sun
    // also lights the terrain lobes; keep them out of sight with specular 0.
    s.terrainNormal = tilted(60.0f);
    expectNear(grassLighting(s, block), glm::vec3(2.0f * 9.0f / 16.0f));
    // Facing away: wrapped 0.
    s.terrainNormal = -UP;
    expectNear(grassLighting(s, block), glm::vec3(0.0f));
}

TEST(GrassLightingFormulas, WaterMixesDiffuseTowardsTheWetTerms) {
    LightingBlock block = sunOnly();
    block.diffuseHigh = glm::vec3(1.0f);
    block.sss = 1.0f;  // wrapped = 1 with the terrain normal up
    GrassSurface s = whiteSurface();
    s.bladeNormal = UP;
    s.water = 0.0f;
    expectNear(grassLighting(s, block), glm::vec3(1.0f));
    block.sss = 0.25f;
    s.water = 0.5f;
    expectNear(grassLighting(s, block), glm::vec3(0.5f + 0.5f * 0.25f));
    s.water = 1.0f;
    expectNear(grassLighting(s, block), glm::vec3(0.25f));
}

TEST(GrassLightingFormulas, AmbientBlendsGroundToSkyTimesAoAndAoDarkensLit) {
    LightingBlock block = sunOnly();
    block.sunColor = glm::vec3(0.0f);  // no sun: ambient alone
    block.skyColor = {1.0f, 0.0f, 0.0f};
    block.groundColor = {0.0f, 1.0f, 0.0f};
    GrassSurface s = whiteSurface();
    s.ao = 0.5f;
    // SSS normal up: sky alone, × 0.35 × albedo × AO.
    expectNear(grassLighting(s, block), {0.35f * 0.5f, 0.0f, 0.0f});
    // Sideways: half sky, half ground.
    s.terrainNormal = {1.0f, 0.0f, 0.0f};
    expectNear(grassLighting(s, block), {0.35f * 0.25f, 0.35f * 0.25f, 0.0f});
    // The sun back, the ambient off: lit × mix(1, AO, 1/2).
    block = sunOnly();
    block.diffuseHigh = glm::vec3(1.0f);
    s.terrainNormal = UP;
    s.ao = 0.2f;
    expectNear(grassLighting(s, block), glm::vec3(0.6f));
}

// The article's model (LightingModel::Article): what ours adds is gone.
LightingBlock articleOnly() {
    LightingBlock block = sunOnly();
    block.grassLighting = ARTICLE_LIGHTING;
    return block;
}

TEST(GrassLightingFormulas, ArticleLobesUseRoughnessSquaredWithoutNlOrClamp) {
    // Light, eye and normal together (n·h = n·v = n·l = 1), water 1: α = 1, 1/4, 1/16, so
    // D = 1/(π α²) is 1/π, 16/π, 256/π, and F = F0.
    const float expected = 0.04f * (0.5f + 0.3f * 16.0f + 0.2f * 256.0f) / PI;
    EXPECT_NEAR(specularLobes(UP, UP, UP, 1.0f, ARTICLE), expected, 1e-5f);
    // Ours at the same angle: α = 1, 1/2, 1/4 and the clamp at 4 does not bind: 4.9·F0/π.
    EXPECT_NEAR(specularLobes(UP, UP, UP, 1.0f, OURS), 0.04f * 4.9f / PI, 1e-6f);
    // Light behind the normal: ours is 0, the article's lobes stay (no n·l factor). With the eye
    // and the light mirrored about the plane, h lies in it: n·h = 0, D = α²/π per lobe.
    const glm::vec3 eye = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
    const glm::vec3 light = glm::normalize(glm::vec3(-1.0f, -1.0f, 0.0f));
    EXPECT_EQ(specularLobes(UP, light, eye, 1.0f, OURS), 0.0f);
    const float schlick = 0.04f + 0.96f;  // n·v clamped to 0
    const float flat = (0.5f * 1.0f + 0.3f * (1.0f / 16.0f) + 0.2f * (1.0f / 256.0f)) / PI;
    EXPECT_NEAR(specularLobes(UP, light, eye, 1.0f, ARTICLE), schlick * flat, 1e-5f);
    // Dry blades: r = 0.02, α = 4e-4, 1e-4, 2.5e-5: peaks of millions, unclamped.
    EXPECT_GT(specularLobes(UP, UP, UP, 0.0f, ARTICLE), 1e5f);
    EXPECT_EQ(specularLobes(UP, UP, UP, 0.0f, OURS), 4.0f);
}

TEST(GrassLightingFormulas, ArticleHasNoAmbientAndNoAoOnTheLitColour) {
    LightingBlock block = articleOnly();
    block.skyColor = {1.0f, 0.0f, 0.0f};
    block.groundColor = {0.0f, 1.0f, 0.0f};
    block.diffuseHigh = glm::vec3(1.0f);
    GrassSurface s = whiteSurface();
    s.bladeNormal = UP;
    s.ao = 0.2f;
    // Diffuse alone, at full strength whatever the AO (ours: 0.6 plus the ambient).
    expectNear(grassLighting(s, block), glm::vec3(1.0f));
    block.sunColor = glm::vec3(0.0f);
    expectNear(grassLighting(s, block), glm::vec3(0.0f));
}

TEST(GrassLightingFormulas, ArticleSssIsTheRampLitThroughTheSssNormal) {
    LightingBlock block = articleOnly();
    block.sss = 2.0f;
    block.sssIntensity = 0.0f;  // the terrain normal itself
    block.diffuseLow = {1.0f, 0.0f, 0.0f};
    block.diffuseMid = {0.0f, 1.0f, 0.0f};
    block.diffuseHigh = {0.0f, 0.0f, 1.0f};
    GrassSurface s = whiteSurface();
    s.water = 1.0f;                      // the wet terms alone
    s.bladeNormal = {0.0f, 0.0f, 1.0f};  // the sun grazes it: no blade lobe
    s.toEye = {0.0f, 0.0f, 1.0f};
    block.specular = 0.0f;
    // Terrain normal 60° from the sun: the ramp at n·l = ½, mid to high halfway.
    s.terrainNormal = tilted(60.0f);
    expectNear(grassLighting(s, block), 2.0f * glm::vec3(0.0f, 0.5f, 0.5f));
    // Facing away (n·l = −1): the low colour, where our wrapped light gives 0.
    s.terrainNormal = -UP;
    expectNear(grassLighting(s, block), 2.0f * glm::vec3(1.0f, 0.0f, 0.0f));
    block.grassLighting = GRASS_LIGHTING;
    block.diffuseLow = block.diffuseMid = block.diffuseHigh = glm::vec3(0.0f);
    block.skyColor = block.groundColor = glm::vec3(0.0f);
    expectNear(grassLighting(s, block), glm::vec3(0.0f));
}

}  // namespace
}  // namespace grass::core
