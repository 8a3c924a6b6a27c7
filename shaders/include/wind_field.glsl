// The wind field of core/physics/wind.cpp (SPEC §4), mirrored for the shaders that read it: the
// blades' physics (physics.glsl) and the billboards' far field (billboard.vert), so both move
// with the same sources. World space, metres, seconds. Defined once, whoever includes it first.
#ifndef GRASS_WIND_FIELD_GLSL
#define GRASS_WIND_FIELD_GLSL

// core::WindSource without its path (core::WindSourceGpu, 64 bytes): the caller evaluates each
// source's path on the CPU and passes the centre at the time it asks for.
struct WindSource {
    vec4 directionStrength;  // xyz direction, w strength
    vec4 axisRadius;         // xyz axis, w radiusM
    vec4 shape;              // coreRadiusM, wavelengthM, speedMps, gust
    uvec4 kind;              // x: core::WindKind
};

const uint WIND_KIND_DIRECTIONAL = 0u;
const uint WIND_KIND_POINT = 1u;
const uint WIND_KIND_VORTEX = 2u;

const float TWO_PI = 6.28318530717958647692;
const float NOISE_PERIOD = 65536.0;
const float DEFAULT_GUST_CELL_M = 10.0;
const float TINY_LENGTH = 1e-20;

bool isFiniteFloat(float x) {
    return !isnan(x) && !isinf(x);
}

bool isFinite(vec3 v) {
    return isFiniteFloat(v.x) && isFiniteFloat(v.y) && isFiniteFloat(v.z);
}

vec3 safeNormalize(vec3 v) {
    float len = length(v);
    return (len > TINY_LENGTH && isFiniteFloat(len)) ? v / len : vec3(0.0);
}

// Same hash as core::latticeValue (lowbias32, Wellons).
float latticeValue(uint x, uint y, uint z) {
    uint h = x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu;
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return float(h >> 8u) * (1.0 / 16777215.0);
}

float fade(float t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

float falloff(float r, float radiusM) {
    if (radiusM <= 0.0)
        return 1.0;
    if (r >= radiusM)
        return 0.0;
    float q = 1.0 - (r / radiusM) * (r / radiusM);
    return q * q;
}

float coreRamp(float r, float coreRadiusM) {
    return coreRadiusM > 0.0 ? min(r / coreRadiusM, 1.0) : 1.0;
}

// C's fmod (sign of x), not GLSL's mod (sign of y), so negative coordinates hash the same cells.
vec3 fmodPeriod(vec3 p) {
    return p - NOISE_PERIOD * trunc(p / NOISE_PERIOD);
}

float valueNoise3(vec3 p) {
    if (!isFinite(p))
        return 0.5;
    vec3 q = fmodPeriod(p);
    vec3 cell = floor(q);
    vec3 f = q - cell;
    uint ix = uint(int(cell.x) + 65536);
    uint iy = uint(int(cell.y) + 65536);
    uint iz = uint(int(cell.z) + 65536);
    float ux = fade(f.x), uy = fade(f.y), uz = fade(f.z);
    float zs[2];
    for (uint dz = 0u; dz < 2u; ++dz) {
        float c00 = latticeValue(ix, iy, iz + dz), c10 = latticeValue(ix + 1u, iy, iz + dz);
        float c01 = latticeValue(ix, iy + 1u, iz + dz);
        float c11 = latticeValue(ix + 1u, iy + 1u, iz + dz);
        float y0 = c00 + (c10 - c00) * ux, y1 = c01 + (c11 - c01) * ux;
        zs[dz] = y0 + (y1 - y0) * uy;
    }
    return zs[0] + (zs[1] - zs[0]) * uz;
}

// core::windAt for one source; `centre` is samplePath(source.path, timeS, source.position).
vec3 windAt(WindSource source, vec3 centre, vec3 p, float timeS) {
    float strength = source.directionStrength.w;
    float radiusM = source.axisRadius.w;
    float coreRadiusM = source.shape.x, wavelengthM = source.shape.y;
    float speedMps = source.shape.z, gust = source.shape.w;
    if (!isFinite(p) || !isFiniteFloat(timeS) || !(strength != 0.0))
        return vec3(0.0);
    vec3 result = vec3(0.0);
    if (source.kind.x == WIND_KIND_DIRECTIONAL) {
        vec3 dir = safeNormalize(source.directionStrength.xyz);
        float magnitude = strength;
        if (wavelengthM > 0.0) {
            float phase = TWO_PI * (dot(dir, p) - speedMps * timeS) / wavelengthM;
            magnitude *= 0.5 + 0.5 * sin(phase);
        }
        if (gust > 0.0) {
            float cell = wavelengthM > 0.0 ? wavelengthM : DEFAULT_GUST_CELL_M;
            float n = valueNoise3((p - dir * (speedMps * timeS)) / cell);
            float g = clamp(gust, 0.0, 1.0);
            magnitude *= 1.0 - g + g * n;
        }
        float r = radiusM > 0.0 ? length(p - centre) : 0.0;
        result = dir * (magnitude * falloff(r, radiusM));
    } else if (source.kind.x == WIND_KIND_POINT) {
        vec3 d = p - centre;
        float r = length(d);
        result = safeNormalize(d) * (strength * coreRamp(r, coreRadiusM) * falloff(r, radiusM));
    } else if (source.kind.x == WIND_KIND_VORTEX) {
        vec3 axis = safeNormalize(source.axisRadius.xyz);
        vec3 d = p - centre;
        vec3 radial = d - axis * dot(d, axis);
        float r = length(radial);
        vec3 tangent = safeNormalize(cross(axis, radial));
        result = tangent * (strength * coreRamp(r, coreRadiusM) * falloff(r, radiusM));
    }
    return isFinite(result) ? result : vec3(0.0);
}

#endif  // GRASS_WIND_FIELD_GLSL
