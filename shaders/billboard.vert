#version 450 core
// Star billboard grass objects (SPEC §8, GPU Gems 1 ch. 7): only the upper vertices (aSway = 1)
// move, with the book's sine sway and the scene's wind sources, and their normals turn with them;
// the roots stay on the surface.
#include "billboard_wind.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec3 aNormal;
layout(location = 3) in vec3 aObjectCentre;
layout(location = 4) in float aSway;
layout(location = 5) in vec3 aTint;
layout(location = 6) in float aObjectHeight;

uniform mat4 uViewProj;
uniform vec3 uCameraPos;
uniform float uTime;
// 0 per cluster (uClusterOffset, from the CPU), 1 per vertex, 2 per object.
uniform int uWindMode;
uniform vec3 uClusterOffset;
uniform vec3 uClusterWind;  // per cluster: the scene's wind at the cluster's centre (CPU)
uniform float uStiffness;   // of the blades the billboards stand for
uniform vec2 uWindDirection;
uniform float uWindAmplitude;
uniform float uWindFrequency;
uniform vec4 uFade;  // fade-in start, end, fade-out start, end (metres)
// The editor's reduced picture draws one object in n, each √n wider about its centre (the
// ground's normal through the object's centre is the axis), so the field keeps its cover.
uniform float uWidthScale = 1.0;

out vec2 vUv;
out vec3 vNormal;  // animated (listing 7-1)
out vec3 vUp;      // the object's up at rest: the ground's normal
out vec3 vPosition;
out float vFade;
out vec3 vTint;

void main() {
    const vec3 up = normalize(aNormal);
    const vec3 offset = aPosition - aObjectCentre;
    const float along = dot(offset, up);
    const vec3 position = aObjectCentre + along * up + (offset - along * up) * uWidthScale;
    StarVertexMotion motion = billboardVertexMotion(
        position, aNormal, aObjectCentre, aSway, aObjectHeight, uWindMode, uClusterOffset,
        uClusterWind, uTime, uWindDirection, uWindAmplitude, uWindFrequency, uStiffness);
    // By the object's centre, so a whole object fades together.
    vFade = billboardFade(distance(uCameraPos, aObjectCentre), uFade);
    vUv = aUv;
    vNormal = motion.normal;
    vUp = aNormal;
    vPosition = motion.position;
    vTint = aTint;
    gl_Position = uViewProj * vec4(motion.position, 1.0);
}
