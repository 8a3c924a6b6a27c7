// Simple lighting for the foundation (issue 3): wrapped Lambert from the sun plus a sky/ground
// hemisphere ambient. The grass lighting model of SPEC §10 replaces this for blades later.
#include "lighting_block.glsl"

vec3 simpleLighting(vec3 albedo, vec3 normal, float wrap) {
    vec3 toSun = -uSunDirection;
    float diffuse = max((dot(normal, toSun) + wrap) / (1.0 + wrap), 0.0);
    vec3 ambient = mix(uGroundColor, uSkyColor, 0.5 + 0.5 * normal.y) * 0.45;
    return albedo * (diffuse * uSunColor + ambient);
}
