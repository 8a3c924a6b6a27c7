#include "util/bmp_header.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "util/image_header.h"

namespace grass::core {

namespace {

// Microsoft's BITMAPINFOHEADER family: all integers little-endian.
std::uint32_t little(std::string_view bytes, std::size_t at, std::size_t size) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < size; ++i)
        v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
    return v;
}

std::string hex(std::uint32_t value) {
    std::array<char, 12> text{};
    std::snprintf(text.data(), text.size(), "0x%08x", value);
    return text.data();
}

constexpr std::size_t FILE_HEADER = 14;
constexpr std::uint32_t OS2_V1 = 12;
constexpr std::array<std::uint32_t, 6> KNOWN_SIZES{OS2_V1, 40, 52, 56, 108, 124};
constexpr std::uint32_t BI_BITFIELDS = 3, BI_ALPHABITFIELDS = 6;

}  // namespace

Result<void> checkBmpHeader(std::string_view head, const std::string& name, int maxSide) {
    const auto damaged = [&](const std::string& what) {
        return makeError(name, "a damaged BMP: " + what);
    };
    if (head.size() < FILE_HEADER + 4)
        return damaged("the file ends inside its header");
    const std::uint32_t size = little(head, FILE_HEADER, 4);
    bool known = false;
    for (const std::uint32_t k : KNOWN_SIZES)
        known = known || k == size;
    if (!known)
        return makeError(name, "a BMP with a " + std::to_string(size) + "-byte header (" +
                                   (size == 64 ? std::string("OS/2 2.x") : "an unusual kind") +
                                   ") is not read: OpenImageIO 2.4 does not know it and would "
                                   "read garbage; save the image as a Windows BMP or as PNG");
    if (head.size() < FILE_HEADER + size && head.size() < BMP_HEAD_BYTES)
        return damaged("the file ends inside its " + std::to_string(size) + "-byte header");
    std::int64_t width = 0, height = 0;
    std::uint32_t bits = 0, compression = 0;
    if (size == OS2_V1) {
        width = little(head, 18, 2);
        height = little(head, 20, 2);
        bits = little(head, 24, 2);
    } else {
        width = static_cast<std::int32_t>(little(head, 18, 4));
        height = static_cast<std::int32_t>(little(head, 22, 4));  // negative: stored top-down
        bits = little(head, 28, 2);
        compression = little(head, 30, 4);
    }
    if (auto fits = checkImageSize(name, std::llabs(width), std::llabs(height), maxSide); !fits)
        return fits;
    if (bits != 32 || (compression != BI_BITFIELDS && compression != BI_ALPHABITFIELDS))
        return {};
    // The masks follow a 40-byte header and open the larger ones: at 54 either way.
    if (head.size() < BMP_HEAD_BYTES)
        return damaged("the file ends inside its colour masks");
    const std::uint32_t red = little(head, 54, 4), green = little(head, 58, 4),
                        blue = little(head, 62, 4);
    if (red == 0x00ff0000u && green == 0x0000ff00u && blue == 0x000000ffu)
        return {};
    return makeError(name, "a 32-bit BMP whose colour masks (red " + hex(red) + ", green " +
                               hex(green) + ", blue " + hex(blue) +
                               ") are not the usual order is not read: OpenImageIO 2.4 ignores "
                               "the masks and would read wrong colours; save the image as 24-bit "
                               "BMP or as PNG");
}

}  // namespace grass::core
