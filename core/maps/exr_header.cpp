#include "maps/exr_header.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <string>

namespace grass::core {

namespace fs = std::filesystem;

namespace {

constexpr std::array<unsigned char, 4> EXR_MAGIC{0x76, 0x2f, 0x31, 0x01};
// Version field flags (OpenEXR file layout): names of up to 255 characters, several parts.
constexpr std::uint32_t LONG_NAMES_FLAG = 0x400;
constexpr std::uint32_t MULTI_PART_FLAG = 0x1000;
constexpr std::size_t LONG_NAME_MAX = 255;
constexpr std::size_t SHORT_NAME_MAX = 31;

// OpenEXR stores integers little-endian.
std::int64_t littleEndian32(const unsigned char* bytes, bool isSigned) {
    const std::uint32_t v =
        static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
        static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
    return isSigned ? static_cast<std::int64_t>(static_cast<std::int32_t>(v))
                    : static_cast<std::int64_t>(v);
}

// A null-terminated string of at most maxLength characters; false at the end of the file or
// when it is longer.
bool readName(std::istream& in, std::size_t maxLength, std::string& out) {
    out.clear();
    for (char c; in.get(c);) {
        if (c == '\0')
            return true;
        if (out.size() == maxLength)
            return false;
        out.push_back(c);
    }
    return false;
}

// A name read from the file as our one-line errors may show it: bytes outside printable ASCII
// (a newline, say) as \xNN.
std::string printableName(const std::string& name) {
    std::string out = "\"";
    for (const char c : name) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f && c != '"' && c != '\\') {
            out.push_back(c);
        } else {
            constexpr char HEX[] = "0123456789abcdef";
            out += "\\x";
            out.push_back(HEX[byte >> 4]);
            out.push_back(HEX[byte & 0xf]);
        }
    }
    return out + "\"";
}

}  // namespace

bool hasExrMagic(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::array<unsigned char, 4> magic{};
    return in.read(reinterpret_cast<char*>(magic.data()), magic.size()) && magic == EXR_MAGIC;
}

Result<void> checkExrHeader(const fs::path& file, int maxSide) {
    const std::string name = file.string();
    const auto damaged = [&](const std::string& what) {
        return makeError(name, "a damaged OpenEXR header: " + what);
    };
    std::error_code ec;
    const auto fileBytes = static_cast<std::int64_t>(fs::file_size(file, ec));
    if (ec)
        return makeError(name, "cannot read the file: " + ec.message());
    std::ifstream in(file, std::ios::binary);
    std::array<unsigned char, 8> start{};
    if (!in.read(reinterpret_cast<char*>(start.data()), start.size()))
        return damaged("the file ends inside the magic number and version");
    const auto version = static_cast<std::uint32_t>(littleEndian32(start.data() + 4, false));
    const std::size_t maxName = version & LONG_NAMES_FLAG ? LONG_NAME_MAX : SHORT_NAME_MAX;
    const bool multiPart = (version & MULTI_PART_FLAG) != 0;

    std::string attribute, type;
    for (int part = 0;; ++part) {
        bool emptyHeader = true;
        for (;;) {
            if (!readName(in, maxName, attribute))
                return damaged(in ? "an attribute name longer than " + std::to_string(maxName) +
                                        " characters"
                                  : "the file ends inside the header");
            if (attribute.empty())
                break;
            emptyHeader = false;
            std::array<unsigned char, 4> sizeBytes{};
            if (!readName(in, maxName, type) ||
                !in.read(reinterpret_cast<char*>(sizeBytes.data()), sizeBytes.size()))
                return damaged("attribute " + printableName(attribute) + " is cut short");
            const std::int64_t size = littleEndian32(sizeBytes.data(), true);
            const std::int64_t left = fileBytes - static_cast<std::int64_t>(in.tellg());
            if (size < 0 || size > left)
                return damaged("attribute " + printableName(attribute) + " claims " +
                               std::to_string(size) + " bytes, the file has " +
                               std::to_string(left) + " left");
            if (attribute == "dataWindow" && type == "box2i" && size == 16) {
                std::array<unsigned char, 16> box{};
                in.read(reinterpret_cast<char*>(box.data()), box.size());
                const std::int64_t width =
                    littleEndian32(box.data() + 8, true) - littleEndian32(box.data(), true) + 1;
                const std::int64_t height = littleEndian32(box.data() + 12, true) -
                                            littleEndian32(box.data() + 4, true) + 1;
                if (width < 1 || height < 1)
                    return damaged("the data window is empty");
                if (width > maxSide || height > maxSide)
                    return makeError(name, "the image is " + std::to_string(width) + "×" +
                                               std::to_string(height) + "; maps may be at most " +
                                               std::to_string(maxSide) + "×" +
                                               std::to_string(maxSide) +
                                               " texels; refused before decoding");
            } else {
                in.seekg(size, std::ios::cur);
            }
        }
        // A single-part file has one header; a multi-part file's list ends with an empty one.
        if (!multiPart || (emptyHeader && part > 0))
            return {};
    }
}

}  // namespace grass::core
