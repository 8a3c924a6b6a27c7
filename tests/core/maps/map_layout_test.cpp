// Maps read as viewers show the file (docs/project-format.md, maps), found wrong with real
// third-party images: an orientation tag, OpenEXR's data window and channel names, separate-plane
// TIFFs, files of several images, WebP's alpha and a TIFF that crashes OpenImageIO 2.4.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <string>
#include <vector>

#include "maps/map_channels.h"
#include "maps/map_image.h"
#include "support/scratch_folder.h"
#include "support/spec_on_disk.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using test::ScratchFolder;

// Writes `pixels` (float, interleaved) with `spec` as given: its attributes, windows and names.
void writeSpec(const fs::path& file, const OIIO::ImageSpec& spec,
               const std::vector<float>& pixels) {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out) << file;
    ASSERT_TRUE(out->open(file.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

bool anyWarning(const MapImage& map, const std::string& part) {
    for (const std::string& warning : map.warnings)
        if (warning.find(part) != std::string::npos)
            return true;
    return false;
}

std::string allWarnings(const MapImage& map) {
    std::string all;
    for (const std::string& warning : map.warnings)
        all += warning + " | ";
    return all;
}

// A phone photo held on its side is stored sideways with Orientation 6; every viewer turns it.
// Stored 3×2 (0 .. 5 row by row): shown 2×3 with stored row 0 down the right edge.
TEST(MapLayout, AnOrientationTagTurnsTheMapAsViewersShowIt) {
    const ScratchFolder dir("map-orientation");
    OIIO::ImageSpec spec(3, 2, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("Orientation", 6);
    writeSpec(dir / "turned.tif", spec, {0.0f, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f});
    const auto map = loadMapImage(dir / "turned.tif");
    ASSERT_TRUE(map.ok()) << map.error().str();
    ASSERT_EQ(map->width, 2);
    ASSERT_EQ(map->height, 3);
    const std::vector<float> shown = {0.3f, 0.0f, 0.4f, 0.1f, 0.5f, 0.2f};
    for (std::size_t i = 0; i < shown.size(); ++i)
        EXPECT_FLOAT_EQ(map->texels[i], shown[i]) << i;
    EXPECT_TRUE(anyWarning(*map, "turned 90° clockwise")) << allWarnings(*map);
}

// OpenEXR: the data window is what is stored, the display window the picture; a render's crop
// stores only where something is. The map is the display window, black around the data.
TEST(MapLayout, AnExrDataWindowIsPlacedInItsDisplayWindow) {
    const ScratchFolder dir("map-window");
    OIIO::ImageSpec spec(2, 1, 1, OIIO::TypeDesc::HALF);
    spec.x = 1;
    spec.y = 2;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = 4;
    spec.full_height = 3;
    writeSpec(dir / "crop.exr", spec, {0.5f, 0.75f});
    const auto map = loadMapImage(dir / "crop.exr");
    ASSERT_TRUE(map.ok()) << map.error().str();
    ASSERT_EQ(map->width, 4);
    ASSERT_EQ(map->height, 3);
    EXPECT_EQ(map->texels, (std::vector<float>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0.5f, 0.75f, 0}));
    EXPECT_TRUE(anyWarning(*map, "data window 2×1 at (1, 2) placed in its 4×3 display window"))
        << allWarnings(*map);
}

// Channels by name: OpenEXR keeps any names, sorted (A before R); an image of depth and green
// is neither grey nor grey + alpha.
TEST(MapLayout, ChannelsAreChosenByTheirNames) {
    OIIO::ImageSpec sorted(1, 1, 4, OIIO::TypeDesc::HALF);
    sorted.channelnames = {"A", "B", "G", "R"};
    sorted.alpha_channel = 0;
    const MapChannels rgb = chooseMapChannels(sorted);
    ASSERT_EQ(rgb.weights.size(), 3u);
    EXPECT_EQ(rgb.weights[0], (std::pair<int, float>{3, 0.2126f}));  // R
    EXPECT_EQ(rgb.weights[2], (std::pair<int, float>{1, 0.0722f}));  // B
    EXPECT_NE(rgb.note.find("alpha ignored"), std::string::npos) << rgb.note;

    const ScratchFolder dir("map-channels");
    OIIO::ImageSpec depth(2, 1, 2, OIIO::TypeDesc::FLOAT);
    depth.channelnames = {"G", "Z"};
    depth.alpha_channel = -1;
    writeSpec(dir / "gz.exr", depth, {0.25f, 7.0f, 0.5f, 9.0f});
    const auto gz = loadMapImage(dir / "gz.exr");
    ASSERT_TRUE(gz.ok()) << gz.error().str();
    EXPECT_EQ(gz->texels, (std::vector<float>{0.25f, 0.5f}));
    EXPECT_TRUE(anyWarning(*gz, "G read as the value, Z ignored")) << allWarnings(*gz);
    EXPECT_FALSE(anyWarning(*gz, "grey + alpha")) << allWarnings(*gz);

    OIIO::ImageSpec luminance(2, 1, 2, OIIO::TypeDesc::FLOAT);
    luminance.channelnames = {"A", "Y"};
    luminance.alpha_channel = 0;
    writeSpec(dir / "ya.exr", luminance, {0.0f, 0.3f, 1.0f, 0.6f});
    const auto ya = loadMapImage(dir / "ya.exr");
    ASSERT_TRUE(ya.ok()) << ya.error().str();
    EXPECT_EQ(ya->texels, (std::vector<float>{0.3f, 0.6f}));

    OIIO::ImageSpec alphaOnly(2, 1, 1, OIIO::TypeDesc::FLOAT);
    alphaOnly.channelnames = {"A"};
    alphaOnly.alpha_channel = 0;
    writeSpec(dir / "a.exr", alphaOnly, {0.2f, 0.9f});
    const auto a = loadMapImage(dir / "a.exr");
    ASSERT_TRUE(a.ok()) << a.error().str();
    EXPECT_EQ(a->texels, (std::vector<float>{0.2f, 0.9f}));
    EXPECT_TRUE(anyWarning(*a, "its only channel is alpha (A): read as the value"))
        << allWarnings(*a);
}

// A render's OpenEXR keeps its channels sorted by name (A, B, G, N.x, P.x, R, Z); OpenImageIO
// hands R, G, B, A, Z out first, and the map reads the luminance of R, G and B.
TEST(MapLayout, ARendersChannelsReadTheirLuminance) {
    const ScratchFolder dir("map-render");
    OIIO::ImageSpec spec(1, 1, 7, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"A", "B", "G", "N.x", "P.x", "R", "Z"};
    spec.alpha_channel = 0;
    writeSpec(dir / "render.exr", spec, {0.5f, 0.0f, 0.0f, 9.0f, 9.0f, 1.0f, 9.0f});
    ASSERT_EQ(test::specOnDisk(dir / "render.exr").channel_name(0), "R");
    const auto map = loadMapImage(dir / "render.exr");
    ASSERT_TRUE(map.ok()) << map.error().str();
    EXPECT_NEAR(map->texels[0], 0.2126f, 1e-6f);
    EXPECT_TRUE(anyWarning(*map, "A, Z, N.x, P.x ignored")) << allWarnings(*map);
}

// A PNG cropped by a tool that keeps the page offset (an oFFs chunk; OpenImageIO reads it as the
// data window's origin) is read as stored, as viewers show it.
TEST(MapLayout, APngOffsetIsNotAWindow) {
    const ScratchFolder dir("map-png-offset");
    OIIO::ImageSpec spec(3, 1, 1, OIIO::TypeDesc::UINT8);
    spec.x = 100;
    spec.y = 50;
    writeSpec(dir / "cropped.png", spec, {0.0f, 0.4f, 1.0f});
    ASSERT_EQ(test::specOnDisk(dir / "cropped.png").x, 100);  // the offset is in the file
    const auto map = loadMapImage(dir / "cropped.png");
    ASSERT_TRUE(map.ok()) << map.error().str();
    ASSERT_EQ(map->width, 3);
    ASSERT_EQ(map->height, 1);
    EXPECT_NEAR(map->texels[1], 0.4f, 0.5f / 255.0f);
    EXPECT_FALSE(anyWarning(*map, "window")) << allWarnings(*map);
}

// libtiff reads a compressed separate-plane TIFF only from the top, whole: a read in bands of
// 256 rows failed on the first band ("Compression algorithm does not support random access").
// OpenImageIO's writer stores one row a strip, which hides it; the file (tests/data/README.md)
// has 29 rows a strip, LZW, like the real one that failed. Its middle column is R = row mod 256,
// G = 255 − R, B = 128.
TEST(MapLayout, ASeparatePlaneTiffTallerThanABandIsRead) {
    const fs::path file = test::sourceDir() / "tests/data/maps/separate_planes.tif";
    const OIIO::ImageSpec stored = test::specOnDisk(file);
    ASSERT_EQ(stored.get_string_attribute("planarconfig"), "separate");
    ASSERT_EQ(stored.get_int_attribute("tiff:RowsPerStrip"), 29);
    const auto map = loadMapImage(file);
    ASSERT_TRUE(map.ok()) << map.error().str();
    ASSERT_EQ(map->width, 3);
    ASSERT_EQ(map->height, 600);
    for (int row : {0, 255, 256, 511, 599}) {
        const float r = static_cast<float>(row % 256) / 255.0f;
        const float expected = 0.2126f * r + 0.7152f * (1.0f - r) + 0.0722f * (128.0f / 255.0f);
        EXPECT_NEAR(map->at(1, row), expected, 1e-5f) << row;
        EXPECT_EQ(map->at(0, row), 0.0f) << row;
    }
}

TEST(MapLayout, AFileOfSeveralImagesReadsTheFirstAndSaysSo) {
    const ScratchFolder dir("map-subimages");
    const fs::path file = dir / "pages.tif";
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    const OIIO::ImageSpec specs[2] = {OIIO::ImageSpec(2, 1, 1, OIIO::TypeDesc::FLOAT),
                                      OIIO::ImageSpec(2, 1, 1, OIIO::TypeDesc::FLOAT)};
    ASSERT_TRUE(out->open(file.string(), 2, specs)) << out->geterror();
    const std::vector<float> first = {0.1f, 0.2f}, second = {0.8f, 0.9f};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, first.data()));
    ASSERT_TRUE(out->open(file.string(), specs[1], OIIO::ImageOutput::AppendSubimage));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, second.data()));
    ASSERT_TRUE(out->close());
    const auto map = loadMapImage(file);
    ASSERT_TRUE(map.ok()) << map.error().str();
    EXPECT_EQ(map->texels, first);
    EXPECT_TRUE(anyWarning(*map, "holds several images")) << allWarnings(*map);
}

