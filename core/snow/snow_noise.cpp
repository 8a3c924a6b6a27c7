#include "snow/snow_noise.h"

#include <cmath>

#include "util/assert.h"

namespace grass::core {

namespace {

// Irrational-ish offsets per octave (1/π, Euler's γ, 1/√2): any non-lattice shift works.
constexpr glm::vec3 OCTAVE_SHIFT{0.3183099f, 0.5772157f, 0.7071068f};

// Perlin's quintic 6t⁵ − 15t⁴ + 10t³: zero first and second derivatives at the cell faces.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// Perlin 2002's gradient choice from 4 hash bits: the 12 cube-edge directions (4 repeated).
// The top bits are used: pcg3d's high bits mix best.
float gradient(std::uint32_t hash, float x, float y, float z) {
    const std::uint32_t h = hash >> 28u;
    const float u = h < 8u ? x : y;
    const float v = h < 4u ? y : (h == 12u || h == 14u ? x : z);
    return ((h & 1u) == 0u ? u : -u) + ((h & 2u) == 0u ? v : -v);
}

float cornerGradient(glm::ivec3 cell, glm::ivec3 corner, glm::vec3 f) {
    // int → uint wraps negative cells mod 2³², as GLSL's uint(int) does.
    const glm::uvec3 key{static_cast<std::uint32_t>(cell.x + corner.x),
                         static_cast<std::uint32_t>(cell.y + corner.y),
                         static_cast<std::uint32_t>(cell.z + corner.z)};
    const glm::vec3 d = f - glm::vec3(corner);
    return gradient(pcg3d(key).x, d.x, d.y, d.z);
}

float mixf(float a, float b, float t) {
    return a + t * (b - a);
}

}  // namespace

glm::uvec3 pcg3d(glm::uvec3 v) {
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

float hashToUnit(std::uint32_t h) {
    return static_cast<float>(h >> 8u) * (1.0f / 16777216.0f);
}

float perlinNoise3(glm::vec3 p) {
    const glm::vec3 base = glm::floor(p);
    const glm::ivec3 cell(base);
    const glm::vec3 f = p - base;
    const float n000 = cornerGradient(cell, {0, 0, 0}, f);
    const float n100 = cornerGradient(cell, {1, 0, 0}, f);
    const float n010 = cornerGradient(cell, {0, 1, 0}, f);
    const float n110 = cornerGradient(cell, {1, 1, 0}, f);
    const float n001 = cornerGradient(cell, {0, 0, 1}, f);
    const float n101 = cornerGradient(cell, {1, 0, 1}, f);
    const float n011 = cornerGradient(cell, {0, 1, 1}, f);
    const float n111 = cornerGradient(cell, {1, 1, 1}, f);
    const float u = fade(f.x), v = fade(f.y), w = fade(f.z);
    const float x00 = mixf(n000, n100, u), x10 = mixf(n010, n110, u);
    const float x01 = mixf(n001, n101, u), x11 = mixf(n011, n111, u);
    const float value = mixf(mixf(x00, x10, v), mixf(x01, x11, v), w);
    // The √2-long edge gradients leave no proven bound below ±1 (sampling peaks near ±0.98);
    // the clamp makes the documented range that Fi and Zn rely on exact.
    return glm::clamp(value, -1.0f, 1.0f);
}

float fractalNoise(glm::vec3 p, int octaves, float amplitudeA, float frequencyB) {
    GRASS_ASSERT(octaves >= 1 && amplitudeA > 0.0f);
    float sum = 0.0f;
    float norm = 0.0f;
    float amplitude = 1.0f;
    float frequency = 1.0f;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * perlinNoise3(frequency * p + static_cast<float>(i) * OCTAVE_SHIFT);
        norm += amplitude;
        amplitude *= amplitudeA;
        frequency *= frequencyB;
    }
    return sum / norm;
}

}  // namespace grass::core
