// A grass texture read as viewers show the file (billboard/grass_texture.h, util/image_layout.h):
// its orientation tag applied, WebP colours as stored.
#include "billboard/grass_texture.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

// The file stores (204, 204, 204, 128) and (0, 0, 0, 0) (tests/data/README.md); OpenImageIO's
// WebP reader hands out 102 for the first, which the billboards would have drawn half as bright.
TEST(GrassTextureFile, AWebpKeepsItsStoredColours) {
    const auto texture = loadGrassTexture(test::sourceDir() / "tests/data/maps/half_covered.webp");
    ASSERT_TRUE(texture.ok()) << texture.error().str();
    ASSERT_EQ(texture->width, 2);
    EXPECT_EQ(texture->pixels[3], 128);
    for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(int{texture->pixels[static_cast<std::size_t>(c)]} - 204), 2) << c;
    EXPECT_EQ(texture->pixels[7], 0);
}

// Orientation 3 (turned 180°) of a 2×2 texture: stored red, green / blue, clear; shown clear,
// blue / green, red (a mirror alone, orientation 2 or 4, would not give this).
TEST(GrassTextureFile, AnOrientationTagTurnsTheTexture) {
    const fs::path file = test::scratchDir("grass_texture_orientation") / "turned.tif";
    {
        auto out = OIIO::ImageOutput::create(file.string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(2, 2, 4, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:UnassociatedAlpha", 1);
        spec.attribute("Orientation", 3);
        const std::vector<std::uint8_t> pixels = {255, 0, 0,   255, 0, 255, 0, 255,
                                                  0,   0, 255, 255, 9, 9,   9, 0};
        ASSERT_TRUE(out->open(file.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const auto texture = loadGrassTexture(file);
    ASSERT_TRUE(texture.ok()) << texture.error().str();
    ASSERT_EQ(texture->width, 2);
    ASSERT_EQ(texture->height, 2);
    const auto& p = texture->pixels;
    EXPECT_EQ(p[3], 0);     // top left: the clear texel
    EXPECT_EQ(p[6], 255);   // top right: blue
    EXPECT_EQ(p[9], 255);   // bottom left: green
    EXPECT_EQ(p[12], 255);  // bottom right: red
    EXPECT_EQ(p[13] + p[14], 0);
}

}  // namespace
}  // namespace grass::core
