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

// The drift factor D per cell of SNOW_DRIFT_CELL_TEXELS² depth-map texels (R32F), written by
// snow_drift.comp while the snow drifts. SNOW_DRIFT_UNIT in render/snow_block.h.
#define SNOW_DRIFT_UNIT 12
layout(binding = SNOW_DRIFT_UNIT) uniform sampler2D uSnowDriftMap;
const int SNOW_DRIFT_CELL_TEXELS = 8;
const int SNOW_DRIFT_SAMPLES = 16;
const float SNOW_DRIFT_REFERENCE_RAD = 0.34906585;

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

// The jittered disc of Fe's samples about a point (exposureCoefficient): its centre on the depth
// map, the point's depth, the slope term of the bias, and the disc's rotation; one sample's
// direction and share of the radius (snowDiscSample); whether the surface stored where a
// sample at `radiusTexels` lands leaves the point open to the sky (snowSampleExposed).
struct SnowDisc {
    vec3 c;
    vec2 centre;
    uint ix, iy;
    float slope, texelM, n, rotation;
};

SnowDisc snowDiscAt(vec3 posWorld, vec3 normal, int samples) {
    SnowDisc d;
    d.c = snowMapCoords(posWorld);
    float res = float(uSnowResolution);
    d.centre = vec2(d.c.x * res, d.c.y * res);
    d.ix = uint(snowTexelIndex(d.centre.x));
    d.iy = uint(snowTexelIndex(d.centre.y));
    float cosPhi = dot(normalize(normal), -uSnowForward);
    float sinPhi = sqrt(max(0.0, 1.0 - cosPhi * cosPhi));
    d.slope = sinPhi < SNOW_MAX_SLOPE_BIAS * cosPhi ? sinPhi / cosPhi : SNOW_MAX_SLOPE_BIAS;
    d.texelM = uSnowSizeM / res;
    d.n = float(samples);
    d.rotation = 6.2831853 * hashToUnit(pcg3d(uvec3(d.ix, d.iy, 0u)).x);
    return d;
}

void snowDiscSample(SnowDisc d, int k, out vec2 direction, out float share) {
    float twoPi = 6.2831853;
    uvec3 h = pcg3d(uvec3(d.ix, d.iy, uint(k) + 1u));
    float fk = float(k);
    share = sqrt((fk + hashToUnit(h.x)) / d.n);
    float angle = d.rotation + fk * SNOW_GOLDEN_ANGLE + (hashToUnit(h.y) - 0.5) * (twoPi / d.n);
    direction = vec2(cos(angle), sin(angle));
}

bool snowSampleExposed(SnowDisc d, vec2 direction, float share, float radiusTexels) {
    float r = radiusTexels * share;
    vec2 s = d.centre + r * direction;
    float stored = snowStoredDepth(snowTexelIndex(s.x), snowTexelIndex(s.y));
    float bias = uSnowBiasM + (r + SNOW_HALF_TEXEL_DIAGONAL) * d.texelM * d.slope;
    return stored >= d.c.z - bias;
}

// Fe (paper eq. 1): the share of jittered samples around the point where nothing stands
// between the point and the sky (core::exposureCoefficient).
float exposureCoefficient(vec3 posWorld, vec3 normal, int samples, float radiusTexels) {
    SnowDisc d = snowDiscAt(posWorld, normal, samples);
    int exposed = 0;
    for (int k = 0; k < 32; ++k) {  // constant bound: llvmpipe mis-compiles variable loop bounds
        if (k >= samples)
            break;
        vec2 direction;
        float share;
        snowDiscSample(d, k, direction, share);
        if (snowSampleExposed(d, direction, share, radiusTexels))
            ++exposed;
    }
    return float(exposed) / d.n;
}

// Fe over two discs of the same samples at once (the coverage's and the displacement's
// boundary disc, radii x and y): each what exposureCoefficient gives, with the samples' hashes
// and directions worked out once (mesh_snow.tese, per tessellated vertex).
vec2 exposureCoefficients(vec3 posWorld, vec3 normal, int samples, vec2 radiiTexels) {
    SnowDisc d = snowDiscAt(posWorld, normal, samples);
    ivec2 exposed = ivec2(0);
    for (int k = 0; k < 32; ++k) {  // constant bound, as above
        if (k >= samples)
            break;
        vec2 direction;
        float share;
        snowDiscSample(d, k, direction, share);
        if (snowSampleExposed(d, direction, share, radiiTexels.x))
            ++exposed.x;
        if (snowSampleExposed(d, direction, share, radiiTexels.y))
            ++exposed.y;
    }
    return vec2(exposed) / d.n;
}

// The world position of the surface texel (ix, iy) holds at `depth` (core: texelWorld).
vec3 snowTexelWorld(int ix, int iy, float depth) {
    float n = float(uSnowResolution);
    float u = (float(ix) + 0.5) / n, v = (float(iy) + 0.5) / n;
    return uSnowOrigin + uSnowRight * (u * uSnowSizeM) + uSnowUpAxis * (v * uSnowSizeM) +
           uSnowForward * depth;
}

