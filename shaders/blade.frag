#version 450 core
// Blade shading (blade_shade.glsl): per pixel, or the colour the vertex stage lit
// (GRASS_LIGHT_PER_VERTEX, a program variant).
#include "blade_shade.glsl"

in vec3 vPosition;
in vec3 vNormal;
flat in vec3 vUp;
in float vHeight;
#ifdef GRASS_LIGHT_PER_VERTEX
in vec3 vLitColor;
#endif
flat in uint vBladeIndex;

// Hybrid technique: the blades fade out between these camera distances (metres) while the
// billboards fade in; alpha-to-coverage turns the alpha into a per-sample dissolve. (0, 0): off.
#ifdef GRASS_BLADE_FADE_OUT
// The hybrid's cross-fade (x, y: start and end distance): blades dissolve by alpha-to-coverage
// as the billboards come in. A program variant, so other blades carry no position to the
// fragments for it (software GL runs both sides of a uniform branch).
uniform vec2 uFadeOut;
#endif

out vec4 fragColor;

void main() {
#ifdef GRASS_BLADE_FADE_OUT
    float alpha = uFadeOut.y > 0.0
                      ? 1.0 - smoothstep(uFadeOut.x, uFadeOut.y, distance(uCameraPosition, vPosition))
                      : 1.0;
#else
    float alpha = 1.0;
#endif
#ifdef GRASS_LIGHT_PER_VERTEX
    vec3 color = vLitColor;
#else
    vec3 color = shadeBlade(vPosition, vNormal, vUp, vHeight, vBladeIndex);
#endif
    fragColor = vec4(color, alpha);
}
