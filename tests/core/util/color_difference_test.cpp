#include "util/color_difference.h"

#include <gtest/gtest.h>

#include <vector>

namespace grass::core {
namespace {

TEST(ColorDifference, WhiteAndBlackHaveTheirLightness) {
    const glm::vec3 white = srgb8ToLab(255, 255, 255);
    EXPECT_NEAR(white.x, 100.0f, 0.05f);
    EXPECT_NEAR(white.y, 0.0f, 0.05f);
    EXPECT_NEAR(white.z, 0.0f, 0.05f);
    EXPECT_NEAR(srgb8ToLab(0, 0, 0).x, 0.0f, 1e-4f);
}

// Reference values from the CIE formulas (e.g. colormine.org / Bruce Lindbloom's calculator):
// sRGB (255, 0, 0) → L* 53.24, a* 80.09, b* 67.20; mid grey (128, 128, 128) → L* 53.59.
TEST(ColorDifference, PrimariesMatchPublishedLab) {
    const glm::vec3 red = srgb8ToLab(255, 0, 0);
    EXPECT_NEAR(red.x, 53.24f, 0.1f);
    EXPECT_NEAR(red.y, 80.09f, 0.2f);
    EXPECT_NEAR(red.z, 67.20f, 0.2f);
    EXPECT_NEAR(srgb8ToLab(128, 128, 128).x, 53.59f, 0.1f);
}

TEST(ColorDifference, DeltaEIsZeroForEqualColoursAndSymmetric) {
    const std::uint8_t a[3] = {30, 120, 40}, b[3] = {40, 110, 35};
    EXPECT_EQ(deltaE76(a, a), 0.0f);
    EXPECT_FLOAT_EQ(deltaE76(a, b), deltaE76(b, a));
    EXPECT_GT(deltaE76(a, b), 1.0f);
}

TEST(ColorDifference, MaskedMeanCountsOnlyMaskedPixels) {
    // Two pixels: the first differs (black vs white, ΔE 100), the second is equal.
    const std::vector<std::uint8_t> a = {0, 0, 0, 255, 10, 20, 30, 255};
    const std::vector<std::uint8_t> b = {255, 255, 255, 255, 10, 20, 30, 255};
    const MaskedDeltaE both = maskedDeltaE76(a, b, std::vector<std::uint8_t>{1, 1});
    EXPECT_EQ(both.pixels, 2u);
    EXPECT_NEAR(both.meanDeltaE, 50.0, 0.05);
    EXPECT_NEAR(both.maxDeltaE, 100.0, 0.05);
    const MaskedDeltaE second = maskedDeltaE76(a, b, std::vector<std::uint8_t>{0, 1});
    EXPECT_EQ(second.pixels, 1u);
    EXPECT_EQ(second.meanDeltaE, 0.0);
    EXPECT_EQ(maskedDeltaE76(a, b, std::vector<std::uint8_t>{0, 0}).pixels, 0u);
}

}  // namespace
}  // namespace grass::core
