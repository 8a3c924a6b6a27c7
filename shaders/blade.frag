#version 450 core
// Blade shading: the grass lighting of SPEC §10 (grass_lighting.glsl) with the blade's baked AO,
// blurred terrain normal and water, or the foundation's wrapped Lambert (uGrassLighting = 0).
// Blades are two-sided: the normal turns towards the viewer.
#include "blade_shading.glsl"
#include "grass_lighting.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec3 vUp;
in float vHeight;
flat in uint vBladeIndex;

uniform vec3 uCameraPosition;
uniform vec3 uRootColor;
uniform vec3 uTipColor;
uniform int uGrassLighting;
// Hybrid technique: the blades fade out between these camera distances (metres) while the
// billboards fade in; alpha-to-coverage turns the alpha into a per-sample dissolve. (0, 0): off.
uniform vec2 uFadeOut;

out vec4 fragColor;

void main() {
    vec3 toEye = uCameraPosition - vPosition;
    float eyeDistance = length(toEye);
    toEye = eyeDistance > 0.0 ? toEye / eyeDistance : vUp;
    // The strip's halves and the tessellated quads do not share one winding, so
    // gl_FrontFacing cannot tell the side; the view direction can.
    vec3 normal = normalize(vNormal);
    if (dot(normal, toEye) < 0.0) normal = -normal;
    vec3 albedo = mix(uRootColor, uTipColor, vHeight);
    float alpha = uFadeOut.y > 0.0 ? 1.0 - smoothstep(uFadeOut.x, uFadeOut.y, eyeDistance) : 1.0;
    if (uGrassLighting == 0) {
        // A thin blade's normal is nearly horizontal, so a high sun would leave the field
        // black; leaning it towards the surface normal lights it the way a field scatters.
        float selfShadow = mix(0.45, 1.0, vHeight);
        vec3 leaned = normalize(normal + 0.8 * vUp);
        fragColor = vec4(simpleLighting(albedo, leaned, 0.5) * selfShadow, alpha);
        return;
    }
    BladeShading baked = bladeShading[vBladeIndex];
    GrassSurface surface;
    surface.albedo = albedo;
    surface.bladeNormal = normal;
    surface.terrainNormal = normalize(vUp);
    surface.blurredNormal = baked.blurredNormalAo.xyz;
    // The AO darkens the root more than the tip: the canopy above a point is what occludes it.
    surface.ao = mix(baked.blurredNormalAo.w, 1.0, vHeight * vHeight);
    surface.water = baked.waterAge.x;
    surface.height = vHeight;
    surface.toEye = toEye;
    surface.eyeDistance = eyeDistance;
    fragColor = vec4(grassLighting(surface), alpha);
}
