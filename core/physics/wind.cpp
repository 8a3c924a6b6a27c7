#include "physics/wind.h"

#include <algorithm>
#include <cmath>

namespace grass::core {
namespace {

constexpr float TWO_PI = 6.28318530717958647692f;
// The noise lattice repeats every NOISE_PERIOD cells, so lattice indices always fit in 32 bits.
constexpr float NOISE_PERIOD = 65536.0f;
// Gust cells when the wave has no wavelength.
constexpr float DEFAULT_GUST_CELL_M = 10.0f;

bool isFinite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Unit vector, or zero when v is too short (or not finite) to have a direction.
glm::vec3 safeNormalize(glm::vec3 v) {
    const float len = glm::length(v);
    return (len > 1e-20f && std::isfinite(len)) ? v / len : glm::vec3(0.0f);
}

// A 32-bit integer hash (lowbias32, Wellons) of three lattice indices, mapped to [0, 1].
float latticeValue(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu;
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return static_cast<float>(h >> 8u) * (1.0f / 16777215.0f);
}

float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// (1 − (r/R)²)² inside R, 0 outside; 1 everywhere for R ≤ 0.
float falloff(float r, float radiusM) {
    if (radiusM <= 0.0f)
        return 1.0f;
    if (r >= radiusM)
        return 0.0f;
    const float q = 1.0f - (r / radiusM) * (r / radiusM);
    return q * q;
}

// Linear rise inside the core, 1 outside.
float coreRamp(float r, float coreRadiusM) {
    return coreRadiusM > 0.0f ? std::min(r / coreRadiusM, 1.0f) : 1.0f;
}

}  // namespace

glm::vec3 samplePath(const std::vector<PathKey>& path, float timeS, glm::vec3 fallback) {
    if (path.empty())
        return fallback;
    if (!(timeS > path.front().timeS))
        return path.front().posWorld;
    if (timeS >= path.back().timeS)
        return path.back().posWorld;
    const auto next = std::upper_bound(path.begin(), path.end(), timeS,
                                       [](float t, const PathKey& k) { return t < k.timeS; });
    const PathKey& b = *next;
    const PathKey& a = *(next - 1);
    const float span = b.timeS - a.timeS;
    const float u = span > 0.0f ? (timeS - a.timeS) / span : 1.0f;
    return glm::mix(a.posWorld, b.posWorld, u);
}

float valueNoise3(glm::vec3 p) {
    if (!isFinite(p))
        return 0.5f;
    const glm::vec3 q(std::fmod(p.x, NOISE_PERIOD), std::fmod(p.y, NOISE_PERIOD),
                      std::fmod(p.z, NOISE_PERIOD));
    const glm::vec3 cell = glm::floor(q);
    const glm::vec3 f = q - cell;
    // Offsetting by the period keeps the indices non-negative; wrap-around is the period itself.
    const auto ix = static_cast<std::uint32_t>(static_cast<std::int32_t>(cell.x) + 65536);
    const auto iy = static_cast<std::uint32_t>(static_cast<std::int32_t>(cell.y) + 65536);
    const auto iz = static_cast<std::uint32_t>(static_cast<std::int32_t>(cell.z) + 65536);
    const float ux = fade(f.x), uy = fade(f.y), uz = fade(f.z);
    float zs[2];
    for (std::uint32_t dz = 0; dz < 2; ++dz) {
        const float c00 = latticeValue(ix, iy, iz + dz), c10 = latticeValue(ix + 1, iy, iz + dz);
        const float c01 = latticeValue(ix, iy + 1, iz + dz);
        const float c11 = latticeValue(ix + 1, iy + 1, iz + dz);
        const float y0 = c00 + (c10 - c00) * ux, y1 = c01 + (c11 - c01) * ux;
        zs[dz] = y0 + (y1 - y0) * uy;
    }
    return zs[0] + (zs[1] - zs[0]) * uz;
}

glm::vec3 windAt(const WindSource& source, glm::vec3 p, float timeS) {
    if (!isFinite(p) || !std::isfinite(timeS) || !(source.strength != 0.0f))
        return glm::vec3(0.0f);
    const glm::vec3 centre = samplePath(source.path, timeS, source.position);
    glm::vec3 result(0.0f);
    switch (source.kind) {
        case WindKind::Directional: {
            const glm::vec3 dir = safeNormalize(source.direction);
            float magnitude = source.strength;
            if (source.wavelengthM > 0.0f) {
                const float phase =
                    TWO_PI * (glm::dot(dir, p) - source.speedMps * timeS) / source.wavelengthM;
                magnitude *= 0.5f + 0.5f * std::sin(phase);
            }
            if (source.gust > 0.0f) {
                const float cell =
                    source.wavelengthM > 0.0f ? source.wavelengthM : DEFAULT_GUST_CELL_M;
                const float n = valueNoise3((p - dir * (source.speedMps * timeS)) / cell);
                const float g = std::clamp(source.gust, 0.0f, 1.0f);
                magnitude *= 1.0f - g + g * n;
            }
            const float r = source.radiusM > 0.0f ? glm::length(p - centre) : 0.0f;
            result = dir * (magnitude * falloff(r, source.radiusM));
            break;
        }
        case WindKind::Point: {
            const glm::vec3 d = p - centre;
            const float r = glm::length(d);
            result = safeNormalize(d) * (source.strength * coreRamp(r, source.coreRadiusM) *
                                         falloff(r, source.radiusM));
            break;
        }
        case WindKind::Vortex: {
            const glm::vec3 axis = safeNormalize(source.axis);
            const glm::vec3 d = p - centre;
            const glm::vec3 radial = d - axis * glm::dot(d, axis);
            const float r = glm::length(radial);
            const glm::vec3 tangent = safeNormalize(glm::cross(axis, radial));
            result = tangent * (source.strength * coreRamp(r, source.coreRadiusM) *
                                falloff(r, source.radiusM));
            break;
        }
    }
    return isFinite(result) ? result : glm::vec3(0.0f);
}

glm::vec3 windAt(const std::vector<WindSource>& sources, glm::vec3 p, float timeS) {
    glm::vec3 sum(0.0f);
    for (const WindSource& s : sources)
        sum += windAt(s, p, timeS);
    return sum;
}

}  // namespace grass::core
