#version 450 core
// Opaque meshes: the surface the grass grows on (uModel = identity) and the props (colliders,
// uModel = translation · uniform scale, so normals need no inverse transpose). With snow on, the
// surface rises by the snow's depth along its normal (SPEC §11, paper eq. 5) where the sky
// reaches it, with a smooth falloff at the edge of sheltered ground.
#include "snow.glsl"

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
    vec3 posWorld = (uModel * vec4(aPosition, 1.0)).xyz;
    // The exposure is taken where the ground is, before it rises.
    vPosWorld = posWorld;
    posWorld += snowDisplacement(posWorld, vNormal);
    gl_Position = uViewProj * vec4(posWorld, 1.0);
}
