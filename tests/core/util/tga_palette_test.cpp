// Colour-mapped TGAs decoded by grass (util/tga_palette.h), files built byte by byte after the
// Truevision TGA 2.0 layout: an 18-byte header, the image ID, the colour map, the pixels.
#include "util/tga_palette.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "billboard/grass_texture.h"
#include "maps/map_image.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

struct Tga {
    unsigned char type = 1;
    unsigned firstEntry = 0;
    unsigned entryBits = 24;
    unsigned indexBits = 8;
    unsigned char descriptor = 0;
    int width = 2, height = 2;
    std::string id;
    std::string palette;  // the entries' bytes
    std::string pixels;

    std::string bytes(unsigned entries) const {
        std::string b(18, '\0');
        b[0] = static_cast<char>(id.size());
        b[1] = 1;
        b[2] = static_cast<char>(type);
        b[3] = static_cast<char>(firstEntry & 0xff);
        b[4] = static_cast<char>(firstEntry >> 8);
        b[5] = static_cast<char>(entries & 0xff);
        b[6] = static_cast<char>(entries >> 8);
        b[7] = static_cast<char>(entryBits);
        b[12] = static_cast<char>(width);
        b[14] = static_cast<char>(height);
        b[16] = static_cast<char>(indexBits);
        b[17] = static_cast<char>(descriptor);
        return b + id + palette + pixels;
    }
};

// Three 24-bit entries, stored B, G, R: red, green, blue.
const std::string RGB_PALETTE("\x00\x00\xff\x00\xff\x00\xff\x00\x00", 9);

std::array<int, 4> pixel(const PalettedImage& image, int x, int y) {
    const auto at = static_cast<std::size_t>(4 * (y * image.pixels.width + x));
    return {image.pixels.pixels[at], image.pixels.pixels[at + 1], image.pixels.pixels[at + 2],
            image.pixels.pixels[at + 3]};
}

constexpr std::array<int, 4> RED{255, 0, 0, 255}, GREEN{0, 255, 0, 255}, BLUE{0, 0, 255, 255};

TEST(TgaPalette, PixelsLandWhereTheOriginSays) {
    Tga tga;
    tga.id = "made by hand";  // skipped: the map starts after it
    tga.palette = RGB_PALETTE;
    tga.pixels = std::string("\x00\x01\x02\x00", 4);  // file order: red green / blue red
    // Bottom-left origin (TGA's default): the file's first row is the bottom one.
    auto image = decodeColourMappedTga(tga.bytes(3), "a.tga", 64);
    ASSERT_TRUE(image) << image.error().str();
    EXPECT_EQ(pixel(*image, 0, 1), RED);
    EXPECT_EQ(pixel(*image, 1, 1), GREEN);
    EXPECT_EQ(pixel(*image, 0, 0), BLUE);
    EXPECT_FALSE(image->alpha);
    // Top-right origin: the first row is the top one, and it runs right to left.
    tga.descriptor = 0x30;
    image = decodeColourMappedTga(tga.bytes(3), "a.tga", 64);
    ASSERT_TRUE(image) << image.error().str();
    EXPECT_EQ(pixel(*image, 1, 0), RED);
    EXPECT_EQ(pixel(*image, 0, 0), GREEN);
    EXPECT_EQ(pixel(*image, 1, 1), BLUE);
}

// Run-length packets: a run of 3 × green crosses from the first row into the second, then a raw
// packet of one blue.
TEST(TgaPalette, RunLengthPacketsMayCrossRows) {
    Tga tga;
    tga.type = 9;
    tga.descriptor = 0x20;  // top-left
    tga.palette = RGB_PALETTE;
    tga.pixels = std::string("\x82\x01\x00\x02", 4);
    const auto image = decodeColourMappedTga(tga.bytes(3), "a.tga", 64);
    ASSERT_TRUE(image) << image.error().str();
    EXPECT_EQ(pixel(*image, 0, 0), GREEN);
    EXPECT_EQ(pixel(*image, 1, 0), GREEN);
    EXPECT_EQ(pixel(*image, 0, 1), GREEN);
    EXPECT_EQ(pixel(*image, 1, 1), BLUE);
}

// 16-bit entries (A RRRRR GGGGG BBBBB, little-endian), 16-bit indices, a first entry index of 2,
// and the alpha bit counted when the descriptor says the pixels hold alpha.
TEST(TgaPalette, SixteenBitEntriesAndIndicesFromTheFirstEntry) {
    Tga tga;
    tga.firstEntry = 2;
    tga.entryBits = 16;
    tga.indexBits = 16;
    tga.descriptor = 0x21;  // top-left, 1 alpha bit
    tga.width = 2;
    tga.height = 1;
    // Entry 2: opaque pure red (0x8000 | 31 << 10); entry 3: transparent mid blue (16).
    tga.palette = std::string("\x00\xfc\x10\x00", 4);
    tga.pixels = std::string("\x02\x00\x03\x00", 4);
    const auto image = decodeColourMappedTga(tga.bytes(2), "a.tga", 64);
    ASSERT_TRUE(image) << image.error().str();
    EXPECT_TRUE(image->alpha);
    EXPECT_EQ(pixel(*image, 0, 0), RED);
    EXPECT_EQ(pixel(*image, 1, 0), (std::array<int, 4>{0, 0, 132, 0}));  // 16 → 16·8 + 16/4
}

