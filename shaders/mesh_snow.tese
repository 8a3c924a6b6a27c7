#version 450 core
// The snow surface (paper eq. 5): each tessellated point rises along the interpolated normal by
// As·Fe·Zn, Fe taken over the boundary falloff (snow.glsl), so the snow swells into drifts and
// fades smoothly at the edge of sheltered ground. The fragment shader (mesh.frag) shades the
// ground position under the snow, where the exposure was measured, with the snow's noise of the
// vertex (smooth across a triangle of a few pixels; the fragment stage would repeat its four
// octaves of hashed Perlin noise for every pixel).
layout(triangles, equal_spacing, ccw) in;
#include "snow.glsl"

in vec3 tePosWorld[];
in vec3 teNormal[];
in vec2 teUv[];

uniform mat4 uViewProj;

out vec3 vNormal;
out vec2 vUv;
out vec3 vPosWorld;
out float vSnowNoise;
out float vSnowDrift;
#ifdef GRASS_SNOW_EXPOSURE_PER_VERTEX
// The exposure of the coverage (not the displacement's wider boundary disc) at the vertex, for
// the fragments to interpolate (RenderOptions::snowExposurePerVertex).
out float vSnowExposure;
#endif

void main() {
    vec3 b = gl_TessCoord;
    vec3 posWorld = b.x * tePosWorld[0] + b.y * tePosWorld[1] + b.z * tePosWorld[2];
    vec3 normal = b.x * teNormal[0] + b.y * teNormal[1] + b.z * teNormal[2];
    vNormal = normal;
    vUv = b.x * teUv[0] + b.y * teUv[1] + b.z * teUv[2];
    vPosWorld = posWorld;
    vSnowNoise = snowNoiseAt(posWorld);
    vSnowDrift = snowDriftAt(posWorld);
#ifdef GRASS_SNOW_EXPOSURE_PER_VERTEX
    // The coverage's exposure and the displacement's, over the same samples at once.
    vec2 Fe = exposureCoefficients(posWorld, normal, uSnowSamples,
                                   vec2(uSnowRadiusTexels, uSnowBoundaryRadiusTexels));
    vSnowExposure = Fe.x;
    vec3 displacement =
        snowDisplacementFromExposure(snowBoundaryExposureOf(Fe.y), vSnowNoise, vSnowDrift);
#else
    vec3 displacement = snowDisplacement(posWorld, normal, vSnowNoise, vSnowDrift);
#endif
    gl_Position = uViewProj * vec4(posWorld + displacement, 1.0);
}
