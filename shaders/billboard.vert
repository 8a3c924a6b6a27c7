#version 450 core
// Star billboard grass objects (SPEC §8, GPU Gems 1 ch. 7): only the upper vertices (aSway = 1)
// move with the wind; the roots stay on the surface.
#include "billboard_wind.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec3 aNormal;
layout(location = 3) in vec3 aObjectCentre;
layout(location = 4) in float aSway;

uniform mat4 uViewProj;
uniform vec3 uCameraPos;
uniform float uTime;
// 0 per cluster (uClusterOffset, from the CPU), 1 per vertex, 2 per object.
uniform int uWindMode;
uniform vec3 uClusterOffset;
uniform vec2 uWindDirection;
uniform float uWindAmplitude;
uniform float uWindFrequency;
uniform vec4 uFade;  // fade-in start, end, fade-out start, end (metres)

out vec2 vUv;
out vec3 vNormal;
out vec3 vPosition;
out float vFade;

void main() {
    vec3 offset = uClusterOffset;
    if (uWindMode == 1)
        offset = billboardWindOffset(aPosition, uTime, uWindDirection, uWindAmplitude,
                                     uWindFrequency);
    else if (uWindMode == 2)
        offset = billboardWindOffset(aObjectCentre, uTime, uWindDirection, uWindAmplitude,
                                     uWindFrequency);
    vec3 position = aPosition + aSway * offset;
    // By the object's centre, so a whole object fades together.
    vFade = billboardFade(distance(uCameraPos, aObjectCentre), uFade);
    vUv = aUv;
    vNormal = aNormal;
    vPosition = position;
    gl_Position = uViewProj * vec4(position, 1.0);
}
