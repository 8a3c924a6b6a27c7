// Snow accumulation (SPEC §11, paper 004), the GLSL mirror of core/snow: the same PCG hash,
// Perlin and fractal noise, jittered exposure Fe over the orthographic depth map, incline Fi,
// coverage Fp = Fe·Fi, colour and displacement. Every function keeps its C++ name and order of
// operations, so tests can hold GPU and CPU together.

#include "snow_block.glsl"
#include "snow_view_block.glsl"

// The depth map: depth / depthRange, cleared to 1 (nothing above). SNOW_MAP_UNIT in
// render/snow_block.h.
#define SNOW_MAP_UNIT 6
layout(binding = SNOW_MAP_UNIT) uniform sampler2D uSnowDepth;

const float SNOW_GOLDEN_ANGLE = 2.39996323;
const float SNOW_MAX_SLOPE_BIAS = 4.0;
const float SNOW_HALF_TEXEL_DIAGONAL = 0.70710678;
const float SNOW_MAX_TEXEL_COORD = 1048576.0;

uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

float hashToUnit(uint h) {
    return float(h >> 8u) * (1.0 / 16777216.0);
}

float snowFade(float t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

float snowGradient(uint hash, float x, float y, float z) {
    uint h = hash >> 28u;
    float u = h < 8u ? x : y;
    float v = h < 4u ? y : (h == 12u || h == 14u ? x : z);
    return ((h & 1u) == 0u ? u : -u) + ((h & 2u) == 0u ? v : -v);
}

float snowCornerGradient(ivec3 cell, ivec3 corner, vec3 f) {
    uvec3 key = uvec3(cell + corner);
    vec3 d = f - vec3(corner);
    return snowGradient(pcg3d(key).x, d.x, d.y, d.z);
}

float perlinNoise3(vec3 p) {
    vec3 base = floor(p);
    ivec3 cell = ivec3(base);
    vec3 f = p - base;
    float n000 = snowCornerGradient(cell, ivec3(0, 0, 0), f);
    float n100 = snowCornerGradient(cell, ivec3(1, 0, 0), f);
    float n010 = snowCornerGradient(cell, ivec3(0, 1, 0), f);
    float n110 = snowCornerGradient(cell, ivec3(1, 1, 0), f);
    float n001 = snowCornerGradient(cell, ivec3(0, 0, 1), f);
    float n101 = snowCornerGradient(cell, ivec3(1, 0, 1), f);
    float n011 = snowCornerGradient(cell, ivec3(0, 1, 1), f);
    float n111 = snowCornerGradient(cell, ivec3(1, 1, 1), f);
    float u = snowFade(f.x), v = snowFade(f.y), w = snowFade(f.z);
    float x00 = n000 + u * (n100 - n000), x10 = n010 + u * (n110 - n010);
    float x01 = n001 + u * (n101 - n001), x11 = n011 + u * (n111 - n011);
    float y0 = x00 + v * (x10 - x00), y1 = x01 + v * (x11 - x01);
    return clamp(y0 + w * (y1 - y0), -1.0, 1.0);
}

float fractalNoise(vec3 p, int octaves, float amplitudeA, float frequencyB) {
    const vec3 OCTAVE_SHIFT = vec3(0.3183099, 0.5772157, 0.7071068);
    float sum = 0.0, norm = 0.0, amplitude = 1.0, frequency = 1.0;
    for (int i = 0; i < 8; ++i) {  // constant bound: llvmpipe mis-compiles variable loop bounds
        if (i >= octaves)
            break;
        sum += amplitude * perlinNoise3(frequency * p + float(i) * OCTAVE_SHIFT);
        norm += amplitude;
        amplitude *= amplitudeA;
        frequency *= frequencyB;
    }
    return sum / norm;
}

float snowNoiseAt(vec3 posWorld) {
    return fractalNoise(posWorld / uSnowNoiseScaleM, uSnowOctaves, uSnowNoiseA, uSnowNoiseB);
}

vec3 snowMapCoords(vec3 posWorld) {
    vec3 d = posWorld - uSnowOrigin;
    return vec3(dot(d, uSnowRight) / uSnowSizeM, dot(d, uSnowUpAxis) / uSnowSizeM,
                dot(d, uSnowForward));
}

int snowTexelIndex(float t) {
    return int(floor(clamp(t, -SNOW_MAX_TEXEL_COORD, SNOW_MAX_TEXEL_COORD)));
}

float snowStoredDepth(int ix, int iy) {
    if (ix < 0 || iy < 0 || ix >= uSnowResolution || iy >= uSnowResolution)
        return 3.0e38;
    return texelFetch(uSnowDepth, ivec2(ix, iy), 0).r * uSnowDepthRangeM;
}

// Fe (paper eq. 1): the share of jittered samples around the point where nothing stands
// between the point and the sky (core::exposureCoefficient).
float exposureCoefficient(vec3 posWorld, vec3 normal, int samples, float radiusTexels) {
    vec3 c = snowMapCoords(posWorld);
    float res = float(uSnowResolution);
    vec2 centre = vec2(c.x * res, c.y * res);
    uint ix = uint(snowTexelIndex(centre.x));
    uint iy = uint(snowTexelIndex(centre.y));
    float cosPhi = dot(normalize(normal), -uSnowForward);
    float sinPhi = sqrt(max(0.0, 1.0 - cosPhi * cosPhi));
    float slope = sinPhi < SNOW_MAX_SLOPE_BIAS * cosPhi ? sinPhi / cosPhi : SNOW_MAX_SLOPE_BIAS;
    float texelM = uSnowSizeM / res;
    float twoPi = 6.2831853;
    float n = float(samples);
    float rotation = twoPi * hashToUnit(pcg3d(uvec3(ix, iy, 0u)).x);
    int exposed = 0;
    for (int k = 0; k < 32; ++k) {  // constant bound, as above
        if (k >= samples)
            break;
        uvec3 h = pcg3d(uvec3(ix, iy, uint(k) + 1u));
        float fk = float(k);
        float r = radiusTexels * sqrt((fk + hashToUnit(h.x)) / n);
        float angle = rotation + fk * SNOW_GOLDEN_ANGLE + (hashToUnit(h.y) - 0.5) * (twoPi / n);
        vec2 s = centre + r * vec2(cos(angle), sin(angle));
        float stored = snowStoredDepth(snowTexelIndex(s.x), snowTexelIndex(s.y));
        float bias = uSnowBiasM + (r + SNOW_HALF_TEXEL_DIAGONAL) * texelM * slope;
        if (stored >= c.z - bias)
            ++exposed;
    }
    return float(exposed) / n;
}

// Fi (paper eq. 2): cos φ plus the noise, none on vertical faces and overhangs.
float inclineCoefficient(vec3 normal, vec3 up, float noise, float inclineNoise) {
    float cosPhi = dot(normalize(normal), up);
    if (cosPhi <= 0.0)
        return 0.0;
    return clamp(cosPhi + inclineNoise * noise, 0.0, 1.0);
}

bool snowLies() {
    return uSnowEnabled != 0 && uSnowAmountM > 0.0;
}

// The smooth boundary of the displacement: exposure over the falloff disc, smoothstepped.
float snowBoundaryExposure(vec3 posWorld, vec3 normal) {
    return smoothstep(0.0, 1.0,
                      exposureCoefficient(posWorld, normal, uSnowSamples, uSnowBoundaryRadiusTexels));
}

// Vn = V + As·Fe·Zn·N (paper eq. 5), Zn = 0.5 + 0.5·noise ≥ 0; `noise` is snowNoiseAt(posWorld).
vec3 snowDisplacement(vec3 posWorld, vec3 normal, float noise) {
    if (!snowLies())
        return vec3(0.0);
    float Zn = 0.5 + 0.5 * noise;
    return uSnowAmountM * snowBoundaryExposure(posWorld, normal) * Zn * normalize(normal);
}

vec3 snowDisplacement(vec3 posWorld, vec3 normal) {
    return snowDisplacement(posWorld, normal, snowNoiseAt(posWorld));
}

// Local snow depth in metres, As·Fe·Zn with the boundary's Fe (core::snowDepthAt).
float snowDepthAt(vec3 posWorld, vec3 normal) {
    return length(snowDisplacement(posWorld, normal));
}

bool bladeBuriedBySnow(float heightM, float snowDepthM) {
    return heightM < snowDepthM;
}

float bladeTipSnow(float tipFe) {
    return snowLies() ? clamp(tipFe, 0.0, 1.0) : 0.0;
}

// (Fp, Fe, Fi) from the exposure Fe at a surface point: Fp = Fe·Fi (paper eq. 3); zero where no
// snow lies. `noise` is snowNoiseAt at the point, or its value interpolated from the tessellated
// surface's vertices: the noise is smooth at the scale of a few pixels (projects/winter: Fp moves
// by at most 3/255, by 0.0002 on average, docs/snow.md).
vec3 snowCoverageFromExposure(vec3 normal, float noise, float Fe) {
    if (!snowLies())
        return vec3(0.0);
    float Fi = inclineCoefficient(normal, uSnowUp, noise, uSnowInclineNoise);
    return vec3(Fe * Fi, Fe, Fi);
}

// The same with Fe measured at the point (per pixel in the opaque pass).
vec3 snowCoverageTerms(vec3 posWorld, vec3 normal, float noise) {
    if (!snowLies())
        return vec3(0.0);
    return snowCoverageFromExposure(
        normal, noise, exposureCoefficient(posWorld, normal, uSnowSamples, uSnowRadiusTexels));
}

// C = Fp·Cs + (1 − Fp)·Cn (paper eq. 3); exactly Cn at Fp = 0.
vec3 snowShade(float Fp, vec3 Cn) {
    return Fp * uSnowColor + (1.0 - Fp) * Cn;
}
