// The BMP headers refused before OpenImageIO 2.4 misreads them (util/bmp_header.h), built byte by
// byte after Microsoft's BITMAPFILEHEADER / BITMAPINFOHEADER layout.
#include "util/bmp_header.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace grass::core {
namespace {

void put(std::string& bytes, std::size_t at, std::uint32_t value, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i)
        bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xffu);
}

// File header and a DIB header of `headerSize` bytes for a width × height image, then (for a
// 40-byte header, or inside a larger one) the red, green and blue masks.
std::string bmpHead(std::uint32_t headerSize, std::int32_t width, std::int32_t height,
                    std::uint16_t bits, std::uint32_t compression, std::uint32_t red = 0,
                    std::uint32_t green = 0, std::uint32_t blue = 0) {
    std::string bytes(14 + std::max<std::uint32_t>(headerSize, 52), '\0');
    bytes[0] = 'B';
    bytes[1] = 'M';
    put(bytes, 14, headerSize, 4);
    put(bytes, 18, static_cast<std::uint32_t>(width), 4);
    put(bytes, 22, static_cast<std::uint32_t>(height), 4);
    put(bytes, 26, 1, 2);
    put(bytes, 28, bits, 2);
    put(bytes, 30, compression, 4);
    put(bytes, 54, red, 4);
    put(bytes, 58, green, 4);
    put(bytes, 62, blue, 4);
    return bytes;
}

constexpr std::uint32_t BI_RGB = 0, BI_BITFIELDS = 3;

TEST(BmpHeader, UsualFilesPass) {
    EXPECT_TRUE(checkBmpHeader(bmpHead(40, 64, 32, 24, BI_RGB), "a.bmp", 16384).ok());
    EXPECT_TRUE(checkBmpHeader(bmpHead(124, 64, -32, 32, BI_RGB), "a.bmp", 16384).ok());
    // 32-bit bit fields in the order the reader assumes (B, G, R bytes in memory).
    EXPECT_TRUE(
        checkBmpHeader(bmpHead(40, 4, 4, 32, BI_BITFIELDS, 0x00ff0000u, 0x0000ff00u, 0x000000ffu),
                       "a.bmp", 16384)
            .ok());
    // 16-bit bit fields are read by their masks.
    EXPECT_TRUE(checkBmpHeader(bmpHead(40, 4, 4, 16, BI_BITFIELDS, 0xf800u, 0x07e0u, 0x001fu),
                               "a.bmp", 16384)
                    .ok());
    std::string os2 = bmpHead(12, 0, 0, 0, 0);
    put(os2, 18, 64, 2);
    put(os2, 20, 32, 2);
    put(os2, 22, 1, 2);
    put(os2, 24, 8, 2);
    EXPECT_TRUE(checkBmpHeader(os2, "a.bmp", 16384).ok());
}

TEST(BmpHeader, MasksInAnotherOrderAreRefusedNamingThem) {
    const auto refused =
        checkBmpHeader(bmpHead(40, 4, 4, 32, BI_BITFIELDS, 0x000000ffu, 0x0000ff00u, 0x00ff0000u),
                       "rgb.bmp", 16384);
    ASSERT_FALSE(refused.ok());
    const std::string message = refused.error().str();
    EXPECT_NE(message.find("rgb.bmp"), std::string::npos) << message;
    EXPECT_NE(message.find("red 0x000000ff"), std::string::npos) << message;
    EXPECT_NE(message.find("save the image as 24-bit BMP or as PNG"), std::string::npos) << message;
}

TEST(BmpHeader, UnknownHeaderSizesShortFilesAndHugeSizesAreRefused) {
    const auto os2v2 = checkBmpHeader(bmpHead(64, 4, 4, 24, BI_RGB), "os2.bmp", 16384);
    ASSERT_FALSE(os2v2.ok());
    EXPECT_NE(os2v2.error().str().find("64-byte header (OS/2 2.x)"), std::string::npos)
        << os2v2.error().str();
    const auto cut = checkBmpHeader(bmpHead(40, 4, 4, 24, BI_RGB).substr(0, 30), "cut.bmp", 16384);
    ASSERT_FALSE(cut.ok());
    EXPECT_NE(cut.error().str().find("a damaged BMP"), std::string::npos) << cut.error().str();
    const auto masksCut =
        checkBmpHeader(bmpHead(40, 4, 4, 32, BI_BITFIELDS).substr(0, 56), "cut.bmp", 16384);
    EXPECT_FALSE(masksCut.ok());
    const auto huge = checkBmpHeader(bmpHead(40, 4, -20000, 24, BI_RGB), "huge.bmp", 16384);
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(huge.error().str().find("16384"), std::string::npos) << huge.error().str();
}

}  // namespace
}  // namespace grass::core
