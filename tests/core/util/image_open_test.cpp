// One reader per image (core/util/image_open.h): the one the first bytes name, else the one the
// extension names; never OpenImageIO's trial of every reader, and no colour-mapped TGA.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "maps/map_image.h"
#include "support/test_paths.h"
#include "util/image_file.h"
#include "util/image_open.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
}

// A 2×2 TGA (Truevision TGA 2.0): an 18-byte header, then the pixels bottom row first.
std::string tgaBytes(unsigned char imageType, unsigned char colourMapType,
                     std::uint16_t colourMapLength, unsigned char bitsPerPixel,
                     const std::string& pixels) {
    std::string bytes(18, '\0');
    bytes[1] = static_cast<char>(colourMapType);
    bytes[2] = static_cast<char>(imageType);
    bytes[5] = static_cast<char>(colourMapLength & 0xff);
    bytes[6] = static_cast<char>(colourMapLength >> 8);
    bytes[7] = static_cast<char>(colourMapType ? 24 : 0);
    bytes[12] = 2;  // width
    bytes[14] = 2;  // height
    bytes[16] = static_cast<char>(bitsPerPixel);
    return bytes + std::string(static_cast<std::size_t>(colourMapLength) * 3, '\x80') + pixels;
}

TEST(ImageOpen, SignaturesNameTheirReaders) {
    EXPECT_EQ(imageFormatBySignature("\x89PNG\r\n\x1a\nrest"), "png");
    EXPECT_EQ(imageFormatBySignature("\xff\xd8\xff\xe0"), "jpeg");
    EXPECT_EQ(imageFormatBySignature(std::string("\x76\x2f\x31\x01\x02\0\0\0", 8)), "openexr");
    EXPECT_EQ(imageFormatBySignature(std::string("II*\0", 4)), "tiff");
    EXPECT_EQ(imageFormatBySignature(std::string("MM\0*", 4)), "tiff");
    // Formats whose readers allocate what their header claims on open are left to their
    // extension (a GIF canvas, a WebP picture), as are files without a signature (TGA), a
    // cut-short one, nothing at all.
    EXPECT_EQ(imageFormatBySignature("GIF87aB\xa3\xa3-"), "");
    EXPECT_EQ(imageFormatBySignature(std::string("RIFF\x10\0\0\0WEBPVP8 ", 16)), "");
    EXPECT_EQ(imageFormatBySignature(tgaBytes(3, 0, 0, 8, "abcd")), "");
    EXPECT_EQ(imageFormatBySignature("\x89PN"), "");
    EXPECT_EQ(imageFormatBySignature(""), "");
}

