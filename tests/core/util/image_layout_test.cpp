// Where stored pixels show (util/image_layout.h): the eight EXIF orientations and OpenEXR's data
// window, checked against the EXIF definitions (where the stored row 0 and column 0 lie as
// shown), not against the code's own table.
#include "util/image_layout.h"

#include <gtest/gtest.h>

#include <vector>

namespace grass::core {
namespace {

// A 3×2 picture stored as written: values 0 1 2 / 3 4 5 (row 0 first).
const std::vector<float> STORED = {0, 1, 2, 3, 4, 5};

ImageLayout plain(int orientation) {
    ImageLayout layout;
    layout.orientation = orientation;
    layout.dataWidth = layout.fullWidth = 3;
    layout.dataHeight = layout.fullHeight = 2;
    return layout;
}

// Shown pictures, row by row, as EXIF (CIPA DC-008, tag 274) defines them: e.g. 6 "the 0th row
// is the visual right-hand side, the 0th column the visual top": stored row 0 (0 1 2) runs down
// the right edge, its first pixel at the top.
TEST(ImageLayout, EveryOrientationShowsTheStoredRowsWhereExifSays) {
    const std::vector<std::vector<float>> shown = {
        {},
        {0, 1, 2, 3, 4, 5},  // 1: as stored
        {2, 1, 0, 5, 4, 3},  // 2: row 0 top, column 0 right
        {5, 4, 3, 2, 1, 0},  // 3: row 0 bottom, column 0 right
        {3, 4, 5, 0, 1, 2},  // 4: row 0 bottom, column 0 left
        {0, 3, 1, 4, 2, 5},  // 5: row 0 left, column 0 top
        {3, 0, 4, 1, 5, 2},  // 6: row 0 right, column 0 top
        {5, 2, 4, 1, 3, 0},  // 7: row 0 right, column 0 bottom
        {2, 5, 1, 4, 0, 3},  // 8: row 0 left, column 0 bottom
    };
    for (int orientation = 1; orientation <= 8; ++orientation) {
        const ImageLayout layout = plain(orientation);
        EXPECT_EQ(layout.shownWidth(), orientation >= 5 ? 2 : 3) << orientation;
        EXPECT_EQ(layout.shownHeight(), orientation >= 5 ? 3 : 2) << orientation;
        EXPECT_EQ(showImage(STORED, 1, layout), shown[static_cast<std::size_t>(orientation)])
            << "orientation " << orientation;
    }
}

TEST(ImageLayout, ChannelsMoveTogether) {
    const std::vector<std::uint8_t> rgb = {10, 11, 12, 20, 21, 22};  // 2×1, two RGB pixels
    ImageLayout layout;
    layout.orientation = 2;
    layout.dataWidth = layout.fullWidth = 2;
    layout.dataHeight = layout.fullHeight = 1;
    EXPECT_EQ(showImage(rgb, 3, layout), (std::vector<std::uint8_t>{20, 21, 22, 10, 11, 12}));
}

TEST(ImageLayout, TheDataWindowSitsInTheDisplayWindowWithBlackAround) {
    OIIO::ImageSpec spec(2, 1, 1, OIIO::TypeDesc::FLOAT);
    spec.x = 3;  // the data window (3, 1) .. (4, 1) of a display window (2, 0) .. (5, 2)
    spec.y = 1;
    spec.full_x = 2;
    spec.full_y = 0;
    spec.full_width = 4;
    spec.full_height = 3;
    const ImageLayout layout = imageLayout(spec, "openexr");
    ASSERT_TRUE(layout.windowed());
    EXPECT_EQ(showImage(std::vector<float>{7, 8}, 1, layout),
              (std::vector<float>{0, 0, 0, 0, 0, 7, 8, 0, 0, 0, 0, 0}));
    const std::vector<std::string> notes = imageLayoutNotes(layout);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("data window 2×1 at (1, 1)"), std::string::npos) << notes[0];
    EXPECT_NE(notes[0].find("4×3 display window"), std::string::npos) << notes[0];

