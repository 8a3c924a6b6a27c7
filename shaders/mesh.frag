#version 450 core
#include "lighting.glsl"

in vec3 vNormal;
in vec2 vUv;

uniform vec3 uAlbedo;

out vec4 fragColor;

void main() {
    // Two-sided: glTF meshes may be open shells seen from behind (a Möbius strip always is).
    vec3 normal = normalize(gl_FrontFacing ? vNormal : -vNormal);
    fragColor = vec4(simpleLighting(uAlbedo, normal, 0.2), 1.0);
}