// Sx, the maximum upwind slope at the centre of drift cell `cell` (core::snowDriftShelterAngle):
// a texel holds a surface when its depth lies inside the view's range (the cleared far plane
// and off-map samples do not).
float snowDriftShelterAngle(ivec2 cell) {
    float halfCell = 0.5 * float(SNOW_DRIFT_CELL_TEXELS);
    vec2 centre = vec2(float(cell.x * SNOW_DRIFT_CELL_TEXELS) + halfCell,
                       float(cell.y * SNOW_DRIFT_CELL_TEXELS) + halfCell);
    int hx = snowTexelIndex(centre.x), hy = snowTexelIndex(centre.y);
    float here = snowStoredDepth(hx, hy);
    if (!(here < uSnowDepthRangeM))
        return 0.0;
    vec3 herePos = snowTexelWorld(hx, hy, here);
    float texelM = uSnowSizeM / float(uSnowResolution);
    float reachTexels = uSnowDriftReachM / texelM;
    float steepest = 0.0;
    bool any = false;
    for (int k = 1; k <= SNOW_DRIFT_SAMPLES; ++k) {
        float share = float(k) / float(SNOW_DRIFT_SAMPLES);
        vec2 s = centre - uSnowDriftDirection * (reachTexels * share);
        int sx = snowTexelIndex(s.x), sy = snowTexelIndex(s.y);
        float stored = snowStoredDepth(sx, sy);
        if (!(stored < uSnowDepthRangeM))
            continue;
        // Heights along world up, distances across it (a slanted fall tilts the map plane).
        vec3 d = snowTexelWorld(sx, sy, stored) - herePos;
        float across = sqrt(d.x * d.x + d.z * d.z);
        if (!(across > 0.0))
            continue;
        float slope = d.y / across;
        steepest = any ? max(steepest, slope) : slope;
        any = true;
    }
    return any ? atan(steepest) : 0.0;
}

// D at a world point: bilinear between the four nearest cell centres (core::snowDriftFactorAt);
// exactly 1 while the snow does not drift.
float snowDriftAt(vec3 posWorld) {
    if (!(uSnowDrift > 0.0))
        return 1.0;
    vec3 c = snowMapCoords(posWorld);
    int cells = uSnowResolution / SNOW_DRIFT_CELL_TEXELS;
    float n = float(cells);
    float x = clamp(c.x * n - 0.5, 0.0, n - 1.0);
    float y = clamp(c.y * n - 0.5, 0.0, n - 1.0);
    int x0 = min(int(x), cells - 1);
    int y0 = min(int(y), cells - 1);
    int x1 = min(x0 + 1, cells - 1), y1 = min(y0 + 1, cells - 1);
    float fx = x - float(x0), fy = y - float(y0);
    float d00 = texelFetch(uSnowDriftMap, ivec2(x0, y0), 0).r;
    float d10 = texelFetch(uSnowDriftMap, ivec2(x1, y0), 0).r;
    float d01 = texelFetch(uSnowDriftMap, ivec2(x0, y1), 0).r;
    float d11 = texelFetch(uSnowDriftMap, ivec2(x1, y1), 0).r;
    float bottom = d00 + fx * (d10 - d00);
    float top = d01 + fx * (d11 - d01);
    return bottom + fy * (top - bottom);
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

// The smooth boundary of the displacement: exposure over the falloff disc, smoothstepped;
// from that exposure when the caller has it already (exposureCoefficients' y).
float snowBoundaryExposureOf(float boundaryDiscFe) {
    return smoothstep(0.0, 1.0, boundaryDiscFe);
}

float snowBoundaryExposure(vec3 posWorld, vec3 normal) {
    return snowBoundaryExposureOf(
        exposureCoefficient(posWorld, normal, uSnowSamples, uSnowBoundaryRadiusTexels));
}

// Vn = V + As·Fe·D·Zn·up (paper eq. 5 raised against the fall, not along N: core::
// snowDisplacement says why), Zn = 0.5 + 0.5·noise ≥ 0; `noise` is snowNoiseAt(posWorld),
// `FeBoundary` snowBoundaryExposure there (for a caller that has it: mesh_snow.tese).
vec3 snowDisplacementFromExposure(float FeBoundary, float noise, float drift) {
    if (!snowLies())
        return vec3(0.0);
    float Zn = 0.5 + 0.5 * noise;
    return uSnowAmountM * (FeBoundary * drift) * Zn * uSnowUp;
}

// `drift` is snowDriftAt(posWorld), for a caller that needs it anyway (mesh_snow.tese).
vec3 snowDisplacement(vec3 posWorld, vec3 normal, float noise, float drift) {
    if (!snowLies())
        return vec3(0.0);
    return snowDisplacementFromExposure(snowBoundaryExposure(posWorld, normal), noise, drift);
}

vec3 snowDisplacement(vec3 posWorld, vec3 normal, float noise) {
    return snowDisplacement(posWorld, normal, noise, snowDriftAt(posWorld));
}

vec3 snowDisplacement(vec3 posWorld, vec3 normal) {
    return snowDisplacement(posWorld, normal, snowNoiseAt(posWorld));
}

// Local snow depth in metres, As·Fe·D·Zn with the boundary's Fe (core::snowDepthAt).
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
// `drift` is D there (snowDriftAt): ground the wind scours (D < 1) shows through, Fp = Fe·Fi·D.
vec3 snowCoverageFromExposure(vec3 normal, float noise, float Fe, float drift) {
    if (!snowLies())
        return vec3(0.0);
    float Fi = inclineCoefficient(normal, uSnowUp, noise, uSnowInclineNoise);
    return vec3(Fe * Fi * min(drift, 1.0), Fe, Fi);
}

// The same with Fe measured at the point (per pixel in the opaque pass).
vec3 snowCoverageTerms(vec3 posWorld, vec3 normal, float noise, float drift) {
    if (!snowLies())
        return vec3(0.0);
    return snowCoverageFromExposure(
        normal, noise, exposureCoefficient(posWorld, normal, uSnowSamples, uSnowRadiusTexels),
        drift);
}

// C = Fp·Cs + (1 − Fp)·Cn (paper eq. 3); exactly Cn at Fp = 0.
vec3 snowShade(float Fp, vec3 Cn) {
    return Fp * uSnowColor + (1.0 - Fp) * Cn;
}
