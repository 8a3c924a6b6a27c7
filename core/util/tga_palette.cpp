#include "util/tga_palette.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <system_error>
#include <vector>

#include "util/file_extension.h"
#include "util/image_header.h"

namespace grass::core {

namespace {

constexpr std::size_t HEADER_BYTES = 18;
constexpr unsigned char COLOUR_MAPPED = 1;
constexpr unsigned char COLOUR_MAPPED_RLE = 9;
// Image descriptor (byte 17): bits 0–3 the alpha bits a pixel holds, bit 4 set when columns
// run right to left, bit 5 set when rows run top to bottom.
constexpr unsigned char RIGHT_TO_LEFT = 0x10;
constexpr unsigned char TOP_TO_BOTTOM = 0x20;
constexpr unsigned char ALPHA_BITS = 0x0f;

unsigned little16(std::string_view bytes, std::size_t at) {
    return static_cast<unsigned char>(bytes[at]) |
           static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 1])) << 8;
}

struct Header {
    std::size_t idLength = 0;
    unsigned char mapType = 0, imageType = 0;
    unsigned firstEntry = 0, mapLength = 0, entryBits = 0;
    int width = 0, height = 0;
    unsigned indexBits = 0;
    unsigned char descriptor = 0;

    std::size_t entryBytes() const { return (entryBits + 7) / 8; }
    std::size_t indexBytes() const { return indexBits / 8; }
    std::size_t mapBytes() const { return mapLength * entryBytes(); }
};

Header readHeader(std::string_view bytes) {
    Header h;
    h.idLength = static_cast<unsigned char>(bytes[0]);
    h.mapType = static_cast<unsigned char>(bytes[1]);
    h.imageType = static_cast<unsigned char>(bytes[2]);
    h.firstEntry = little16(bytes, 3);
    h.mapLength = little16(bytes, 5);
    h.entryBits = static_cast<unsigned char>(bytes[7]);
    h.width = static_cast<int>(little16(bytes, 12));
    h.height = static_cast<int>(little16(bytes, 14));
    h.indexBits = static_cast<unsigned char>(bytes[16]);
    h.descriptor = static_cast<unsigned char>(bytes[17]);
    return h;
}

// One palette entry as RGBA: 24 and 32 bits are B, G, R (, A) bytes; 15 and 16 bits a
// little-endian word A RRRRR GGGGG BBBBB, each 5-bit value widened to 8 bits.
std::array<std::uint8_t, 4> paletteEntry(std::string_view entry, unsigned bits, bool alpha) {
    const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(entry[i]); };
    if (bits >= 24)
        return {byte(2), byte(1), byte(0),
                bits == 32 && alpha ? byte(3) : static_cast<std::uint8_t>(255)};
    const unsigned word = little16(entry, 0);
    const auto widen = [](unsigned five) {
        return static_cast<std::uint8_t>(five << 3 | five >> 2);
    };
    return {widen(word >> 10 & 0x1f), widen(word >> 5 & 0x1f), widen(word & 0x1f),
            static_cast<std::uint8_t>(bits == 16 && alpha && (word & 0x8000) == 0 ? 0 : 255)};
}

}  // namespace

bool isColourMappedTga(const std::filesystem::path& file, std::string_view head) {
    return lowerExtension(file) == ".tga" && imageFormatBySignature(head).empty() &&
           head.size() >= 3 &&
           (static_cast<unsigned char>(head[2]) == COLOUR_MAPPED ||
            static_cast<unsigned char>(head[2]) == COLOUR_MAPPED_RLE);
}

bool isColourMappedTga(const std::filesystem::path& file) {
    std::string head(8, '\0');  // the longest signature (PNG's) and the image type
    std::ifstream in(file, std::ios::binary);
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return isColourMappedTga(file, head);
}

