#include "util/contact_sheet.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "util/rng.h"

namespace grass {
namespace {

Rgba8Pixels filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                   std::uint8_t a = 255) {
    Rgba8Pixels image{width, height, {}};
    for (int i = 0; i < width * height; ++i)
        image.pixels.insert(image.pixels.end(), {r, g, b, a});
    return image;
}

const std::uint8_t* pixelAt(const Rgba8Pixels& image, int x, int y) {
    return &image.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                          static_cast<std::size_t>(x)) *
                         4];
}

TEST(ContactSheet, FewFramesMakeOneRowOfFullSizeCells) {
    // tests/cli/turntable_cli_tests.cmake checks this size on the tiny project's 64 × 48 views.
    const ContactSheetLayout layout = contactSheetLayout(4, 64, 48);
    EXPECT_EQ(layout.columns, 4);
    EXPECT_EQ(layout.rows, 1);
    EXPECT_EQ(layout.cellWidth, 64);
    EXPECT_EQ(layout.cellHeight, 48);
    EXPECT_EQ(layout.frames, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(layout.width(), 4 * 64 + 5 * 2);
    EXPECT_EQ(layout.height(), 48 + 2 * 2);
}

TEST(ContactSheet, LargeFramesShrinkToTheCellWidthKeepingTheirAspect) {
    const ContactSheetLayout layout = contactSheetLayout(8, 1280, 720);
    EXPECT_EQ(layout.columns, 8);
    EXPECT_EQ(layout.rows, 1);
    EXPECT_EQ(layout.cellWidth, 256);
    EXPECT_EQ(layout.cellHeight, 144);
    const ContactSheetLayout odd = contactSheetLayout(3, 1000, 333);
    EXPECT_EQ(odd.cellWidth, 256);
    EXPECT_EQ(odd.cellHeight, 85);  // 333 · 256 / 1000 = 85.2
}

TEST(ContactSheet, RowsFillUpToEightColumns) {
    const ContactSheetLayout layout = contactSheetLayout(20, 64, 48);
    EXPECT_EQ(layout.columns, 8);
    EXPECT_EQ(layout.rows, 3);
    EXPECT_EQ(layout.frames.size(), 20u);
    EXPECT_EQ(layout.cellOf(19), 19);
}

TEST(ContactSheet, LongTurnsShowAnEvenSelectionStartingAtFrameZero) {
    const ContactSheetLayout layout = contactSheetLayout(3600, 640, 360);
    ASSERT_EQ(layout.frames.size(), 64u);
    EXPECT_EQ(layout.rows, 8);
    EXPECT_EQ(layout.frames.front(), 0);
    // 3600 / 64 = 56.25 frames apart: 56 or 57, never bunched up or skipping a stretch.
    for (std::size_t i = 1; i < layout.frames.size(); ++i) {
        const int gap = layout.frames[i] - layout.frames[i - 1];
        EXPECT_TRUE(gap == 56 || gap == 57) << "cell " << i << ": " << gap;
    }
    EXPECT_GE(layout.frames.back(), 3600 - 57);
    EXPECT_EQ(layout.cellOf(0), 0);
    EXPECT_EQ(layout.cellOf(1), -1);
    EXPECT_EQ(layout.cellOf(layout.frames.back()), 63);
}

TEST(ContactSheet, TinyFramesAreNeverEnlarged) {
    const ContactSheetLayout layout = contactSheetLayout(2, 1, 1);
    EXPECT_EQ(layout.cellWidth, 1);
    EXPECT_EQ(layout.cellHeight, 1);
}

TEST(BoxDownscale, SameSizeIsTheIdentity) {
    Rng rng(7);
    Rgba8Pixels image{5, 3, {}};
    for (int i = 0; i < 5 * 3 * 4; ++i)
        image.pixels.push_back(static_cast<std::uint8_t>(rng.below(256)));
    EXPECT_EQ(boxDownscale(image, 5, 3).pixels, image.pixels);
}

TEST(BoxDownscale, HalvingAveragesEachTwoByTwoBlock) {
    Rgba8Pixels image{2, 2, {0, 0, 0, 255, 100, 0, 0, 255, 0, 200, 0, 255, 0, 0, 40, 255}};
    const Rgba8Pixels small = boxDownscale(image, 1, 1);
    ASSERT_EQ(small.pixels.size(), 4u);
    EXPECT_EQ(small.pixels[0], 25);   // 100 / 4
    EXPECT_EQ(small.pixels[1], 50);   // 200 / 4
    EXPECT_EQ(small.pixels[2], 10);   // 40 / 4
    EXPECT_EQ(small.pixels[3], 255);  // alpha is averaged too
}

TEST(BoxDownscale, ACheckerboardBecomesGreyAndAConstantStaysConstant) {
    Rgba8Pixels checker{64, 48, {}};
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::uint8_t v = (x + y) % 2 ? 255 : 0;
            checker.pixels.insert(checker.pixels.end(), {v, v, v, 255});
        }
    const Rgba8Pixels grey = boxDownscale(checker, 16, 12);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x)
            EXPECT_NEAR(pixelAt(grey, x, y)[0], 128, 1) << x << "," << y;
    // Non-integer ratios: every footprint still holds only the one colour.
    const Rgba8Pixels flat = boxDownscale(filled(37, 23, 10, 200, 30), 11, 7);
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 11; ++x) {
            EXPECT_EQ(pixelAt(flat, x, y)[0], 10);
            EXPECT_EQ(pixelAt(flat, x, y)[1], 200);
            EXPECT_EQ(pixelAt(flat, x, y)[2], 30);
        }
}

TEST(ContactSheet, EachFrameLandsInItsCellInsideTheBorder) {
    const ContactSheetLayout layout = contactSheetLayout(3, 8, 6);
    Rgba8Pixels sheet = blankContactSheet(layout);
    ASSERT_EQ(sheet.width, 3 * 8 + 4 * 2);
    ASSERT_EQ(sheet.height, 6 + 2 * 2);
    const std::uint8_t border = pixelAt(sheet, 0, 0)[0];
    placeInContactSheet(sheet, layout, 0, filled(8, 6, 255, 0, 0));
    placeInContactSheet(sheet, layout, 2, filled(8, 6, 0, 0, 255));
    // Cell 0 spans x 2..9, cell 1 x 12..19 (left empty), cell 2 x 22..29; y 2..7.
    EXPECT_EQ(pixelAt(sheet, 2, 2)[0], 255);
    EXPECT_EQ(pixelAt(sheet, 9, 7)[0], 255);
    EXPECT_EQ(pixelAt(sheet, 10, 4)[0], border);
    EXPECT_EQ(pixelAt(sheet, 15, 4)[0], border);
    EXPECT_EQ(pixelAt(sheet, 22, 2)[2], 255);
    EXPECT_EQ(pixelAt(sheet, 29, 7)[2], 255);
    EXPECT_EQ(pixelAt(sheet, 30, 4)[2], border);
    EXPECT_EQ(pixelAt(sheet, 25, 8)[2], border);
    EXPECT_EQ(pixelAt(sheet, 25, 1)[2], border);
}

}  // namespace
}  // namespace grass
