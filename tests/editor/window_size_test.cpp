// The editor window's first size (app/window_size.h): the project's size when the screen holds
// it, else smaller with the same shape.
#include "app/window_size.h"

#include <gtest/gtest.h>

namespace grass::editor {
namespace {

TEST(WindowSize, AProjectSizeTheScreenHoldsIsKept) {
    EXPECT_EQ(fitWindowSize({1280, 720}, 1920, 1050), (WindowSize{1280, 720}));
    EXPECT_EQ(fitWindowSize({1280, 720}, 0, 0), (WindowSize{1280, 720})) << "no area known";
}

TEST(WindowSize, ALargerOneShrinksToTheWorkAreaKeepingItsShape) {
    // 800 × 600 (Xvfb's screen where the status bar was cut off): 1280 × 720 does not fit.
    const WindowSize fitted = fitWindowSize({1280, 720}, 800, 600);
    EXPECT_LE(fitted.width, 800);
    EXPECT_LE(fitted.height, 600 - WINDOW_FRAME_ALLOWANCE);
    EXPECT_NEAR(double(fitted.width) / fitted.height, 1280.0 / 720.0, 0.01);
    EXPECT_GE(fitted.width, 780) << "no smaller than it must be";
    // A 4K project on a 1366 × 768 laptop, and the same screen at twice the pixels a unit.
    const WindowSize laptop = fitWindowSize({3840, 2160}, 1366, 740);
    EXPECT_LE(laptop.height, 740 - WINDOW_FRAME_ALLOWANCE);
    const WindowSize hiDpi = fitWindowSize({3840, 2160}, 1366, 740, 2.0f);
    EXPECT_LE(hiDpi.height * 2, 740 - WINDOW_FRAME_ALLOWANCE);
    EXPECT_NEAR(double(hiDpi.width) / hiDpi.height, 16.0 / 9.0, 0.01);
}

// The window cannot be made narrower than the panels are laid out for (800 × 480 points), at the
// screen's scale, unless it was created smaller (a test's or a script's size).
TEST(WindowSize, TheLeastSizeIsThePanelsUnlessCreatedSmaller) {
    EXPECT_EQ(leastWindowSize({1280, 720}, 1.0f), (WindowSize{800, 480}));
    EXPECT_EQ(leastWindowSize({2560, 1440}, 2.0f), (WindowSize{1600, 960})) << "HiDPI pixels";
    EXPECT_EQ(leastWindowSize({640, 720}, 1.0f), (WindowSize{640, 480})) << "created narrower";
    EXPECT_EQ(leastWindowSize({320, 240}, 1.0f), (WindowSize{320, 240}));
    EXPECT_EQ(leastWindowSize({1280, 720}, 0.0f), (WindowSize{800, 480})) << "no scale known";
}

}  // namespace
}  // namespace grass::editor
