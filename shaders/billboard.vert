#version 450 core
// Star billboard grass objects (SPEC §8, GPU Gems 1 ch. 7): only the upper vertices (sway = 1)
// move, with the book's sine sway and the scene's wind sources, and their normals turn with them;
// the roots stay on the surface.
#include "billboard_wind.glsl"
#include "star_vertex.glsl"

// One instance a star (core::StarInstance), its 12 vertices made from gl_VertexID.
layout(location = 0) in vec4 aCentreHeight;
layout(location = 1) in vec4 aUpTintR;
layout(location = 2) in vec4 aAcross0TintG;
layout(location = 3) in vec4 aAcross90TintB;

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
// The editor's reduced picture draws one object in n, each √n wider about its centre, so the
// field keeps its cover.
uniform float uWidthScale = 1.0;

out vec2 vUv;
out vec3 vNormal;  // animated (listing 7-1)
out vec3 vUp;      // the object's up at rest: the ground's normal
out vec3 vPosition;
out float vFade;
out vec3 vTint;

void main() {
    const StarVertex star = starVertex(aCentreHeight, aUpTintR, aAcross0TintG, aAcross90TintB,
                                       gl_VertexID, uWidthScale);
    StarVertexMotion motion = billboardVertexMotion(
        star.position, star.up, star.centre, star.sway, star.height, uWindMode, uClusterOffset,
        uClusterWind, uTime, uWindDirection, uWindAmplitude, uWindFrequency, uStiffness);
    // By the object's centre, so a whole object fades together.
    vFade = billboardFade(distance(uCameraPos, star.centre), uFade);
    vUv = star.uv;
    vNormal = motion.normal;
    vUp = star.up;
    vPosition = motion.position;
    vTint = star.tint;
    gl_Position = uViewProj * vec4(motion.position, 1.0);
}
