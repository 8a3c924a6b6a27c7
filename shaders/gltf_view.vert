#version 450 core
// What a stock glTF viewer draws (core/mesh/gltf_view.h): world-space triangles with their
// normals and the colour baseColorFactor × COLOR_0 × _COLOR_0.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor;

uniform mat4 uViewProj;

out vec3 vNormal;
out vec4 vColor;

void main() {
    vNormal = aNormal;
    vColor = aColor;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
