#version 450 core
// Test program of tests/gl/billboard_motion_gl_test.cpp: makes star vertices from their
// instances with starVertex of shaders/include/star_vertex.glsl and animates them with
// billboardVertexMotion of shaders/include/billboard_wind.glsl (the very functions
// shaders/billboard.vert calls, reading the scene's wind sources from the same buffers), one
// vertex per invocation, so the test can compare them with core::starVertex and
// core::billboardVertexMotion.
#include "billboard_wind.glsl"
#include "star_vertex.glsl"

layout(local_size_x = 64) in;

// core::StarInstance, four vec4 a star; vertex i is vertex i % 12 of star i / 12, made by
// starVertex of shaders/include/star_vertex.glsl (what billboard.vert does).
layout(std430, binding = 0) readonly buffer StarBuffer {
    vec4 stars[];
};
// Per vertex: the moved position (xyz), the turned normal (xyz), the vertex at rest (xyz, sway)
// and its uv, object height and tint's green.
layout(std430, binding = 1) writeonly buffer MotionBuffer {
    vec4 motions[];
};

uniform uint uVertexCount;
uniform int uWindMode;
uniform vec3 uClusterSway;
uniform vec3 uClusterWind;
uniform float uTime;
uniform vec2 uWindDirection;
uniform float uWindAmplitude;
uniform float uWindFrequency;
uniform float uStiffness;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uVertexCount)
        return;
    uint star = 4u * (i / 12u);
    StarVertex v = starVertex(stars[star], stars[star + 1u], stars[star + 2u], stars[star + 3u],
                              int(i % 12u), 1.0);
    StarVertexMotion motion = billboardVertexMotion(
        v.position, v.up, v.centre, v.sway, v.height, uWindMode, uClusterSway, uClusterWind,
        uTime, uWindDirection, uWindAmplitude, uWindFrequency, uStiffness);
    motions[4u * i] = vec4(motion.position, 0.0);
    motions[4u * i + 1u] = vec4(motion.normal, 0.0);
    motions[4u * i + 2u] = vec4(v.position, v.sway);
    motions[4u * i + 3u] = vec4(v.uv, v.height, v.tint.g);
}