Result<PalettedImage> decodeColourMappedTga(std::string_view bytes, const std::string& name,
                                            int maxSide) {
    const auto damaged = [&](const std::string& what) {
        return makeError(name, "a damaged colour-mapped TGA: " + what);
    };
    if (bytes.size() < HEADER_BYTES)
        return damaged("the file ends inside its 18-byte header");
    const Header h = readHeader(bytes);
    if (h.mapType != 1 || h.mapLength == 0)
        return damaged("it has no colour map (colour map type " + std::to_string(h.mapType) + ", " +
                       std::to_string(h.mapLength) + " entries)");
    if (h.entryBits != 15 && h.entryBits != 16 && h.entryBits != 24 && h.entryBits != 32)
        return damaged("colour map entries of " + std::to_string(h.entryBits) +
                       " bits (TGA defines 15, 16, 24 and 32)");
    if (h.indexBits != 8 && h.indexBits != 16)
        return damaged("pixels of " + std::to_string(h.indexBits) +
                       " bits (a colour-mapped TGA's are 8 or 16)");
    if ((h.descriptor & 0xc0) != 0)
        return damaged("interleaved rows (image descriptor bits 6–7), which TGA 2.0 retired");
    if (h.width < 1 || h.height < 1)
        return makeError(name, "the image has a " + std::to_string(h.width) + "×" +
                                   std::to_string(h.height) + " header");
    if (auto fits = checkImageSize(name, h.width, h.height, maxSide); !fits)
        return fits.error();
    const std::size_t mapAt = HEADER_BYTES + h.idLength;
    if (bytes.size() < mapAt + h.mapBytes())
        return damaged("the file ends inside its colour map of " + std::to_string(h.mapLength) +
                       " entries");

    PalettedImage image;
    image.alpha = (h.descriptor & ALPHA_BITS) != 0 && (h.entryBits == 32 || h.entryBits == 16);
    std::vector<std::array<std::uint8_t, 4>> palette(h.mapLength);
    for (std::size_t e = 0; e < h.mapLength; ++e)
        palette[e] = paletteEntry(bytes.substr(mapAt + e * h.entryBytes(), h.entryBytes()),
                                  h.entryBits, image.alpha);

    const auto count = static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height);
    // The fewest bytes the pixels can take (run-length: one full run packet per 128 pixels):
    // a header that claims more pixels than the file can hold allocates nothing.
    const std::size_t fewest = h.imageType == COLOUR_MAPPED
                                   ? count * h.indexBytes()
                                   : (count + 127) / 128 * (1 + h.indexBytes());
    if (bytes.size() - mapAt - h.mapBytes() < fewest)
        return damaged("the file holds " + std::to_string(bytes.size() - mapAt - h.mapBytes()) +
                       " bytes of pixel data, fewer than " + std::to_string(count) +
                       " pixels take");
    image.pixels.width = h.width;
    image.pixels.height = h.height;
    image.pixels.pixels.resize(count * 4);
    std::size_t at = mapAt + h.mapBytes();
    const std::size_t indexBytes = h.indexBytes();
    const auto readIndex = [&](unsigned& index) {
        if (bytes.size() - at < indexBytes)
            return false;
        index = indexBytes == 1 ? static_cast<unsigned char>(bytes[at]) : little16(bytes, at);
        at += indexBytes;
        return true;
    };
    // Pixel p in file order (row by row from the file's origin) lands where it is shown.
    const auto place = [&](std::size_t p, unsigned index) -> Result<void> {
        if (index < h.firstEntry || index - h.firstEntry >= h.mapLength)
            return damaged("pixel " + std::to_string(p) + " indexes colour map entry " +
                           std::to_string(index) + ", the map holds entries " +
                           std::to_string(h.firstEntry) + " to " +
                           std::to_string(h.firstEntry + h.mapLength - 1));
        const std::size_t row = p / static_cast<std::size_t>(h.width);
        const std::size_t col = p % static_cast<std::size_t>(h.width);
        const std::size_t y =
            (h.descriptor & TOP_TO_BOTTOM) ? row : static_cast<std::size_t>(h.height) - 1 - row;
        const std::size_t x =
            (h.descriptor & RIGHT_TO_LEFT) ? static_cast<std::size_t>(h.width) - 1 - col : col;
        const auto& rgba = palette[index - h.firstEntry];
        std::copy(rgba.begin(), rgba.end(),
                  image.pixels.pixels.begin() +
                      static_cast<std::ptrdiff_t>(4 * (y * static_cast<std::size_t>(h.width) + x)));
        return {};
    };
    const auto ended = [&](std::size_t p) {
        return damaged("the pixel data ends after " + std::to_string(p) + " of " +
                       std::to_string(count) + " pixels");
    };
    for (std::size_t p = 0; p < count;) {
        unsigned index = 0;
        if (h.imageType == COLOUR_MAPPED) {
            if (!readIndex(index))
                return ended(p);
            if (auto placed = place(p++, index); !placed)
                return placed.error();
            continue;
        }
        // A run-length packet: a header byte (bit 7: one value repeated; else raw values),
        // then 1 to 128 pixels; a packet may run on into the next row.
        if (at >= bytes.size())
            return ended(p);
        const auto packet = static_cast<unsigned char>(bytes[at++]);
        const std::size_t length = std::min<std::size_t>((packet & 0x7fu) + 1u, count - p);
        const bool run = (packet & 0x80u) != 0;
        if (run && !readIndex(index))
            return ended(p);
        for (std::size_t k = 0; k < length; ++k) {
            if (!run && !readIndex(index))
                return ended(p);
            if (auto placed = place(p++, index); !placed)
                return placed.error();
        }
    }
    return image;
}

Result<PalettedImage> readColourMappedTga(const std::filesystem::path& file, int maxSide) {
    const std::string name = file.string();
    std::ifstream in(file, std::ios::binary);
    std::string head(HEADER_BYTES, '\0');
    if (!in.read(head.data(), static_cast<std::streamsize>(head.size())))
        return makeError(name,
                         "a damaged colour-mapped TGA: the file ends inside its 18-byte "
                         "header");
    const Header h = readHeader(head);
    // The most a valid image of this header needs: a run-length file at worst one packet
    // header a pixel. More is never read (a header may sit on gigabytes of anything).
    const std::size_t pixels =
        static_cast<std::size_t>(h.width) * static_cast<std::size_t>(h.height);
    const std::size_t most = HEADER_BYTES + h.idLength + h.mapBytes() +
                             pixels * (std::max<std::size_t>(h.indexBits / 8, 1) + 1);
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    if (ec)
        return makeError(name, "cannot read the file: " + ec.message());
    if (auto fits = checkImageSize(name, h.width, h.height, maxSide); !fits)
        return fits.error();
    std::string bytes(std::min<std::size_t>(static_cast<std::size_t>(size), most), '\0');
    in.seekg(0);
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return decodeColourMappedTga(bytes, name, maxSide);
}

}  // namespace grass::core
