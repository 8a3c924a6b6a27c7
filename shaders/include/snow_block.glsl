// The snow settings of a frame (render/snow_block.h, SnowBlock): core::SnowParams as the snow
// shaders use them, with the amount As at the scene's time and the radii in depth-map texels.
// std140, in the C++ struct's order; uploaded once a frame while snow lies.
#ifndef SNOW_BLOCK_GLSL
#define SNOW_BLOCK_GLSL

#define SNOW_BLOCK_BINDING 1

layout(std140, binding = SNOW_BLOCK_BINDING) uniform SnowBlock {
    vec3 uSnowColor;     // Cs
    float uSnowAmountM;  // As at the scene's time (accumulation and melt applied)
    vec3 uSnowUp;        // −fall direction
    float uSnowNoiseA;
    float uSnowNoiseB;
    float uSnowNoiseScaleM;
    float uSnowInclineNoise;
    float uSnowRadiusTexels;
    float uSnowBoundaryRadiusTexels;  // max(sample radius, boundary falloff / texel)
    float uSnowBiasM;
    int uSnowOctaves;
    int uSnowSamples;
    int uSnowEnabled;  // 0 or 1
    float uSnowDrift;  // core::SnowParams::drift; 0 when the snow does not drift (snowDrifts)
    float uSnowDriftReachM;
    int uSnowPad2;
    vec2 uSnowDriftDirection;  // unit, across the depth map (core::snowDriftMapDirection)
    vec2 uSnowPad3;
};

#endif
