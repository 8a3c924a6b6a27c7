// The header look before OpenImageIO opens an image (core/util/image_header.h): a damaged EXR
// header or PNG chunk is refused by name and size without allocating what it claims.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "maps/map_image.h"
#include "support/test_paths.h"
#include "util/image_header.h"
#include "util/png_chunks.h"

namespace grass::core {
namespace {

constexpr int MAX_SIDE = 16384;

// Bytes of an EXR file, written field by field as the OpenEXR file layout has them.
struct ExrBytes {
    std::string bytes{"\x76\x2f\x31\x01", 4};

    ExrBytes& u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
        return *this;
    }
    ExrBytes& name(const std::string& text) {
        bytes += text;
        bytes.push_back('\0');
        return *this;
    }
    ExrBytes& attribute(const std::string& attr, const std::string& type, std::uint32_t size) {
        return name(attr).name(type).u32(size);
    }
    ExrBytes& box(std::int32_t xMin, std::int32_t yMin, std::int32_t xMax, std::int32_t yMax) {
        attribute("dataWindow", "box2i", 16);
        for (const std::int32_t v : {xMin, yMin, xMax, yMax})
            u32(static_cast<std::uint32_t>(v));
        return *this;
    }
    std::filesystem::path write(const std::string& test) const {
        const auto file = test::scratchDir("exr_header_" + test) / "map.exr";
        std::ofstream(file, std::ios::binary) << bytes;
        return file;
    }
};

// Bytes of a PNG file, chunk by chunk (CRCs left zero: the check leaves them to libpng).
struct PngBytes {
    std::string bytes{"\x89PNG\r\n\x1a\n", 8};

    PngBytes& u32(std::uint32_t v) {
        for (int i = 3; i >= 0; --i)
            bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
        return *this;
    }
    // A chunk with its CRC (pngCrc, checked against a known CRC in PngChunks.TheCrcIsPngsCrc32),
    // or with `crc` in its place.
    PngBytes& chunk(const std::string& type, const std::string& data,
                    std::optional<std::uint32_t> crc = std::nullopt) {
        u32(static_cast<std::uint32_t>(data.size()));
        const std::string typed = type + data;
        bytes += typed;
        return u32(crc ? *crc
                       : pngCrc(0, reinterpret_cast<const unsigned char*>(typed.data()),
                                typed.size()));
    }
    PngBytes& header(std::uint32_t width, std::uint32_t height, int depth = 8,
                     int colourType = 0) {
        PngBytes ihdr;
        ihdr.bytes.clear();
        ihdr.u32(width).u32(height);
        ihdr.bytes.push_back(static_cast<char>(depth));
        ihdr.bytes.push_back(static_cast<char>(colourType));
        ihdr.bytes += std::string("\x00\x00\x00", 3);
        return chunk("IHDR", ihdr.bytes);
    }
    std::filesystem::path write(const std::string& test) const {
        const auto file = test::scratchDir("png_header_" + test) / "map.png";
        std::ofstream(file, std::ios::binary) << bytes;
        return file;
    }
};

TEST(ExrHeader, AMapSavedAsExrPassesAndLoads) {
    const auto file = test::scratchDir("exr_header_saved") / "density.exr";
    ASSERT_TRUE(saveMapImage(makeConstantMap(40, 30, 0.25f), file, MapSampleFormat::Auto));
    EXPECT_TRUE(hasExrMagic(file));
    EXPECT_TRUE(checkExrHeader(file, MAX_SIDE)) << checkExrHeader(file, MAX_SIDE).error().str();
    auto map = loadMapImage(file);
    ASSERT_TRUE(map) << map.error().str();
    EXPECT_EQ(map->width, 40);
    EXPECT_EQ(map->height, 30);
}

TEST(ExrHeader, APngHasNoExrMagic) {
    const auto file = test::scratchDir("exr_header_png") / "density.png";
    ASSERT_TRUE(saveMapImage(makeConstantMap(4, 4, 1.0f), file, MapSampleFormat::Auto));
    EXPECT_FALSE(hasExrMagic(file));
}

// The fuzz target's finding (tests/fuzz/regressions/map_exr): a string attribute claiming
// 1.8 GB in a file of a few hundred bytes, which OpenEXR allocated before reading.
TEST(ExrHeader, AnAttributeClaimingMoreThanTheFileIsRefusedByName) {
    ExrBytes exr;
    exr.u32(2).attribute("capDate", "string", 0x6f640013u);
    exr.bytes += std::string(300, 'x');
    const auto file = exr.write("claims");
    auto checked = checkExrHeader(file, MAX_SIDE);
    ASSERT_FALSE(checked);
    const std::string message = checked.error().str();
    EXPECT_NE(message.find("map.exr"), std::string::npos) << message;
    EXPECT_NE(message.find("\"capDate\" claims 1868824595 bytes"), std::string::npos) << message;
    auto loaded = loadMapImage(file);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().str(), message);
}

