#include "snow/snow.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

namespace {

// Snow lies only when switched on and there is some: the guard that makes As = 0 exact.
bool snowLies(const SnowParams& params) {
    return params.enabled != 0u && params.amountM > 0.0f;
}

float smoothstep01(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

glm::vec3 snowUp(const SnowParams& params) {
    return -glm::normalize(params.fallDirection);
}

float snowNoiseAt(const SnowParams& params, glm::vec3 posWorld) {
    return fractalNoise(posWorld / params.noiseScaleM, params.noiseOctaves, params.noiseAmplitude,
                        params.noiseFrequency);
}

float inclineCoefficient(glm::vec3 normal, glm::vec3 up, float noise, float inclineNoise) {
    const float cosPhi = glm::dot(glm::normalize(normal), up);
    if (cosPhi <= 0.0f)
        return 0.0f;
    return std::clamp(cosPhi + inclineNoise * noise, 0.0f, 1.0f);
}

float snowCoverage(float Fe, float Fi) {
    return Fe * Fi;
}

glm::vec3 snowColor(glm::vec3 Cn, glm::vec3 Cs, float Fp) {
    return Fp * Cs + (1.0f - Fp) * Cn;
}

float snowBoundaryExposure(const SnowDepthMap& map, glm::vec3 posWorld, glm::vec3 normal,
                           const SnowParams& params) {
    const float radius =
        std::max(params.sampleRadiusTexels, params.boundaryFalloffM / map.texelSizeM());
    const float Fe =
        exposureCoefficient(map, posWorld, normal, params.samples, radius, params.depthBiasM);
    return smoothstep01(0.0f, 1.0f, Fe);
}

float snowHeightNoise(float noise) {
    return 0.5f + 0.5f * noise;
}

glm::vec3 snowDisplacement(glm::vec3 posWorld, glm::vec3 /*normal*/, float Fe,
                           const SnowParams& params, float drift) {
    if (!snowLies(params))
        return glm::vec3(0.0f);
    const float Zn = snowHeightNoise(snowNoiseAt(params, posWorld));
    return params.amountM * (Fe * drift) * Zn * snowUp(params);
}

float snowDepthAt(glm::vec3 posWorld, float Fe, const SnowParams& params, float drift) {
    if (!snowLies(params))
        return 0.0f;
    return params.amountM * (Fe * drift) * snowHeightNoise(snowNoiseAt(params, posWorld));
}

bool bladeBuriedBySnow(float heightM, float snowDepthM) {
    return heightM < snowDepthM;
}

float bladeTipSnow(float tipFe, const SnowParams& params) {
    return snowLies(params) ? std::clamp(tipFe, 0.0f, 1.0f) : 0.0f;
}

float bladeSnowWhiteness(float tipSnow, float tau) {
    return tipSnow * smoothstep01(1.0f - SNOW_TIP_FRACTION, 1.0f, tau);
}

float snowLoadGravity(const SnowParams& params, float snowDepthM, float Fe) {
    if (params.enabled == 0u)
        return 0.0f;
    return params.loadGravity * std::max(snowDepthM, 0.0f) * Fe;
}

float snowAmountAt(const SnowParams& params, float timeS) {
    const float t = std::max(timeS, 0.0f);
    const float amount = params.amountM + (params.accumulationRate - params.meltRate) * t;
    return std::clamp(amount, 0.0f, params.maxAmountM);
}

SnowShade shadeSnow(const SnowParams& params, glm::vec3 posWorld, glm::vec3 normal, float Fe,
                    float FeBoundary, glm::vec3 Cn, float drift) {
    SnowShade shade;
    shade.color = Cn;
    if (!snowLies(params))
        return shade;
    const float noise = snowNoiseAt(params, posWorld);
    shade.Fi = inclineCoefficient(normal, snowUp(params), noise, params.inclineNoise);
    shade.Fp = snowCoverage(Fe, shade.Fi) * std::min(drift, 1.0f);
    shade.color = snowColor(Cn, params.snowColor, shade.Fp);
    shade.displacement =
        params.amountM * (FeBoundary * drift) * snowHeightNoise(noise) * snowUp(params);
    return shade;
}

}  // namespace grass::core