    // Partly outside the display window: what lies outside is dropped, nothing is written out
    // of bounds.
    spec.x = 5;  // column 3 of the display, and one beyond it
    EXPECT_EQ(showImage(std::vector<float>{7, 8}, 1, imageLayout(spec, "openexr")),
              (std::vector<float>{0, 0, 0, 0, 0, 0, 0, 7, 0, 0, 0, 0}));
    spec.x = 6;  // wholly beyond
    EXPECT_EQ(showImage(std::vector<float>{7, 8}, 1, imageLayout(spec, "openexr")),
              (std::vector<float>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
    spec.x = -2147483647;  // far to the left: no offset overflows
    EXPECT_EQ(showImage(std::vector<float>{7, 8}, 1, imageLayout(spec, "openexr")),
              (std::vector<float>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
}

// OpenEXR's cube environment maps stack six faces in the data window under a display window of
// one face (OpenEXR's own "WavyCube" sample: 256×1536 under 256×256): all six are the picture.
// OpenImageIO puts a PNG's oFFs offset (ImageMagick writes one after a crop that keeps its
// page) in the data window's origin; viewers ignore it, and so do maps.
TEST(ImageLayout, OnlyOpenExrWindowsCount) {
    OIIO::ImageSpec spec(3, 2, 1, OIIO::TypeDesc::UINT8);
    spec.x = 100;
    spec.y = 50;
    EXPECT_TRUE(imageLayout(spec, "openexr").windowed());
    EXPECT_FALSE(imageLayout(spec, "png").windowed());
    EXPECT_EQ(showImage(STORED, 1, imageLayout(spec, "png")), STORED);
}

TEST(ImageLayout, AnEnvironmentMapIsItsWholeDataWindow) {
    OIIO::ImageSpec spec(4, 24, 1, OIIO::TypeDesc::HALF);
    spec.full_width = 4;
    spec.full_height = 4;
    EXPECT_TRUE(imageLayout(spec, "openexr").windowed());
    spec.attribute("textureformat", "CubeFace Environment");
    const ImageLayout layout = imageLayout(spec, "openexr");
    EXPECT_FALSE(layout.windowed());
    EXPECT_EQ(layout.shownHeight(), 24);
}

TEST(ImageLayout, AnUnknownOrientationIsShownAsStoredAndAnEmptyDisplayWindowIsTheData) {
    OIIO::ImageSpec spec(3, 2, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("Orientation", 9);
    spec.full_width = 0;
    const ImageLayout layout = imageLayout(spec, "openexr");
    EXPECT_EQ(layout.orientation, 1);
    EXPECT_FALSE(layout.windowed());
    EXPECT_TRUE(imageLayoutNotes(layout).empty());
    spec.attribute("Orientation", 8);
    const std::vector<std::string> notes = imageLayoutNotes(imageLayout(spec, "openexr"));
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("turned 90° anticlockwise"), std::string::npos) << notes[0];
}

TEST(ImageLayout, AlphaIsFoundByOpenImageIosIndexWhenInRangeElseByName) {
    OIIO::ImageSpec spec(1, 1, 4, OIIO::TypeDesc::UINT8);  // R G B A, alpha 3
    EXPECT_EQ(alphaChannelOf(spec), 3);
    spec.alpha_channel = 4;  // OpenImageIO 2.4's GIF reader: one past the last channel
    EXPECT_EQ(alphaChannelOf(spec), 3);
    spec.channelnames = {"A", "B", "G", "R"};  // OpenEXR's order
    spec.alpha_channel = -1;
    EXPECT_EQ(alphaChannelOf(spec), 0);
    spec.channelnames = {"Y", "Z", "G", "R"};
    EXPECT_EQ(alphaChannelOf(spec), -1);
}

}  // namespace
}  // namespace grass::core
