// Physics buffers and the wind field of core/physics/wind.cpp, mirrored for shaders/physics.comp.
// World space, metres, seconds. Names follow the CPU reference (STYLE.md §1, §3).
//
// Everything that depends on time only (substep count, substep times, path positions of wind
// sources and colliders) is evaluated on the CPU by render::PhysicsGpu and uploaded per substep,
// with exactly the CPU reference's float arithmetic: GLSL division is not correctly rounded, so
// ceil(dtS / maxSubstepS) or t + i·τ computed here could differ from the CPU by a substep.

// core::PhysicsParams (std430, 48 bytes; static_asserts in core/physics/physics.h).
struct PhysicsParams {
    vec4 gravity;
    float dtS;
    float etaDecayPerS;
    float maxSubstepS;
    float maxMovePerSubstep;
    uint gravityMode;
    uint maxSubsteps;
    float frontGravityScale;
    float crushedRecoveryFloor;
};

// core::WindSource without its path (render::WindSourceGpu, 64 bytes): the centre of each
// source at each substep time lives in windCentres.
struct WindSource {
    vec4 directionStrength;  // xyz direction, w strength
    vec4 axisRadius;         // xyz axis, w radiusM
    vec4 shape;              // coreRadiusM, wavelengthM, speedMps, gust
    uvec4 kind;              // x: core::WindKind
};

const uint GRAVITY_MODE_CENTRE = 1u;
const uint WIND_KIND_DIRECTIONAL = 0u;
const uint WIND_KIND_POINT = 1u;
const uint WIND_KIND_VORTEX = 2u;

// The blade buffer of blade.glsl, writable here (same binding, same layout).
layout(std430, binding = 0) buffer PhysicsBladeBuffer {
    Blade physicsBlades[];
};
layout(std430, binding = 1) readonly buffer PhysicsParamsBuffer {
    PhysicsParams params;
};
layout(std430, binding = 2) buffer EtaBuffer {
    float eta[];
};
// Rest tips Iv2 (xyz; w unused).
layout(std430, binding = 3) readonly buffer RestTipBuffer {
    vec4 restTips[];
};
layout(std430, binding = 4) readonly buffer WindSourceBuffer {
    WindSource windSources[];
};
// windCentres[i · windCount + j]: source j's centre at substep i's time t (xyz).
layout(std430, binding = 5) readonly buffer WindCentreBuffer {
    vec4 windCentres[];
};
// colliderSpheres[i · colliderCount + j]: collider j at t + τ of substep i (xyz centre, w radiusM).
layout(std430, binding = 6) readonly buffer ColliderBuffer {
    vec4 colliderSpheres[];
};
// colliderGroups[j]: the broad phase of core::SphereCollider j (render::ColliderGroupGpu):
// boundOffsetRadius = (boundOffset, boundRadiusM), size.x = groupSize.
struct ColliderGroup {
    vec4 boundOffsetRadius;
    uvec4 size;
};
layout(std430, binding = 8) readonly buffer ColliderGroupBuffer {
    ColliderGroup colliderGroups[];
};
// core::GravityLoad: blade i's |gE| grows by gravityLoadScale · gravityLoad[i] (snow load);
// bound and read only when gravityLoadScale > 0.
layout(std430, binding = 9) readonly buffer GravityLoadBuffer {
    float gravityLoad[];
};
// substepTimes[i]: x = t = timeS + i·τ, y = τ, z = t + τ (the collision time).
layout(std430, binding = 7) readonly buffer SubstepBuffer {
    vec4 substepTimes[];
};

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

// e^x − 1 without the cancellation of exp(x) − 1 near 0 (GLSL has no expm1): a Taylor
// polynomial below |x| = 0.5 (truncation < 3e-9 relative), exp(x) − 1 above.
float expm1(float x) {
    if (abs(x) >= 0.5)
        return exp(x) - 1.0;
    return x * (1.0 + x * (1.0 / 2.0 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 +
           x * (1.0 / 720.0 + x * (1.0 / 5040.0 + x * (1.0 / 40320.0))))))));
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
