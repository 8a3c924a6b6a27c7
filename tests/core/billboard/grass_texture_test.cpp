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

// Orientation 3 (turned 180°): stored left to right red, green: shown green, red.
TEST(GrassTextureFile, AnOrientationTagTurnsTheTexture) {
    const fs::path file = test::scratchDir("grass_texture_orientation") / "turned.tif";
    {
        auto out = OIIO::ImageOutput::create(file.string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(2, 1, 4, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:UnassociatedAlpha", 1);
        spec.attribute("Orientation", 3);
        const std::vector<std::uint8_t> pixels = {255, 0, 0, 255, 0, 255, 0, 0};
        ASSERT_TRUE(out->open(file.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const auto texture = loadGrassTexture(file);
    ASSERT_TRUE(texture.ok()) << texture.error().str();
    ASSERT_EQ(texture->width, 2);
    EXPECT_EQ(texture->pixels[3], 0);    // the transparent green, now on the left
    EXPECT_EQ(texture->pixels[4], 255);  // the opaque red, now on the right
    EXPECT_EQ(texture->pixels[7], 255);
}

}  // namespace
}  // namespace grass::core
