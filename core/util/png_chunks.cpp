#include "util/png_chunks.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "util/image_header.h"
#include "util/printable_text.h"

namespace grass::core {

namespace {

constexpr std::int64_t MAX_CHUNK_LENGTH = 0x7fffffff;
constexpr std::size_t IHDR_LENGTH = 13;
constexpr int COLOUR_TYPE_PALETTE = 3;
constexpr std::size_t BLOCK_BYTES = 64 * 1024;

std::uint32_t bigEndian32(const unsigned char* bytes) {
    return static_cast<std::uint32_t>(bytes[0]) << 24 | static_cast<std::uint32_t>(bytes[1]) << 16 |
           static_cast<std::uint32_t>(bytes[2]) << 8 | static_cast<std::uint32_t>(bytes[3]);
}

// §11.2.1 Table 11.1: the bit depths each colour type allows.
bool allowedDepth(int colourType, int depth) {
    switch (colourType) {
        case 0:
            return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
        case 2:
        case 4:
        case 6:
            return depth == 8 || depth == 16;
        case COLOUR_TYPE_PALETTE:
            return depth == 1 || depth == 2 || depth == 4 || depth == 8;
        default:
            return false;
    }
}

const std::array<std::uint32_t, 256>& crcTable() {
    static const std::array<std::uint32_t, 256> TABLE = [] {
        std::array<std::uint32_t, 256> table{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k)
                c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            table[n] = c;
        }
        return table;
    }();
    return TABLE;
}

}  // namespace

std::uint32_t pngCrc(std::uint32_t crc, const unsigned char* data, std::size_t size) {
    const auto& table = crcTable();
    crc = ~crc;
    for (std::size_t i = 0; i < size; ++i)
        crc = table[(crc ^ data[i]) & 0xffu] ^ (crc >> 8);
    return ~crc;
}

Result<void> checkPngChunks(std::istream& in, std::int64_t bytes, const std::string& name,
                            int maxSide) {
    const auto damaged = [&](const std::string& what) {
        return makeError(name, "a damaged PNG: " + what);
    };
    int colourType = -1;
    bool palette = false, data = false;
    std::vector<unsigned char> chunk, block;  // IHDR's data; a block of a chunk read
    for (bool first = true;; first = false) {
        std::array<unsigned char, 8> head{};
        if (!in.read(reinterpret_cast<char*>(head.data()), head.size()))
            return damaged("the file ends before the IEND chunk");
        const std::int64_t length = bigEndian32(head.data());
        const std::string type(reinterpret_cast<const char*>(head.data() + 4), 4);
        const std::int64_t left = bytes - static_cast<std::int64_t>(in.tellg());
        if (length > MAX_CHUNK_LENGTH || length + 4 > left)
            return damaged("chunk " + quotedName(type) + " claims " + std::to_string(length) +
                           " bytes and a 4-byte CRC, the file has " + std::to_string(left) +
                           " left");
        // Bit 5 of the first byte: an ancillary chunk, which libpng drops if its CRC is bad.
        // Critical chunks are read in blocks for their CRC (an IDAT may be hundreds of MB); the
        // header's data is kept.
        const bool critical = (head[4] & 0x20u) == 0;
        std::uint32_t crc = pngCrc(0, head.data() + 4, 4);
        if (!critical && !first)
            in.seekg(length, std::ios::cur);
        for (std::int64_t done = 0; (critical || first) && done < length;) {
            const auto step = static_cast<std::size_t>(
                std::min<std::int64_t>(length - done, static_cast<std::int64_t>(BLOCK_BYTES)));
            block.resize(step);
            if (!in.read(reinterpret_cast<char*>(block.data()), static_cast<std::streamsize>(step)))
                return damaged("the file ends inside chunk " + quotedName(type));
            crc = pngCrc(crc, block.data(), step);
            if (first && done == 0)
                chunk.assign(block.begin(),
                             block.begin() + std::min<std::size_t>(step, IHDR_LENGTH));
            done += static_cast<std::int64_t>(step);
        }
        std::array<unsigned char, 4> stored{};
        if (!in.read(reinterpret_cast<char*>(stored.data()), 4))
            return damaged("the file ends inside chunk " + quotedName(type));
        if (critical && crc != bigEndian32(stored.data()))
            return damaged("chunk " + quotedName(type) +
                           " fails its CRC check (the file is corrupt)");
        if (first) {
            if (type != "IHDR" || length != static_cast<std::int64_t>(IHDR_LENGTH))
                return damaged("the first chunk is " + quotedName(type) + " of " +
                               std::to_string(length) + " bytes, not a 13-byte IHDR");
            const std::int64_t width = bigEndian32(chunk.data());
            const std::int64_t height = bigEndian32(chunk.data() + 4);
            if (width < 1 || height < 1)
                return makeError(name, "the image has a " + std::to_string(width) + "×" +
                                           std::to_string(height) + " header");
            if (auto fits = checkImageSize(name, width, height, maxSide); !fits)
                return fits;
            const int depth = chunk[8];
            colourType = chunk[9];
            if (!allowedDepth(colourType, depth))
                return damaged("IHDR gives colour type " + std::to_string(colourType) +
                               " at bit depth " + std::to_string(depth) +
                               ", which PNG does not define");
            if (chunk[10] != 0 || chunk[11] != 0 || chunk[12] > 1)
                return damaged(
                    "IHDR gives a compression, filter or interlace method PNG does "
                    "not define");
            continue;
        }
        if (type == "PLTE")
            palette = true;
        if (type == "IDAT") {
            if (colourType == COLOUR_TYPE_PALETTE && !palette)
                return damaged("a paletted image without a PLTE chunk before its pixels");
            data = true;
        }
        if (type == "IEND")
            return data ? Result<void>{} : damaged("IEND comes before any IDAT (no pixels)");
    }
}

}  // namespace grass::core
