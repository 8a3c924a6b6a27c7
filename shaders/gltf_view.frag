#version 450 core
// A stock viewer's lighting of a glTF: Lambert from the sun plus the sky/ground ambient of the
// frame's lighting block (lighting.glsl without the wrap), on the unlit colour. Double-sided as
// glTF's doubleSided materials are: a back face's normal is reversed (spec §3.9.6).
#include "lighting.glsl"

in vec3 vNormal;
in vec4 vColor;

// The unlit colour alone (what RenderOptions::albedoView draws of our field).
uniform bool uUnlit;

out vec4 fragColor;

void main() {
    vec3 normal = normalize(gl_FrontFacing ? vNormal : -vNormal);
    fragColor = vec4(uUnlit ? vColor.rgb : simpleLighting(vColor.rgb, normal, 0.0), 1.0);
}
