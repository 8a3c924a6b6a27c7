// The lighting of a frame (render/lighting_block.h, LightingBlock): the sun and the sky/ground
// ambient of lighting.glsl and the grass lighting of SPEC §10 (grass_lighting.glsl). std140, in
// the C++ struct's order; uploaded once a frame and read by every program that lights a surface.
#ifndef LIGHTING_BLOCK_GLSL
#define LIGHTING_BLOCK_GLSL

#define LIGHTING_BLOCK_BINDING 0

layout(std140, binding = LIGHTING_BLOCK_BINDING) uniform LightingBlock {
    vec3 uSunDirection;  // direction the light travels, normalized
    float uTerrainNormalWeight;
    vec3 uSunColor;  // colour × intensity
    float uSpecular;
    vec3 uSkyColor;
    float uTransmission;
    vec3 uGroundColor;
    float uTransmissionDistortion;
    vec3 uDiffuseLow;
    float uTransmissionPower;
    vec3 uDiffuseMid;
    float uSss;
    vec3 uDiffuseHigh;
    float uSssIntensity;
    vec2 uSpecularFade;  // metres: specular 0 at x, full at y
    int uGrassLighting;  // 1: grass lighting (SPEC §10), 0: the wrapped Lambert
    float uFieldWater;   // a field's mean water, for billboards and stem sets
    // Sun shadows (sun_shadow.glsl): the sun's depth-map view, uSunShadows 0 = off.
    vec3 uSunShadowOrigin;
    float uSunShadowSizeM;
    vec3 uSunShadowRight;
    float uSunShadowDepthRangeM;
    vec3 uSunShadowUp;
    int uSunShadows;
    vec3 uSunShadowForward;
    float uSunShadowBiasM;
};

#endif
