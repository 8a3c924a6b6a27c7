#version 450 core
// Test program of tests/gl/billboard_motion_gl_test.cpp: animates star vertices with
// billboardVertexMotion of shaders/include/billboard_wind.glsl (the very function
// shaders/billboard.vert calls, reading the scene's wind sources from the same buffers), one
// vertex per invocation, so the test can compare it with core::billboardVertexMotion.
#include "billboard_wind.glsl"

layout(local_size_x = 64) in;

// core::StarVertex, 16 floats: position (3), uv (2), normal (3), object centre (3), sway, tint
// (3), object height. Read as floats: std430 would align the vec2 after the vec3.
layout(std430, binding = 0) readonly buffer VertexBuffer {
    float vertexData[];
};
// Per vertex: the moved position (xyz) and the turned normal (xyz).
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

vec3 readVec3(uint at) {
    return vec3(vertexData[at], vertexData[at + 1u], vertexData[at + 2u]);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uVertexCount)
        return;
    uint base = 16u * i;
    StarVertexMotion motion = billboardVertexMotion(
        readVec3(base), readVec3(base + 5u), readVec3(base + 8u), vertexData[base + 11u],
        vertexData[base + 15u], uWindMode, uClusterSway, uClusterWind, uTime, uWindDirection,
        uWindAmplitude, uWindFrequency, uStiffness);
    motions[2u * i] = vec4(motion.position, 0.0);
    motions[2u * i + 1u] = vec4(motion.normal, 0.0);
}
