#version 450 core
// Opaque meshes under snow (SPEC §11): world-space corners for the tessellation stages
// (mesh_snow.tesc / .tese), which subdivide by screen size and raise the surface by the snow.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;  // translation · uniform scale: normals need no inverse transpose

out vec3 tcPosWorld;
out vec3 tcNormal;
out vec2 tcUv;

void main() {
    tcPosWorld = (uModel * vec4(aPosition, 1.0)).xyz;
    tcNormal = mat3(uModel) * aNormal;
    tcUv = aUv;
}