// OpenImageIO 2.4's WebP reader multiplies the colour by alpha whatever oiio:UnassociatedAlpha
// says: a half-covered texel stored as grey 204 read 0.4 for its 0.8. (Its WebP writer is no
// help for the test: it divides the colour by alpha in linear light on the way in.) The file,
// made with Pillow (tests/data/README.md), stores (204, 204, 204, 128) and (0, 0, 0, 0).
TEST(MapLayout, WebpAlphaDoesNotDarkenTheValues) {
    const auto map = loadMapImage(test::sourceDir() / "tests/data/maps/half_covered.webp");
    ASSERT_TRUE(map.ok()) << map.error().str();
    // The reader's premultiplied 8 bits (102 of 255) divided by 128/255: within 1.5 levels.
    EXPECT_NEAR(map->texels[0], 204.0f / 255.0f, 1.5f / 255.0f);
    EXPECT_EQ(map->texels[1], 0.0f);  // no colour is left where alpha is 0
    EXPECT_TRUE(anyWarning(*map, "1 transparent texels read as 0")) << allWarnings(*map);
}

// A tiled CMYK TIFF crashed OpenImageIO 2.4 (a heap overrun in its tile conversion; valgrind
// shows it on both files): refused before a pixel is read, by every reader that opens images.
TEST(MapLayout, TiledCmykTiffsAreRefusedBeforeTheyCrash) {
    for (const char* name : {"cmyk_tiled_jpeg.tif", "cmyk_tiled_lzw.tif"}) {
        const fs::path file = test::sourceDir() / "tests/data/maps" / name;
        const auto map = loadMapImage(file);
        ASSERT_FALSE(map.ok()) << name;
        EXPECT_NE(map.error().str().find(name), std::string::npos) << map.error().str();
        EXPECT_NE(map.error().str().find("a tiled CMYK TIFF is not read"), std::string::npos)
            << map.error().str();
        const auto pixels = readRgba8Image(file);
        ASSERT_FALSE(pixels.ok()) << name;
        EXPECT_NE(pixels.error().str().find("tiled CMYK"), std::string::npos)
            << pixels.error().str();
    }
}

// Found by the map_tiff fuzz target (tests/fuzz/README.md): channels R, A, B and strips that end
// early. Asking OpenImageIO 2.4 for channel R alone made its TIFF reader free memory it had not
// allocated (an abort); all channels are read now, and the error is one short line.
TEST(MapLayout, ADamagedTiffIsReadWithAllItsChannels) {
    const fs::path file =
        test::sourceDir() / "tests/fuzz/regressions/map_tiff/some-channels-of-a-damaged-strip.tif";
    const auto map = loadMapImage(file);
    ASSERT_FALSE(map.ok());
    const std::string message = map.error().str();
    EXPECT_NE(message.find("cannot read the pixels"), std::string::npos) << message;
    EXPECT_NE(message.find("more)"), std::string::npos) << message;
    EXPECT_LT(message.size(), 600u) << message;
}

}  // namespace
}  // namespace grass::core
