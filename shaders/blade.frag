#version 450 core
// Blade shading for the foundation: colour from root to tip, darker near the root (the
// field shadows itself), two-sided normals flipped towards the viewer.
#include "lighting.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec3 vUp;
in float vHeight;

uniform vec3 uRootColor;
uniform vec3 uTipColor;

out vec4 fragColor;

void main() {
    // A thin blade's geometric normal is nearly horizontal, so a high sun would leave the
    // field black; leaning the (two-sided) normal towards the surface normal lights it the
    // way a field of many blades scatters light (a stand-in until SPEC §10 lighting).
    vec3 normal = normalize((gl_FrontFacing ? vNormal : -vNormal) + 0.8 * vUp);
    vec3 albedo = mix(uRootColor, uTipColor, vHeight);
    float selfShadow = mix(0.45, 1.0, vHeight);
    fragColor = vec4(simpleLighting(albedo, normal, 0.5) * selfShadow, 1.0);
}
