// Perceptual colour difference of 8-bit sRGB pixels: CIELAB (D65 white, the sRGB primaries) and
// ΔE76 = the Euclidean distance in L*a*b*. One ΔE76 unit is about a just-noticeable difference
// for flat patches (Sharma 2003); 2–3 is visible side by side. Used by `grass tradeoff` to
// measure a rendering setting's error against a reference frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace grass::core {

// 8-bit sRGB (gamma-encoded) → CIELAB (L* in 0..100).
glm::vec3 srgb8ToLab(std::uint8_t r, std::uint8_t g, std::uint8_t b);
// ΔE76 between two 8-bit sRGB colours.
float deltaE76(const std::uint8_t* rgbA, const std::uint8_t* rgbB);

struct MaskedDeltaE {
    double meanDeltaE = 0.0;  // mean ΔE76 over the pixels in the mask (0 for an empty mask)
    double maxDeltaE = 0.0;
    std::size_t pixels = 0;  // pixels in the mask
};

// Mean ΔE76 of two RGBA8 images of the same size over the pixels where mask[i] is non-zero (one
// byte per pixel). Precondition: sizes agree (a.size() == b.size() == 4 · mask.size()).
MaskedDeltaE maskedDeltaE76(std::span<const std::uint8_t> rgbaA,
                            std::span<const std::uint8_t> rgbaB,
                            std::span<const std::uint8_t> mask);

}  // namespace grass::core
