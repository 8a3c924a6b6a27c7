#include "render/snow_block.h"

#include <algorithm>

#include "snow/snow.h"
#include "snow/snow_drift.h"

namespace grass::render {

SnowBlock snowBlock(const core::SnowParams& params, float amountM, const core::OrthoSnowView& view,
                    int resolution) {
    SnowBlock block;
    block.enabled = params.enabled != 0u && resolution > 0 ? 1 : 0;
    block.amountM = amountM;
    block.color = params.snowColor;
    block.up = core::snowUp(params);
    block.octaves = params.noiseOctaves;
    block.noiseA = params.noiseAmplitude;
    block.noiseB = params.noiseFrequency;
    block.noiseScaleM = params.noiseScaleM;
    block.inclineNoise = params.inclineNoise;
    block.samples = params.samples;
    block.radiusTexels = params.sampleRadiusTexels;
    const float texelM = view.sizeM / float(std::max(resolution, 1));
    block.boundaryRadiusTexels =
        std::max(params.sampleRadiusTexels, params.boundaryFalloffM / texelM);
    block.biasM = params.depthBiasM;
    const glm::vec2 driftDirection = core::snowDriftMapDirection(view, params.driftDirection);
    if (block.enabled != 0 && core::snowDrifts(params, driftDirection)) {
        block.drift = params.drift;
        block.driftReachM = params.driftReachM;
        block.driftDirection = driftDirection;
    }
    return block;
}

}  // namespace grass::render
