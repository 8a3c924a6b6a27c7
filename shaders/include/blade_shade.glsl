// The colour of a blade point, shared by the fragment shader (per-pixel lighting, the default)
// and the vertex stages (per-vertex lighting, the article's choice; GRASS_LIGHT_PER_VERTEX): the
// grass lighting of SPEC §10 with the blade's baked AO, blurred terrain normal and water, or,
// compiled with GRASS_SIMPLE_LIGHTING (the program variant for uGrassLighting = 0), the wrapped
// Lambert: software GL runs both sides of a branch, so the model a frame does not use is not
// compiled in (nature-100k's grass pass ~3 ms). Blades are two-sided: the normal turns to the
// viewer.
#ifndef GRASS_BLADE_SHADE_GLSL
#define GRASS_BLADE_SHADE_GLSL
#include "blade_texels.glsl"
#include "grass_lighting.glsl"

uniform vec3 uCameraPosition;
uniform vec3 uRootColor;
uniform vec3 uTipColor;
// The colours of grass in poor conditions; the baked wilt (1 − b of the growth model, SPEC §9)
// blends towards them.
uniform vec3 uPoorRootColor;
uniform vec3 uPoorTipColor;
// 1: the unlit colour (RenderOptions::albedoView), to compare geometry and colour alone.
uniform int uAlbedoView;
// Snow on the tips (SPEC §11): the cull pass writes each drawn blade's tip whiteness, read only
// by the program variant with GRASS_SNOW_TIPS, which draws while snow lies (software GL runs both
// sides of a uniform branch, so a lookup merely switched off would still cost every vertex).
#ifdef GRASS_SNOW_TIPS
uniform vec3 uSnowTipColor;
#endif
// The share of the snow colour at height τ (core::bladeSnowWhiteness, SNOW_TIP_FRACTION 0.3).
float bladeSnowWhiteness(float tipSnowAmount, float tau) {
    return tipSnowAmount * smoothstep(0.7, 1.0, tau);
}

vec3 shadeBlade(vec3 position, vec3 normal, vec3 up, float height, uint bladeIndex) {
    vec3 toEye = uCameraPosition - position;
    float eyeDistance = length(toEye);
    toEye = eyeDistance > 0.0 ? toEye / eyeDistance : up;
    // The strip's halves and the tessellated quads do not share one winding, so
    // gl_FrontFacing cannot tell the side; the view direction can.
    normal = normalize(normal);
    if (dot(normal, toEye) < 0.0) normal = -normal;
    BladeShading baked = fetchShading(bladeIndex);
    vec3 albedo = mix(mix(uRootColor, uTipColor, height), mix(uPoorRootColor, uPoorTipColor, height),
                      baked.waterAge.z);
#ifdef GRASS_SNOW_TIPS
    // C = Fp·Cs + (1 − Fp)·Cn (paper eq. 3) with the tip's whiteness for Fp.
    float white = bladeSnowWhiteness(fetchTipSnow(bladeIndex), height);
    albedo = white * uSnowTipColor + (1.0 - white) * albedo;
#endif
    if (uAlbedoView != 0) return albedo;
    float sun = sunVisibility(position);
#ifdef GRASS_SIMPLE_LIGHTING
    // A thin blade's normal is nearly horizontal, so a high sun would leave the field
    // black; leaning it towards the surface normal lights it the way a field scatters.
    float selfShadow = mix(0.45, 1.0, height);
    vec3 leaned = normalize(normal + 0.8 * up);
    return simpleLightingShadowed(albedo, leaned, 0.5, sun) * selfShadow;
#else
    GrassSurface surface;
    surface.albedo = albedo;
    surface.bladeNormal = normal;
    surface.terrainNormal = normalize(up);
    surface.blurredNormal = baked.blurredNormalAo.xyz;
    // The AO darkens the root more than the tip: the canopy above a point is what occludes it.
    surface.ao = mix(baked.blurredNormalAo.w, 1.0, height * height);
    surface.water = baked.waterAge.x;
    surface.height = height;
    surface.toEye = toEye;
    surface.eyeDistance = eyeDistance;
    surface.sunVisibility = sun;
    return grassLighting(surface);
#endif
}
#endif
