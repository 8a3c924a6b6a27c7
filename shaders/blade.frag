#version 450 core
// Blade shading for the foundation: colour from root to tip, darker near the root (the
// field shadows itself), two-sided normals flipped towards the viewer.
#include "lighting.glsl"

in vec3 vPosition;
in vec3 vNormal;
in float vHeight;

uniform vec3 uRootColor;
uniform vec3 uTipColor;

out vec4 fragColor;

void main() {
    vec3 normal = normalize(gl_FrontFacing ? vNormal : -vNormal);
    vec3 albedo = mix(uRootColor, uTipColor, vHeight);
    float selfShadow = mix(0.45, 1.0, vHeight);
    fragColor = vec4(simpleLighting(albedo, normal, 0.5) * selfShadow, 1.0);
}
