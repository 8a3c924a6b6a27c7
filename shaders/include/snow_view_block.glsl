// The orthographic view of the snow depth map (render/snow_view_block.h, SnowViewBlock:
// core::OrthoSnowView and the map's resolution). std140, in the C++ struct's order; uploaded by
// the depth pass, which draws through it, and read by the snow shaders that sample the map.
#ifndef SNOW_VIEW_BLOCK_GLSL
#define SNOW_VIEW_BLOCK_GLSL

#define SNOW_VIEW_BLOCK_BINDING 2

layout(std140, binding = SNOW_VIEW_BLOCK_BINDING) uniform SnowViewBlock {
    vec3 uSnowOrigin;
    float uSnowSizeM;
    vec3 uSnowRight;
    float uSnowDepthRangeM;
    vec3 uSnowUpAxis;
    int uSnowResolution;
    vec3 uSnowForward;
    float uSnowViewPad;
};

#endif
