#include "util/color_difference.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "util/assert.h"

namespace grass::core {

namespace {

float srgbToLinear(std::uint8_t value) {
    const float c = static_cast<float>(value) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// CIE f(t): cube root above (6/29)³, the linear segment below (keeps the slope finite at 0).
float labF(float t) {
    constexpr float DELTA = 6.0f / 29.0f;
    return t > DELTA * DELTA * DELTA ? std::cbrt(t) : t / (3.0f * DELTA * DELTA) + 4.0f / 29.0f;
}

}  // namespace

glm::vec3 srgb8ToLab(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const glm::vec3 rgb{srgbToLinear(r), srgbToLinear(g), srgbToLinear(b)};
    // Linear sRGB → XYZ (IEC 61966-2-1), divided by the D65 white point.
    const float x = (0.4124f * rgb.r + 0.3576f * rgb.g + 0.1805f * rgb.b) / 0.95047f;
    const float y = 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b;
    const float z = (0.0193f * rgb.r + 0.1192f * rgb.g + 0.9505f * rgb.b) / 1.08883f;
    const float fx = labF(x), fy = labF(y), fz = labF(z);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

float deltaE76(const std::uint8_t* rgbA, const std::uint8_t* rgbB) {
    return glm::distance(srgb8ToLab(rgbA[0], rgbA[1], rgbA[2]),
                         srgb8ToLab(rgbB[0], rgbB[1], rgbB[2]));
}

MaskedDeltaE maskedDeltaE76(std::span<const std::uint8_t> rgbaA,
                            std::span<const std::uint8_t> rgbaB,
                            std::span<const std::uint8_t> mask) {
    GRASS_ASSERT(rgbaA.size() == rgbaB.size() && rgbaA.size() == 4 * mask.size());
    MaskedDeltaE result;
    double sum = 0.0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (mask[i] == 0)
            continue;
        const double d = deltaE76(&rgbaA[4 * i], &rgbaB[4 * i]);
        sum += d;
        result.maxDeltaE = std::max(result.maxDeltaE, d);
        ++result.pixels;
    }
    result.meanDeltaE = result.pixels > 0 ? sum / static_cast<double>(result.pixels) : 0.0;
    return result;
}

}  // namespace grass::core
