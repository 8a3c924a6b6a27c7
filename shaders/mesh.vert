#version 450 core
// Opaque meshes: the surface the grass grows on (uModel = identity) and the props (colliders,
// uModel = translation · uniform scale, so normals need no inverse transpose). Snow-free: under
// snow the surface goes through mesh_snow.vert and the tessellation stages instead.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uViewProj;
uniform mat4 uModel;

out vec3 vNormal;
out vec2 vUv;
out vec3 vPosWorld;

void main() {
    vNormal = mat3(uModel) * aNormal;
    vUv = aUv;
    vPosWorld = (uModel * vec4(aPosition, 1.0)).xyz;
    gl_Position = uViewProj * vec4(vPosWorld, 1.0);
}
