#version 450 core
// Star billboards: alpha-to-coverage with depth test and write (no sorting needed for the
// coverage itself); the distance fade scales alpha, so fading objects dissolve sample by sample.
#include "grass_lighting.glsl"

layout(binding = 0) uniform sampler2D uGrassTexture;
// 0.02 with multisampling; 0.5 without, where alpha-to-coverage does nothing and this cutoff
// alone shapes the blades.
uniform float uAlphaCutoff;

in vec2 vUv;
in vec3 vNormal;
in vec3 vUp;
in vec3 vPosition;
in float vFade;
in vec3 vTint;  // the near field's growth colour here (1: the texture's own)

// The blades' lighting (SPEC §10, uGrassLighting 1; 0: the wrapped Lambert) so billboards and
// blades match where they cross-fade: the object stands for many blades, so it takes the field's
// mean AO and water (uFieldWater of the lighting block) and the surface normal for both blade
// and terrain normals.
uniform vec3 uCameraPosition;
uniform float uFieldAo;

out vec4 fragColor;

void main() {
    vec4 texel = texture(uGrassTexture, vUv);
    texel.rgb *= vTint;
    // Sharpen alpha to about one pixel of ramp at every mip level: minified, mipmapped alpha
    // otherwise goes soft and thin, and alpha-to-coverage turns soft alpha into dither.
    float alpha = texel.a;
    float width = fwidth(alpha);
    if (width > 1.0e-4)
        alpha = clamp((alpha - 0.5) / width + 0.5, 0.0, 1.0);
    alpha *= vFade;
    if (alpha < uAlphaCutoff)
        discard;
    // Two-sided, and the normal is the object's up on both sides (GPU Gems ch. 7): no flip. It
    // leans with the wind (the animated normal); the ground's stays the object's rest up.
    vec3 normal = normalize(vNormal);
    vec3 up = normalize(vUp);
    float sun = sunVisibility(vPosition);
    if (uGrassLighting == 0) {
        fragColor = vec4(simpleLightingShadowed(texel.rgb, normal, 0.3, sun), alpha);
        return;
    }
    vec3 toEye = uCameraPosition - vPosition;
    float eyeDistance = length(toEye);
    float height = clamp(1.0 - vUv.y, 0.0, 1.0);  // v = 0 at the top of the quads
    GrassSurface surface;
    surface.albedo = texel.rgb;
    surface.bladeNormal = normal;
    surface.terrainNormal = up;
    surface.blurredNormal = up;
    surface.ao = mix(uFieldAo, 1.0, height * height);
    surface.water = uFieldWater;
    surface.height = height;
    surface.toEye = eyeDistance > 0.0 ? toEye / eyeDistance : up;
    surface.eyeDistance = eyeDistance;
    surface.sunVisibility = sun;
    fragColor = vec4(grassLighting(surface), alpha);
}