TEST(TgaPalette, DamagedFilesAreRefusedSayingWhat) {
    Tga tga;
    tga.palette = RGB_PALETTE;
    tga.pixels = std::string("\x00\x01\x03\x00", 4);  // entry 3 of three
    auto refused = decodeColourMappedTga(tga.bytes(3), "bad.tga", 64);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().str().find("bad.tga: a damaged colour-mapped TGA: pixel 2 indexes "
                                         "colour map entry 3, the map holds entries 0 to 2"),
              std::string::npos)
        << refused.error().str();

    tga.pixels = std::string("\x00\x01", 2);
    refused = decodeColourMappedTga(tga.bytes(3), "bad.tga", 64);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().str().find("holds 2 bytes of pixel data, fewer than 4 pixels take"),
              std::string::npos)
        << refused.error().str();

    tga.type = 9;
    tga.pixels = std::string("\x85", 1);  // a run whose value is missing
    EXPECT_FALSE(decodeColourMappedTga(tga.bytes(3), "bad.tga", 64));
    tga.pixels = std::string("\x00\x01", 2);  // one raw pixel, then nothing
    refused = decodeColourMappedTga(tga.bytes(3), "bad.tga", 64);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().str().find("ends after 1 of 4 pixels"), std::string::npos)
        << refused.error().str();

    tga.type = 1;
    tga.pixels.clear();
    refused = decodeColourMappedTga(tga.bytes(4), "bad.tga", 64);  // four entries, three stored
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().str().find("ends inside its colour map of 4 entries"),
              std::string::npos);

    tga.pixels = std::string(4, '\0');
    tga.entryBits = 12;
    EXPECT_FALSE(decodeColourMappedTga(tga.bytes(3), "bad.tga", 64));
    tga.entryBits = 24;
    tga.indexBits = 4;
    EXPECT_FALSE(decodeColourMappedTga(tga.bytes(3), "bad.tga", 64));
    tga.indexBits = 8;
    tga.width = 65;
    tga.pixels = std::string(130, '\0');
    refused = decodeColourMappedTga(tga.bytes(3), "bad.tga", 64);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().str().find("65×2"), std::string::npos) << refused.error().str();
    EXPECT_FALSE(decodeColourMappedTga(tga.bytes(3).substr(0, 10), "bad.tga", 64));
}

// Through the file readers: a map reads the palette's luminance, a grass texture its colours and
// alpha.
TEST(TgaPalette, MapsAndGrassTexturesReadThem) {
    const auto dir = test::scratchDir("tga_palette_files");
    Tga tga;
    tga.palette = RGB_PALETTE;
    tga.pixels = std::string("\x00\x01\x02\x00", 4);
    const auto file = dir / "palette.tga";
    std::ofstream(file, std::ios::binary) << tga.bytes(3);
    EXPECT_TRUE(isColourMappedTga(file));
    const auto map = loadMapImage(file);
    ASSERT_TRUE(map) << map.error().str();
    EXPECT_NEAR(map->at(0, 1), 0.2126f, 1e-6f);  // red, bottom left
    EXPECT_NEAR(map->at(1, 1), 0.7152f, 1e-6f);
    EXPECT_NEAR(map->at(0, 0), 0.0722f, 1e-6f);
    ASSERT_FALSE(map->warnings.empty());
    EXPECT_NE(map->warnings[0].find("a colour-mapped TGA"), std::string::npos);

    const auto opaque = loadGrassTexture(file);  // 24-bit entries: no alpha
    ASSERT_FALSE(opaque);
    EXPECT_NE(opaque.error().str().find("no alpha channel"), std::string::npos);

    tga.entryBits = 32;
    tga.descriptor = 0x08;  // 8 alpha bits
    tga.palette = std::string("\x00\x00\xff\xff\x00\xff\x00\x00\xff\x00\x00\x80", 12);
    const auto withAlpha = dir / "alpha.tga";
    std::ofstream(withAlpha, std::ios::binary) << tga.bytes(3);
    const auto texture = loadGrassTexture(withAlpha);
    ASSERT_TRUE(texture) << texture.error().str();
    EXPECT_EQ(texture->pixels[0], 0);  // top left: entry 2, blue, alpha 128
    EXPECT_EQ(texture->pixels[2], 255);
    EXPECT_EQ(texture->pixels[3], 128);
    EXPECT_EQ(texture->pixels[7], 255);  // top right: entry 0, red, opaque
}

}  // namespace
}  // namespace grass::core
