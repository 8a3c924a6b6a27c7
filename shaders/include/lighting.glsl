// Simple lighting for the foundation (issue 3): wrapped Lambert from the sun plus a sky/ground
// hemisphere ambient. The grass lighting model of SPEC §10 replaces this for blades later.
// sunVisibility (0 in the sun's shadow .. 1 lit) scales the sun's term only.
#include "lighting_block.glsl"
#include "sun_shadow.glsl"

vec3 simpleLightingShadowed(vec3 albedo, vec3 normal, float wrap, float sunVisibility) {
    vec3 toSun = -uSunDirection;
    float diffuse = max((dot(normal, toSun) + wrap) / (1.0 + wrap), 0.0) * sunVisibility;
    vec3 ambient = mix(uGroundColor, uSkyColor, 0.5 + 0.5 * normal.y) * 0.45;
    return albedo * (diffuse * uSunColor + ambient);
}

vec3 simpleLighting(vec3 albedo, vec3 normal, float wrap) {
    return simpleLightingShadowed(albedo, normal, wrap, 1.0);
}
