// Sun shadows (issue 30 item 11): how much of the sun reaches a point, from the sun's depth map
// of the surface and the colliders (SceneRenderer's sun pass, the snow depth program along the
// light). The same 2×2 bilinear percentage-closer filter as core::sunVisibility, its C++ twin
// (core/scene/sun_shadow.h). Compiled in only with GRASS_SUN_SHADOWS (the renderer's shadowed
// program variants): software GL runs both sides of a uniform branch, so a lookup merely skipped
// would still cost a frame without shadows (docs/rendering.md measured 2-5 %). Without the
// define, and with uSunShadows 0, every point is lit.
#ifndef SUN_SHADOW_GLSL
#define SUN_SHADOW_GLSL

#include "lighting_block.glsl"

#ifdef GRASS_SUN_SHADOWS
// SUN_SHADOW_UNIT (render/scene_renderer.h); depth in [0, 1] of uSunShadowDepthRangeM.
layout(binding = 13) uniform sampler2D uSunShadowMap;

float sunShadowLit(ivec2 texel, ivec2 size, float depthM) {
    ivec2 at = clamp(texel, ivec2(0), size - 1);
    return depthM <= texelFetch(uSunShadowMap, at, 0).r * uSunShadowDepthRangeM ? 1.0 : 0.0;
}

float sunVisibility(vec3 p) {
    if (uSunShadows == 0)
        return 1.0;
    vec3 d = p - uSunShadowOrigin;
    vec2 uv = vec2(dot(d, uSunShadowRight), dot(d, uSunShadowUp)) / uSunShadowSizeM;
    if (!(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0))
        return 1.0;
    ivec2 size = textureSize(uSunShadowMap, 0);
    vec2 t = uv * vec2(size) - 0.5;
    vec2 cell = floor(t);
    vec2 f = t - cell;
    ivec2 i = ivec2(cell);
    float depthM = dot(d, uSunShadowForward) - uSunShadowBiasM;
    float l00 = sunShadowLit(i, size, depthM);
    float l10 = sunShadowLit(i + ivec2(1, 0), size, depthM);
    float l01 = sunShadowLit(i + ivec2(0, 1), size, depthM);
    float l11 = sunShadowLit(i + ivec2(1, 1), size, depthM);
    float bottom = l00 + (l10 - l00) * f.x;
    float top = l01 + (l11 - l01) * f.x;
    return bottom + (top - bottom) * f.y;
}
#else
float sunVisibility(vec3 p) {
    return 1.0;
}
#endif

#endif
