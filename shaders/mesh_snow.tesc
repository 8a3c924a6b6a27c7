#version 450 core
// Tessellation of a surface triangle under snow: each edge is cut into pieces of about
// uSnowTessPixels on screen (at most uSnowTessMax), so the displaced snow surface, its drifts and
// its soft edge at shelter show as a shape, not only as shading. An edge's level depends on its
// two corners alone, so neighbouring triangles cut a shared edge alike and no cracks open.
layout(vertices = 3) out;

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

void main() {
    tePosWorld[gl_InvocationID] = tcPosWorld[gl_InvocationID];
    teNormal[gl_InvocationID] = tcNormal[gl_InvocationID];
    teUv[gl_InvocationID] = tcUv[gl_InvocationID];
    if (gl_InvocationID == 0) {
        // Outer level i is the edge opposite corner i.
        gl_TessLevelOuter[0] = edgeLevel(1, 2);
        gl_TessLevelOuter[1] = edgeLevel(2, 0);
        gl_TessLevelOuter[2] = edgeLevel(0, 1);
        gl_TessLevelInner[0] =
            max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
    }
}
