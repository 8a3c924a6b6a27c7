#include "util/image_header.h"

#include <array>
#include <cstdint>
#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "util/atomic_file.h"
#include "util/bmp_header.h"
#include "util/byte_size.h"
#include "util/png_chunks.h"
#include "util/printable_text.h"

namespace grass::core {

namespace fs = std::filesystem;

namespace {

constexpr std::array<unsigned char, 4> EXR_MAGIC{0x76, 0x2f, 0x31, 0x01};
constexpr std::array<unsigned char, 8> PNG_SIGNATURE{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::array<unsigned char, 6> GIF87_SIGNATURE{'G', 'I', 'F', '8', '7', 'a'};
constexpr std::array<unsigned char, 6> GIF89_SIGNATURE{'G', 'I', 'F', '8', '9', 'a'};
constexpr std::array<unsigned char, 2> BMP_SIGNATURE{'B', 'M'};
constexpr std::array<unsigned char, 3> JPEG_SIGNATURE{0xff, 0xd8, 0xff};
constexpr std::array<unsigned char, 4> TIFF_LITTLE_ENDIAN{'I', 'I', '*', 0};
constexpr std::array<unsigned char, 4> TIFF_BIG_ENDIAN{'M', 'M', 0, '*'};
// Version field flags (OpenEXR file layout): names of up to 255 characters, several parts.
constexpr std::uint32_t LONG_NAMES_FLAG = 0x400;
constexpr std::uint32_t MULTI_PART_FLAG = 0x1000;
constexpr std::size_t LONG_NAME_MAX = 255;
constexpr std::size_t SHORT_NAME_MAX = 31;
// A channel of a chlist after its name: pixel type (int32), pLinear (1), reserved (3), x and y
// sampling (int32 each).
constexpr std::streamoff CHANNEL_BYTES = 16;

// The attribute types whose value has one size (OpenEXR file layout, "Attribute types", and
// the double-precision types OpenEXR 3 adds). OpenEXR reads that many bytes whatever the
// attribute's size field says, so a size that differs parts its walk from ours: a damaged
// dataWindow of "65 bytes" made OpenEXR 3.1 read on 49 bytes early and take a later string's
// bytes for a size field this walk never saw (1.7 GB allocated for a 429-byte file).
std::int64_t fixedAttributeSize(const std::string& type) {
    static constexpr std::pair<const char*, std::int64_t> SIZES[] = {
        {"box2i", 16}, {"box2f", 16},         {"chromaticities", 32},
        {"compression", 1}, {"deepImageState", 1}, {"double", 8},
        {"envmap", 1},  {"float", 4},          {"int", 4},
        {"keycode", 28}, {"lineOrder", 1},     {"m33f", 36},
        {"m33d", 72},   {"m44f", 64},          {"m44d", 128},
        {"rational", 8}, {"tiledesc", 9},      {"timecode", 8},
        {"v2i", 8},     {"v2f", 8},            {"v2d", 16},
        {"v3i", 12},    {"v3f", 12},           {"v3d", 24},
    };
    for (const auto& [name, size] : SIZES)
        if (type == name)
            return size;
    return -1;
}

// OpenEXR stores integers little-endian.
std::int64_t littleEndian32(const unsigned char* bytes, bool isSigned) {
    const std::uint32_t v =
        static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
        static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
    return isSigned ? static_cast<std::int64_t>(static_cast<std::int32_t>(v))
                    : static_cast<std::int64_t>(v);
}

// The first `count` bytes of a file (fewer when it is shorter or cannot be read).
std::string fileHead(const fs::path& file, std::size_t count) {
    std::string head(count, '\0');
    std::ifstream in(file, std::ios::binary);
    in.read(head.data(), static_cast<std::streamsize>(count));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

template <std::size_t N>
bool startsWith(std::string_view bytes, const std::array<unsigned char, N>& magic) {
    return bytes.size() >= N && std::equal(magic.begin(), magic.end(), bytes.begin(),
                                           [](unsigned char m, char b) {
                                               return m == static_cast<unsigned char>(b);
                                           });
}

template <std::size_t N>
bool startsWith(const fs::path& file, const std::array<unsigned char, N>& magic) {
    return startsWith(std::string_view(fileHead(file, N)), magic);
}

std::string sizeText(std::int64_t width, std::int64_t height) {
    return std::to_string(width) + "×" + std::to_string(height);
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

// An image opened for a look at its header (a file, or encoded bytes in memory), with what its
// errors say.
struct HeaderFile {
    HeaderFile(const fs::path& file, std::string what)
        : name(file.string()), kind(std::move(what)),
          in(std::make_unique<std::ifstream>(file, std::ios::binary)) {
        std::error_code ec;
        const auto size = fs::file_size(file, ec);
        bytes = ec ? -1 : static_cast<std::int64_t>(size);
    }
    // A copy of the bytes: a texture of a few MB, next to its decoding.
    HeaderFile(std::string_view memory, std::string image, std::string what)
        : name(std::move(image)), kind(std::move(what)),
          in(std::make_unique<std::istringstream>(std::string(memory), std::ios::binary)),
          bytes(static_cast<std::int64_t>(memory.size())) {}
    Error damaged(const std::string& what) const {
        return makeError(name, "a damaged " + kind + ": " + what);
    }
    std::int64_t left() { return bytes - static_cast<std::int64_t>(in->tellg()); }

    std::string name, kind;
    std::unique_ptr<std::istream> in;
    std::int64_t bytes = -1;
};

Result<void> checkExr(HeaderFile& exr, int maxSide);
Result<void> checkPng(HeaderFile& png, int maxSide);
Result<void> checkGif(HeaderFile& gif, int maxSide);

}  // namespace

Result<void> checkImageSize(const std::string& name, std::int64_t width, std::int64_t height,
                            int maxSide) {
    if (width <= maxSide && height <= maxSide)
        return {};
    const auto bytes = [](std::int64_t w, std::int64_t h) {
        return byteSizeText(4.0 * static_cast<double>(w) * static_cast<double>(h));
    };
    return makeError(name, "the image is " + sizeText(width, height) + " (" + bytes(width, height) +
                               " at 4 bytes a pixel); images may be at "
                               "most " +
                               sizeText(maxSide, maxSide) + " pixels (" + bytes(maxSide, maxSide) +
                               "); refused before decoding");
}

std::string imageFormatBySignature(std::string_view head) {
    if (startsWith(head, PNG_SIGNATURE))
        return "png";
    if (startsWith(head, JPEG_SIGNATURE))
        return "jpeg";
    if (startsWith(head, EXR_MAGIC))
        return "openexr";
    if (startsWith(head, TIFF_LITTLE_ENDIAN) || startsWith(head, TIFF_BIG_ENDIAN))
        return "tiff";
    return "";
}

bool hasExrMagic(const fs::path& file) {
    return startsWith(file, EXR_MAGIC);
}

bool startsWithPngSignature(const fs::path& file) {
    return startsWith(file, PNG_SIGNATURE);
}

Result<void> checkExrHeader(const fs::path& file, int maxSide) {
    HeaderFile exr(file, "OpenEXR header");
    return checkExr(exr, maxSide);
}

namespace {

Result<void> checkExr(HeaderFile& exr, int maxSide) {
    if (exr.bytes < 0 || !*exr.in)
        return makeError(exr.name, "cannot read the file");
    std::istream& in = *exr.in;
    const auto damaged = [&](const std::string& what) { return exr.damaged(what); };
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
                return damaged("attribute " + quotedName(attribute) + " is cut short");
            const std::int64_t size = littleEndian32(sizeBytes.data(), true);
            const std::int64_t left = exr.left();
            if (size < 0 || size > left)
                return damaged("attribute " + quotedName(attribute) + " claims " +
                               std::to_string(size) + " bytes, the file has " +
                               std::to_string(left) + " left");
            if (const std::int64_t fixed = fixedAttributeSize(type); fixed >= 0 && size != fixed)
                return damaged("attribute " + quotedName(attribute) + " of type " +
                               quotedName(type) + " claims " + std::to_string(size) +
                               " bytes, a " + type + " is " + std::to_string(fixed));
            // A floatvector is read as size / 4 floats: another size leaves bytes unread.
            if (type == "floatvector" && size % 4 != 0)
                return damaged("attribute " + quotedName(attribute) +
                               " of type \"floatvector\" claims " + std::to_string(size) +
                               " bytes, not a whole number of floats");
            if (type == "chlist") {
                // OpenEXR reads a channel list to its empty name whatever the size field says
                // (a channel's 16 bytes of type, linearity and sampling after its name), so the
                // list must end where the field says.
                const std::int64_t listStart = static_cast<std::int64_t>(in.tellg());
                std::string channel;
                for (;;) {
                    if (!readName(in, LONG_NAME_MAX, channel))
                        return damaged("attribute " + quotedName(attribute) +
                                       "'s channel list is cut short or has a name longer "
                                       "than 255 characters");
                    if (channel.empty())
                        break;
                    in.seekg(CHANNEL_BYTES, std::ios::cur);
                    if (!in || exr.left() < 0)
                        return damaged("attribute " + quotedName(attribute) +
                                       "'s channel list is cut short");
                }
                const std::int64_t walked = static_cast<std::int64_t>(in.tellg()) - listStart;
                if (walked != size)
                    return damaged("attribute " + quotedName(attribute) +
                                   " of type \"chlist\" claims " + std::to_string(size) +
                                   " bytes, its channel list holds " + std::to_string(walked));
            } else if (attribute == "dataWindow" && type == "box2i") {
                std::array<unsigned char, 16> box{};
                in.read(reinterpret_cast<char*>(box.data()), box.size());
                const std::int64_t width =
                    littleEndian32(box.data() + 8, true) - littleEndian32(box.data(), true) + 1;
                const std::int64_t height = littleEndian32(box.data() + 12, true) -
                                            littleEndian32(box.data() + 4, true) + 1;
                if (width < 1 || height < 1)
                    return damaged("the data window is empty");
                if (auto fits = checkImageSize(exr.name, width, height, maxSide); !fits)
                    return fits;
            } else {
                in.seekg(size, std::ios::cur);
            }
        }
        // A single-part file has one header; a multi-part file's list ends with an empty one.
        if (!multiPart || (emptyHeader && part > 0))
            return {};
    }
}

Result<void> checkPng(HeaderFile& png, int maxSide) {
    if (png.bytes < 0 || !*png.in)
        return makeError(png.name, "cannot read the file");
    png.in->seekg(static_cast<std::streamoff>(PNG_SIGNATURE.size()));
    return checkPngChunks(*png.in, png.bytes, png.name, maxSide);
}

Result<void> checkGif(HeaderFile& gif, int maxSide) {
    std::array<unsigned char, 10> head{};
    if (gif.bytes < 0 || !gif.in->read(reinterpret_cast<char*>(head.data()), head.size()))
        return gif.damaged("the file ends inside its logical screen size");
    // GIF89a §18: the logical screen's width and height, unsigned 16-bit little-endian.
    const std::int64_t width = head[6] | head[7] << 8;
    const std::int64_t height = head[8] | head[9] << 8;
    return checkImageSize(gif.name, width, height, maxSide);
}

// The look each signature calls for, or none.
Result<void> checkByKind(HeaderFile& image, std::string_view head, int maxSide) {
    if (startsWith(head, EXR_MAGIC)) {
        image.kind = "OpenEXR header";
        return checkExr(image, maxSide);
    }
    if (startsWith(head, PNG_SIGNATURE)) {
        image.kind = "PNG";
        return checkPng(image, maxSide);
    }
    if (startsWith(head, GIF87_SIGNATURE) || startsWith(head, GIF89_SIGNATURE)) {
        image.kind = "GIF";
        return checkGif(image, maxSide);
    }
    if (startsWith(head, BMP_SIGNATURE)) {
        std::string bmp(BMP_HEAD_BYTES, '\0');
        image.in->read(bmp.data(), static_cast<std::streamsize>(bmp.size()));
        bmp.resize(static_cast<std::size_t>(std::max<std::streamsize>(image.in->gcount(), 0)));
        return checkBmpHeader(bmp, image.name, maxSide);
    }
    return {};
}

}  // namespace

Result<void> checkPngChunks(const fs::path& file, int maxSide) {
    HeaderFile png(file, "PNG");
    return checkPng(png, maxSide);
}

Result<void> checkGifScreen(const fs::path& file, int maxSide) {
    HeaderFile gif(file, "GIF");
    return checkGif(gif, maxSide);
}

Result<void> checkImageHeader(const fs::path& file, int maxSide) {
    // OpenImageIO would block on a FIFO and read /dev/zero for ever: regular files only.
    if (auto regular = checkRegularFile(file); !regular)
        return regular;
    HeaderFile image(file, "image");
    return checkByKind(image, fileHead(file, PNG_SIGNATURE.size()), maxSide);
}

Result<void> checkImageHeaderBytes(std::string_view bytes, const std::string& name, int maxSide) {
    HeaderFile image(bytes, name, "image");
    return checkByKind(image, bytes.substr(0, 8), maxSide);
}

}  // namespace grass::core
