#version 450 core
// Tessellation of a surface triangle under snow: each edge is cut into pieces of about
// uSnowTessPixels on screen (at most uSnowTessMax), so the displaced snow surface, its drifts and
// its soft edge at shelter show as a shape, not only as shading. An edge's level depends on its
// two corners alone, so neighbouring triangles cut a shared edge alike and no cracks open.
layout(vertices = 3) out;
#include "snow_block.glsl"

in vec3 tcPosWorld[];
in vec3 tcNormal[];
in vec2 tcUv[];
out vec3 tePosWorld[];
out vec3 teNormal[];
out vec2 teUv[];

uniform mat4 uViewProj;
uniform vec2 uViewportPixels;
uniform float uSnowTessPixels;
uniform float uSnowTessMax;

// Window position of a corner; points behind the eye are clamped to just in front of it, where
// an edge reaching behind the camera gets the largest level (it is close).
vec2 windowPosition(vec3 posWorld) {
    vec4 clip = uViewProj * vec4(posWorld, 1.0);
    return clip.xy / max(clip.w, 1e-3) * 0.5 * uViewportPixels;
}

float edgeLevel(int a, int b) {
    float pixels = distance(windowPosition(tcPosWorld[a]), windowPosition(tcPosWorld[b]));
    return clamp(pixels / uSnowTessPixels, 1.0, uSnowTessMax);
}

// Whether nothing of the patch can be seen: its three corners and the same raised as high as
// the snow can raise them (As·D·Zn·Fe along up with D ≤ 1 + drift, Zn and Fe ≤ 1: snow.glsl's
// snowDisplacement) all lie beyond one plane of the view's frustum. The displaced surface lies
// in the prism those six points span, and each plane bounds a half-space of clip space, so the
// test is conservative. Such a patch gets level 0, which discards it; before, a patch behind
// the camera was cut at the largest level (windowPosition clamps it close), and projects/winter
// tessellated and displaced the ground behind its camera every frame (the snow surface's pass
// 157–221 → 108–145 ms on llvmpipe, the same picture).
bool outsideTheView() {
    vec3 rise = uSnowUp * (uSnowAmountM * (1.0 + uSnowDrift));
    // Per clip plane (x, y, z below −w; x, y, z above +w): every corner lies beyond it so far.
    bvec3 allBelow = bvec3(true), allAbove = bvec3(true);
    for (int corner = 0; corner < 6; ++corner) {
        vec3 p = tcPosWorld[corner % 3] + (corner < 3 ? vec3(0.0) : rise);
        vec4 clip = uViewProj * vec4(p, 1.0);
        bvec3 below = lessThan(clip.xyz, vec3(-clip.w));
        bvec3 above = greaterThan(clip.xyz, vec3(clip.w));
        // GLSL has no && on boolean vectors.
        allBelow = bvec3(allBelow.x && below.x, allBelow.y && below.y, allBelow.z && below.z);
        allAbove = bvec3(allAbove.x && above.x, allAbove.y && above.y, allAbove.z && above.z);
    }
    return any(allBelow) || any(allAbove);
}

void main() {
    tePosWorld[gl_InvocationID] = tcPosWorld[gl_InvocationID];
    teNormal[gl_InvocationID] = tcNormal[gl_InvocationID];
    teUv[gl_InvocationID] = tcUv[gl_InvocationID];
    if (gl_InvocationID == 0) {
        if (outsideTheView()) {
            gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
            gl_TessLevelInner[0] = 0.0;
            return;
        }
        // Outer level i is the edge opposite corner i.
        gl_TessLevelOuter[0] = edgeLevel(1, 2);
        gl_TessLevelOuter[1] = edgeLevel(2, 0);
        gl_TessLevelOuter[2] = edgeLevel(0, 1);
        gl_TessLevelInner[0] =
            max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
    }
}
