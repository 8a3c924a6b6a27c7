#version 450 core
// Opaque meshes, lit. Built plain, with GRASS_MESH_TEXTURES for a textured terrain, and with
// GRASS_SNOW (textures included) for the surfaces under snow (the snow-free
// program holds no snow code at all, so a scene without snow pays nothing for it, not even on
// software rasterizers that execute both sides of a uniform branch); the snow variant also with
// GRASS_SNOW_EXPOSURE_PER_VERTEX, which takes the exposure from the tessellated vertices.
#include "lighting.glsl"
#ifdef GRASS_SNOW
#include "snow.glsl"
// Draws (Fp, Fe, Fi) unlit instead of the shaded surface: docs/snow.md measures the snow mask's
// error against a reference with it.
uniform bool uSnowCoverageView;
#endif

in vec3 vNormal;
in vec2 vUv;
in vec3 vPosWorld;
#ifdef GRASS_SNOW
in float vSnowNoise;  // snowNoiseAt(vPosWorld) at the vertices (mesh_snow.tese)
in float vSnowDrift;  // snowDriftAt(vPosWorld) at the vertices (1 without drift)
#ifdef GRASS_SNOW_EXPOSURE_PER_VERTEX
in float vSnowExposure;  // exposureCoefficient at the vertices
#endif
#endif

uniform vec3 uAlbedo;
// The unlit colour (RenderOptions::albedoView).
uniform bool uAlbedoView;
// The terrain's textures, compiled in only with GRASS_MESH_TEXTURES (the renderer's variant for a
// terrain that has one): software GL runs both sides of a uniform branch, so lookups merely
// switched off would still cost every fragment.
#ifdef GRASS_MESH_TEXTURES
// A glTF surface's own base-colour texture (core/scene/surface_look.h), sRGB decoded by the
// texture format; multiplies uAlbedo (its base colour factor), as glTF defines.
layout(binding = 5) uniform sampler2D uBaseTexture;
uniform bool uHasBaseTexture;
// The editor's map overlay (SceneRenderer::setMapOverlay): the map being painted, 0 purple to 1
// yellow, over the terrain's colour, so the artist sees what the brush writes.
layout(binding = 7) uniform sampler2D uMapOverlay;  // MAP_OVERLAY_UNIT, not the snow map's 6
uniform bool uHasMapOverlay;
#endif

out vec4 fragColor;

void main() {
    // Two-sided: glTF meshes may be open shells seen from behind (a Möbius strip always is).
    vec3 normal = normalize(gl_FrontFacing ? vNormal : -vNormal);
    vec3 albedo = uAlbedo;
#ifdef GRASS_MESH_TEXTURES
    if (uHasBaseTexture)
        albedo *= texture(uBaseTexture, vUv).rgb;
    if (uHasMapOverlay) {
        float value = clamp(texture(uMapOverlay, vUv).r, 0.0, 1.0);
        albedo = mix(albedo, mix(vec3(0.30, 0.04, 0.45), vec3(0.95, 0.85, 0.10), value), 0.7);
    }
#endif
#ifdef GRASS_SNOW
    // Snow settles on the side that faces the sky, whichever side the camera sees.
#ifdef GRASS_SNOW_EXPOSURE_PER_VERTEX
    vec3 coverage = snowCoverageFromExposure(vNormal, vSnowNoise, vSnowExposure, vSnowDrift);
#else
    vec3 coverage = snowCoverageTerms(vPosWorld, vNormal, vSnowNoise, vSnowDrift);
#endif
    if (uSnowCoverageView) {
        fragColor = vec4(coverage, 1.0);
        return;
    }
    albedo = snowShade(coverage.x, albedo);
#endif
    fragColor = vec4(uAlbedoView ? albedo
                                 : simpleLightingShadowed(albedo, normal, 0.2,
                                                          sunVisibility(vPosWorld)),
                     1.0);
}
