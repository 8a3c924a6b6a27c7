#version 450 core
#include "lighting.glsl"
#include "snow.glsl"

in vec3 vNormal;
in vec2 vUv;
in vec3 vPosWorld;

uniform vec3 uAlbedo;
// Draws (Fp, Fe, Fi) unlit instead of the shaded surface: docs/snow.md measures the snow mask's
// error against a reference with it.
uniform bool uSnowCoverageView;

out vec4 fragColor;

void main() {
    // Two-sided: glTF meshes may be open shells seen from behind (a Möbius strip always is).
    if (uSnowCoverageView) {
        fragColor = vec4(snowCoverageTerms(vPosWorld, vNormal), 1.0);
        return;
    }
    vec3 normal = normalize(gl_FrontFacing ? vNormal : -vNormal);
    // Snow settles on the side that faces the sky, whichever side the camera sees.
    vec3 albedo = snowShade(vPosWorld, vNormal, uAlbedo);
    fragColor = vec4(simpleLighting(albedo, normal, 0.2), 1.0);
}