// The map_exr fuzz target's finding
// (tests/fuzz/regressions/map_exr/tga-taken-for-a-damaged-exr.exr): 141 bytes under a .exr name
// that OpenEXR refused; OpenImageIO then tried its other readers, the TGA reader took the bytes as
// a colour-mapped image with an empty palette and read past it (AddressSanitizer: SEGV in
// TGAInput::decode_pixel). Now only OpenEXR is asked.
TEST(ImageOpen, ADamagedExrIsNotHandedToAnotherReader) {
    const fs::path source = fs::path(GRASS_SOURCE_DIR) / "tests/fuzz/regressions/map_exr" /
                            "tga-taken-for-a-damaged-exr.exr";
    const auto file = test::scratchDir("image_open_exr") / "density.exr";
    writeBytes(file, readBytes(source));
    ASSERT_GT(fs::file_size(file), 100u);
    auto map = loadMapImage(file);
    ASSERT_FALSE(map);
    const std::string message = map.error().str();
    EXPECT_NE(message.find("density.exr"), std::string::npos) << message;
    EXPECT_NE(message.find("OpenEXR"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    // The same bytes named .tga are a colour-mapped TGA with an empty palette: grass's own
    // decoder (util/tga_palette.h) refuses them, and OpenImageIO's TGA reader never sees them.
    const auto tga = test::scratchDir("image_open_exr") / "density.tga";
    writeBytes(tga, readBytes(source));
    map = loadMapImage(tga);
    ASSERT_FALSE(map);
    EXPECT_NE(map.error().str().find("a damaged colour-mapped TGA: it has no colour map"),
              std::string::npos)
        << map.error().str();
    auto pixels = readRgba8Image(tga);
    ASSERT_FALSE(pixels);
    EXPECT_NE(pixels.error().str().find("colour-mapped (palette) TGA is not read"),
              std::string::npos)
        << pixels.error().str();
}

TEST(ImageOpen, TgaMapsAreReadUnlessColourMapped) {
    const auto dir = test::scratchDir("image_open_tga");
    // Greyscale (type 3), 8 bits: rows bottom first, so the top row is 200, 200.
    const auto grey = dir / "grey.tga";
    writeBytes(grey, tgaBytes(3, 0, 0, 8, std::string("\x40\x40\xc8\xc8")));
    auto map = loadMapImage(grey);
    ASSERT_TRUE(map) << map.error().str();
    ASSERT_EQ(map->width, 2);
    ASSERT_EQ(map->height, 2);
    EXPECT_NEAR(map->texels[0], 200.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(map->texels[3], 64.0f / 255.0f, 1e-6f);

    // Colour-mapped (type 1, and 9 run-length): maps decode them themselves
    // (util/tga_palette.h); both palette entries are grey 128. OpenImageIO's reader, which looks
    // indices up unchecked, is never handed one: readRgba8Image refuses them by name.
    const std::pair<unsigned char, std::string> paletted[] = {
        {static_cast<unsigned char>(1), std::string("\x00\x01\x00\x01", 4)},
        {static_cast<unsigned char>(9), std::string("\x83\x01", 2)}};  // a run of 4 × entry 1
    for (const auto& [type, pixels] : paletted) {
        const auto file = dir / ("paletted-" + std::to_string(type) + ".tga");
        writeBytes(file, tgaBytes(type, 1, 2, 8, pixels));
        auto read = loadMapImage(file);
        ASSERT_TRUE(read) << read.error().str();
        EXPECT_EQ(read->texels, std::vector<float>(4, 128.0f / 255.0f)) << int{type};
        auto refused = readRgba8Image(file);
        ASSERT_FALSE(refused) << int{type};
        const std::string message = refused.error().str();
        EXPECT_NE(message.find("paletted-"), std::string::npos) << message;
        EXPECT_NE(message.find("save the image as greyscale or true-colour TGA"), std::string::npos)
            << message;
    }
}

// Formats outside the list are refused by name before their reader opens the file: an ICO
// from image-rs's regression inputs (tests/regression/ico) made OpenImageIO 2.4's ICO reader
// divide by zero on open (SIGFPE); these bytes are its first 32.
TEST(ImageOpen, FormatsOutsideTheListAreRefusedByName) {
    const auto dir = test::scratchDir("image_open_formats");
    const auto icon = dir / "density.ico";
    writeBytes(icon,
               std::string("\0\0\1\0\1\0  \0\0\1\0 \0|\2\0\0\x16\0\0\0\x89PNG\r\n\x1a\n", 30));
    auto map = loadMapImage(icon);
    ASSERT_FALSE(map);
    EXPECT_NE(map.error().str().find("density.ico: an image in OpenImageIO's \"ico\" format, "
                                     "which grass does not read: use PNG, JPEG, TIFF"),
              std::string::npos)
        << map.error().str();
    const auto video = dir / "density.mp4";
    writeBytes(video, std::string(64, '\0'));
    map = loadMapImage(video);
    ASSERT_FALSE(map);
    EXPECT_NE(map.error().str().find("density.mp4: "), std::string::npos) << map.error().str();
}

// The first bytes win over the extension: a PNG saved as .jpg (common for downloads) loads, as
// does an encoded PNG in memory under a JPEG mime type.
TEST(ImageOpen, AMisnamedImageIsReadByItsSignature) {
    const auto dir = test::scratchDir("image_open_misnamed");
    const auto png = dir / "density.png";
    ASSERT_TRUE(saveMapImage(makeConstantMap(6, 4, 0.5f), png, MapSampleFormat::Auto));
    const auto jpg = dir / "density.jpg";
    writeBytes(jpg, readBytes(png));
    auto map = loadMapImage(jpg);
    ASSERT_TRUE(map) << map.error().str();
    EXPECT_EQ(map->width, 6);
    EXPECT_NEAR(map->texels[5], 0.5f, 1.0f / 255.0f);

    const std::string bytes = readBytes(png);
    auto decoded = decodeRgba8Image(bytes, "image 0", ".jpg", 64);
    ASSERT_TRUE(decoded) << decoded.error().str();
    EXPECT_EQ(decoded->width, 6);
    EXPECT_EQ(decoded->height, 4);
    // A PNG in memory gets the look a PNG file gets: a chunk claiming more than the bytes hold
    // is refused before libpng allocates it.
    std::string claims = bytes.substr(0, 33);
    claims += std::string("\x6e\x67\x02\x16tEXt", 8) + std::string(64, 'x');
    auto damaged = decodeRgba8Image(claims, "image 2", ".png", 64);
    ASSERT_FALSE(damaged);
    EXPECT_EQ(damaged.error().path, "image 2");
    EXPECT_NE(damaged.error().message.find("chunk \"tEXt\" claims 1852244502 bytes"),
              std::string::npos)
        << damaged.error().str();
    // Bytes no reader takes are refused by the name given.
    auto refused = decodeRgba8Image("not an image at all", "image 1", ".png", 64);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().path, "image 1");
}

}  // namespace
}  // namespace grass::core

namespace grass {
namespace {

// A reader's message is one line, each of its lines once (OpenEXR's subsampled-channel error
// came twice), and never empty: a PAM file gave "not an image OpenImageIO can read: ".
TEST(ImageOpen, ReaderMessagesComeOnOneLineOnceAndNeverEmpty) {
    EXPECT_EQ(oneLine("Subsampled channels\nSubsampled channels \r\nline 2\n"),
              "Subsampled channels; line 2");
    EXPECT_EQ(oneLine("plain"), "plain");
    EXPECT_EQ(oneLine("strip 0\nstrip 1\nstrip 2\nstrip 3\nstrip 4\n"),
              "strip 0; strip 1; strip 2; … (2 more)");
    EXPECT_NE(oneLine("").find("the reader gave no reason"), std::string::npos);
    EXPECT_NE(oneLine(" \n\n").find("the reader gave no reason"), std::string::npos);
}

}  // namespace
}  // namespace grass
