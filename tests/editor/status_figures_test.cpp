// The status line's figures in the room the window leaves: whole figures are left out, least
// wanted first, instead of the line running past the window's edge mid-word.
#include <gtest/gtest.h>

#include "app/status_figures.h"

namespace grass::editor {
namespace {

// One point a character.
float characters(std::string_view text) {
    return float(text.size());
}

const std::vector<StatusFigure> FIGURES{{"100 blades", 5},
                                        {"physics cpu", 2},
                                        {"cull 1 · grass 2 ms", 1},
                                        {"UI 0.5 ms", 0},
                                        {"10 fps", 3}};

TEST(StatusFigures, AllShowWhereTheyFit) {
    EXPECT_EQ(fitStatusFigures(FIGURES, 1000.0f, characters),
              "100 blades   physics cpu   cull 1 · grass 2 ms   UI 0.5 ms   10 fps");
}

TEST(StatusFigures, TheLeastWantedGoFirstAndTheLineFits) {
    const float full =
        characters("100 blades   physics cpu   cull 1 · grass 2 ms   UI 0.5 ms   10 fps");
    EXPECT_EQ(fitStatusFigures(FIGURES, full - 1.0f, characters),
              "100 blades   physics cpu   cull 1 · grass 2 ms   10 fps");
    EXPECT_EQ(fitStatusFigures(FIGURES, 40.0f, characters), "100 blades   physics cpu   10 fps");
    EXPECT_EQ(fitStatusFigures(FIGURES, 20.0f, characters), "100 blades   10 fps");
    // The most wanted stays, even where nothing fits.
    EXPECT_EQ(fitStatusFigures(FIGURES, 3.0f, characters), "100 blades");
}

TEST(StatusFigures, OfEqualsTheLaterGoesAndEmptyFiguresLeaveNoGap) {
    EXPECT_EQ(fitStatusFigures({{"a", 1}, {"", 9}, {"b", 1}, {"c", 2}}, 1000.0f, characters),
              "a   b   c");
    EXPECT_EQ(fitStatusFigures({{"a", 1}, {"b", 1}, {"c", 2}}, 5.0f, characters), "a   c");
}

}  // namespace
}  // namespace grass::editor