TEST(ExrHeader, ANegativeSizeAndACutShortHeaderAreRefused) {
    ExrBytes negative;
    negative.u32(2).attribute("channels", "chlist", 0xffffffffu);
    auto checked = checkExrHeader(negative.write("negative"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("claims -1 bytes"), std::string::npos);

    ExrBytes cut;
    cut.u32(2).name("compression").name("compression");
    checked = checkExrHeader(cut.write("cut"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("\"compression\" is cut short"), std::string::npos)
        << checked.error().str();

    ExrBytes unterminated;
    unterminated.u32(2).attribute("lineOrder", "lineOrder", 1);
    unterminated.bytes.push_back('\0');
    checked = checkExrHeader(unterminated.write("unterminated"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("ends inside the header"), std::string::npos)
        << checked.error().str();
}

// Found by the fuzz target too: a name read from the file holds a newline; errors stay one line.
TEST(ExrHeader, NamesFromTheFileAreShownOnOneLine) {
    ExrBytes exr;
    exr.u32(2).attribute("cap\nDate", "string", 1000);
    auto checked = checkExrHeader(exr.write("newline"), MAX_SIDE);
    ASSERT_FALSE(checked);
    const std::string message = checked.error().str();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("\"cap\\x0aDate\" claims 1000 bytes"), std::string::npos) << message;
}

TEST(ExrHeader, NamesLongerThanTheVersionAllowsAreRefused) {
    const std::string longName(40, 'a');
    ExrBytes shortNames;
    shortNames.u32(2).attribute(longName, "int", 4).u32(0).name("");
    auto checked = checkExrHeader(shortNames.write("short_names"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("longer than 31"), std::string::npos);
    // Bit 10 of the version field allows 255.
    ExrBytes longNames;
    longNames.u32(2 | 0x400).attribute(longName, "int", 4).u32(0).name("");
    EXPECT_TRUE(checkExrHeader(longNames.write("long_names"), MAX_SIDE));
}

TEST(ExrHeader, ADataWindowOverTheMapLimitIsRefusedBeforeDecoding) {
    ExrBytes wide;
    wide.u32(2).box(0, 0, 65535, 65535).name("");
    auto checked = checkExrHeader(wide.write("wide"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("65536×65536"), std::string::npos)
        << checked.error().str();
    EXPECT_NE(checked.error().str().find("refused before decoding"), std::string::npos);

    ExrBytes empty;
    empty.u32(2).box(10, 0, 9, 0).name("");
    checked = checkExrHeader(empty.write("empty"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("data window is empty"), std::string::npos);

    ExrBytes fits;
    fits.u32(2).box(-8, -8, 7, 7).name("");
    EXPECT_TRUE(checkExrHeader(fits.write("fits"), MAX_SIDE));
}

// The map_exr fuzz target's finding (tests/fuzz/regressions/map_exr/data-window-of-65-bytes.exr):
// a dataWindow whose size field said 65. OpenEXR reads a box2i's 16 bytes whatever the field
// says, so it read on 49 bytes before this walk and took a string's bytes for a size this walk
// never saw: 1.7 GB allocated for a 429-byte file. A fixed-size type of another size is damaged.
TEST(ExrHeader, AFixedSizeAttributeOfAnotherSizeIsRefused) {
    ExrBytes exr;
    exr.u32(2).attribute("dataWindow", "box2i", 65);
    for (const std::int32_t v : {0, 0, 65649, 0})
        exr.u32(static_cast<std::uint32_t>(v));
    exr.bytes += std::string(49, 'x');
    exr.name("");
    const auto file = exr.write("fixed_size");
    auto checked = checkExrHeader(file, MAX_SIDE);
    ASSERT_FALSE(checked);
    const std::string message = checked.error().str();
    EXPECT_NE(message.find("map.exr"), std::string::npos) << message;
    EXPECT_NE(message.find("attribute \"dataWindow\" of type \"box2i\" claims 65 bytes, a box2i "
                           "is 16"),
              std::string::npos)
        << message;
    auto loaded = loadMapImage(file);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().str(), message);

    // Every fixed-size type is held to its size, one byte short or long alike; a type of no one
    // size (a string, a channel list, a type OpenEXR does not know) is not.
    for (const auto& [type, size] : {std::pair<std::string, std::uint32_t>{"int", 4},
                                     {"tiledesc", 9}, {"compression", 1}, {"m44d", 128}}) {
        for (const std::uint32_t claimed : {size - 1, size + 1}) {
            ExrBytes wrong;
            wrong.u32(2).attribute("custom", type, claimed);
            wrong.bytes += std::string(claimed, '\0');
            wrong.name("");
            EXPECT_FALSE(checkExrHeader(wrong.write("wrong_" + type), MAX_SIDE))
                << type << " of " << claimed << " bytes";
        }
        ExrBytes right;
        right.u32(2).attribute("custom", type, size);
        right.bytes += std::string(size, '\0');
        right.name("");
        EXPECT_TRUE(checkExrHeader(right.write("right_" + type), MAX_SIDE)) << type;
    }
    ExrBytes text;
    text.u32(2).attribute("owner", "string", 5).name("abcd").attribute("odd", "myType", 3);
    text.bytes += "xyz";
    text.name("");
    EXPECT_TRUE(checkExrHeader(text.write("variable"), MAX_SIDE));
}

// The fresh-clone fuzz run's finding (tests/fuzz/regressions/map_exr/
// channel-list-longer-than-its-size.exr): OpenEXR reads a channel list to its empty name
// whatever its size field says; a list of 37 bytes under a size of 19 parted the two walks
// again, and a string's bytes claimed 1.8 GB. A list must end where its size says, and a
// floatvector (read as size / 4 floats) must be whole floats.
TEST(ExrHeader, VariableSizedAttributesMustEndWhereTheirSizeSays) {
    const auto channel = [](ExrBytes& exr, const std::string& name) {
        exr.name(name).u32(1).u32(0).u32(1).u32(1);  // half, linear 0, sampling 1 × 1
    };
    ExrBytes longer;
    longer.u32(2).attribute("channels", "chlist", 19);
    channel(longer, "Y");
    channel(longer, "\x02");
    longer.name("").name("");
    auto checked = checkExrHeader(longer.write("chlist_longer"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("attribute \"channels\" of type \"chlist\" claims 19 "
                                         "bytes, its channel list holds 37"),
              std::string::npos)
        << checked.error().str();

    ExrBytes cut;
    cut.u32(2).attribute("channels", "chlist", 19);
    cut.name("Y").u32(1);
    EXPECT_FALSE(checkExrHeader(cut.write("chlist_cut"), MAX_SIDE));

    ExrBytes whole;
    whole.u32(2).attribute("channels", "chlist", 37);
    channel(whole, "R");
    channel(whole, "G");
    whole.name("").name("");
    EXPECT_TRUE(checkExrHeader(whole.write("chlist_whole"), MAX_SIDE))
        << checkExrHeader(whole.write("chlist_whole"), MAX_SIDE).error().str();

    ExrBytes partFloat;
    partFloat.u32(2).attribute("weights", "floatvector", 6).u32(0);
    partFloat.bytes += std::string(2, '\0');
    partFloat.name("");
    checked = checkExrHeader(partFloat.write("floatvector_6"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("not a whole number of floats"), std::string::npos);
    ExrBytes floats;
    floats.u32(2).attribute("weights", "floatvector", 8).u32(0).u32(0).name("");
    EXPECT_TRUE(checkExrHeader(floats.write("floatvector_8"), MAX_SIDE));
}

// A multi-part file (version bit 12) is a list of headers ended by an empty one: each part is
// checked, and a list without its end is cut short.
TEST(ExrHeader, EveryPartOfAMultiPartFileIsChecked) {
    ExrBytes parts;
    parts.u32(2 | 0x1000).box(0, 0, 3, 3).name("").box(0, 0, 99999, 3).name("").name("");
    auto checked = checkExrHeader(parts.write("parts"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("100000×4"), std::string::npos) << checked.error().str();

    ExrBytes good;
    good.u32(2 | 0x1000).box(0, 0, 3, 3).name("").box(0, 0, 7, 3).name("").name("");
    EXPECT_TRUE(checkExrHeader(good.write("good"), MAX_SIDE));

    ExrBytes unended;
    unended.u32(2 | 0x1000).box(0, 0, 3, 3).name("");
    EXPECT_FALSE(checkExrHeader(unended.write("unended"), MAX_SIDE));
}

TEST(PngChunks, AMapSavedAsPngPasses) {
    const auto file = test::scratchDir("png_header_saved") / "density.png";
    ASSERT_TRUE(saveMapImage(makeConstantMap(40, 30, 0.25f), file, MapSampleFormat::Auto));
    EXPECT_TRUE(checkPngChunks(file, MAX_SIDE)) << checkPngChunks(file, MAX_SIDE).error().str();
    EXPECT_TRUE(checkImageHeader(file, MAX_SIDE));
}

// The map_png fuzz target's finding (tests/fuzz/regressions/map_png): a tEXt chunk claiming
// 1.85 GB, which took 2 GB of memory before the read failed.
TEST(PngChunks, AChunkClaimingMoreThanTheFileIsRefusedByName) {
    PngBytes png;
    png.header(8, 6).u32(1852243990u);
    png.bytes += "tEXtoiio:ColorSpace";
    const auto file = png.write("claims");
    auto checked = checkImageHeader(file, MAX_SIDE);
    ASSERT_FALSE(checked);
    const std::string message = checked.error().str();
    EXPECT_NE(message.find("map.png"), std::string::npos) << message;
    EXPECT_NE(message.find("chunk \"tEXt\" claims 1852243990 bytes"), std::string::npos) << message;
    auto loaded = loadMapImage(file);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().str(), message);
    // The PNG limit on a chunk's length is 2^31 - 1 whatever the file holds.
    PngBytes over;
    over.header(8, 6).u32(0x80000000u);
    over.bytes += std::string(64, 'x');
    checked = checkPngChunks(over.write("over"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("claims 2147483648 bytes"), std::string::npos);
}

TEST(PngChunks, TheHeaderMustComeFirstAndFitTheLimit) {
    PngBytes wide;
    wide.header(65536, 2).chunk("IDAT", "xx").chunk("IEND", "");
    auto checked = checkPngChunks(wide.write("wide"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("65536×2"), std::string::npos) << checked.error().str();
    EXPECT_NE(checked.error().str().find("refused before decoding"), std::string::npos);

    PngBytes noHeader;
    noHeader.chunk("IDAT", "xx").chunk("IEND", "");
    checked = checkPngChunks(noHeader.write("no_header"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("the first chunk is \"IDAT\" of 2 bytes, not a 13-byte IHDR"),
              std::string::npos)
        << checked.error().str();

    PngBytes noEnd;
    noEnd.header(4, 4).chunk("IDAT", "xx");
    checked = checkPngChunks(noEnd.write("no_end"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("ends before the IEND"), std::string::npos);

    PngBytes fits;
    fits.header(4, 4).chunk("IDAT", "xx").chunk("IEND", "");
    EXPECT_TRUE(checkPngChunks(fits.write("fits"), MAX_SIDE));
}

// Every PNG ends with the same 12 bytes: IEND, empty, CRC ae 42 60 82.
TEST(PngChunks, TheCrcIsPngsCrc32) {
    const std::string iend = "IEND";
    EXPECT_EQ(pngCrc(0, reinterpret_cast<const unsigned char*>(iend.data()), 4), 0xae426082u);
    // Continuing a CRC is the CRC of the whole.
    const std::string text = "tEXtComment";
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    EXPECT_EQ(pngCrc(pngCrc(0, bytes, 4), bytes + 4, text.size() - 4),
              pngCrc(0, bytes, text.size()));
}

// PngSuite's corrupt files (xcsn0g01: IDAT CRC, xhdn0g08: IHDR CRC) made libpng print its own
// "libpng error: …" line before ours; now one line names the chunk. An ancillary chunk with a
// bad CRC is left to libpng, which drops it with a warning and reads the image.
TEST(PngChunks, ACriticalChunkWithABadCrcIsRefusedAnAncillaryOneIsNot) {
    PngBytes badData;
    badData.header(4, 4).chunk("IDAT", "xx", 0x12345678u).chunk("IEND", "");
    auto checked = checkPngChunks(badData.write("bad_idat_crc"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("chunk \"IDAT\" fails its CRC check"), std::string::npos)
        << checked.error().str();

    PngBytes badText;
    badText.header(4, 4).chunk("tEXt", "a\0b", 0x12345678u).chunk("IDAT", "xx").chunk("IEND", "");
    EXPECT_TRUE(checkPngChunks(badText.write("bad_text_crc"), MAX_SIDE));
}

TEST(PngChunks, TheHeaderMustDescribeAPngAndThePixelsMustCome) {
    const std::pair<int, int> undefined[] = {{8, 9}, {3, 2}, {16, 3}, {4, 6}, {2, 2}};
    for (const auto& [depth, colourType] : undefined) {
        PngBytes png;
        png.header(4, 4, depth, colourType).chunk("IDAT", "xx").chunk("IEND", "");
        auto checked = checkPngChunks(png.write("undefined"), MAX_SIDE);
        ASSERT_FALSE(checked) << depth << " " << colourType;
        EXPECT_NE(checked.error().str().find("colour type " + std::to_string(colourType) +
                                             " at bit depth " + std::to_string(depth)),
                  std::string::npos)
            << checked.error().str();
    }
    for (const auto& [depth, colourType] : {std::pair{16, 0}, {1, 3}, {16, 6}, {8, 4}}) {
        PngBytes png;
        png.header(4, 4, depth, colourType);
        if (colourType == 3)
            png.chunk("PLTE", std::string(6, '\0'));
        png.chunk("IDAT", "xx").chunk("IEND", "");
        EXPECT_TRUE(checkPngChunks(png.write("defined"), MAX_SIDE)) << depth << " " << colourType;
    }

    PngBytes noPalette;
    noPalette.header(4, 4, 8, 3).chunk("IDAT", "xx").chunk("IEND", "");
    auto checked = checkPngChunks(noPalette.write("no_palette"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("without a PLTE"), std::string::npos);

    PngBytes noPixels;  // PngSuite's xdtn0g01
    noPixels.header(4, 4).chunk("IEND", "");
    checked = checkPngChunks(noPixels.write("no_pixels"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("IEND comes before any IDAT"), std::string::npos);

    PngBytes shortHeader;
    shortHeader.chunk("IHDR", std::string(12, '\1')).chunk("IDAT", "xx").chunk("IEND", "");
    checked = checkPngChunks(shortHeader.write("short_header"), MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("not a 13-byte IHDR"), std::string::npos);
}

// Found by the map_png and grass_texture fuzz targets: a 45-byte GIF (named .png then) whose
// logical screen is 41794×11683; OpenImageIO's GIF reader allocated that canvas on open, 1.5 GB,
// before its size could be refused.
TEST(ImageHeader, AGifScreenOverTheLimitIsRefusedBeforeDecoding) {
    const auto dir = test::scratchDir("gif_header");
    const auto wide = dir / "wide.gif";
    std::ofstream(wide, std::ios::binary) << std::string("GIF87aB\xa3\xa3-\0\0\0", 13);
    auto checked = checkImageHeader(wide, MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("41794×11683"), std::string::npos)
        << checked.error().str();
    auto map = loadMapImage(wide);
    ASSERT_FALSE(map);
    EXPECT_EQ(map.error().str(), checked.error().str());

    const auto small = dir / "small.gif";
    std::ofstream(small, std::ios::binary) << std::string("GIF89a\x10\0\x08\0\0\0\0", 13);
    EXPECT_TRUE(checkImageHeader(small, MAX_SIDE));
    const auto cut = dir / "cut.gif";
    std::ofstream(cut, std::ios::binary) << "GIF89a\x10";
    checked = checkImageHeader(cut, MAX_SIDE);
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().str().find("a damaged GIF"), std::string::npos);
}

TEST(ImageHeader, OtherFilesPassUnchecked) {
    const auto file = test::scratchDir("image_header_other") / "map.tif";
    ASSERT_TRUE(saveMapImage(makeConstantMap(4, 4, 0.5f), file, MapSampleFormat::Auto));
    EXPECT_TRUE(checkImageHeader(file, MAX_SIDE));
    const auto text = test::scratchDir("image_header_text") / "notes.png";
    std::ofstream(text) << "not an image\n";
    EXPECT_TRUE(checkImageHeader(text, MAX_SIDE));
}

}  // namespace
}  // namespace grass::core
