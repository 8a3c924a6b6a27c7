// "Did you mean …?" for mistyped commands and options (util/nearest_name.h).
#include "util/nearest_name.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/arg_parser.h"

namespace grass::core {
namespace {

TEST(NearestName, CountsEditsIncludingASwapOfNeighbours) {
    EXPECT_EQ(editDistance("render", "render"), 0u);
    EXPECT_EQ(editDistance("rendr", "render"), 1u);     // a letter left out
    EXPECT_EQ(editDistance("--widht", "--width"), 1u);  // two letters swapped
    EXPECT_EQ(editDistance("Export", "export"), 0u);    // case does not count
    EXPECT_EQ(editDistance("sim", "soak"), 3u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
}

TEST(NearestName, SuggestsOnlyANameNearEnough) {
    const std::vector<std::string> commands = {"render", "sim",      "mesh-info", "paint", "export",
                                               "bench",  "tradeoff", "presets",   "soak"};
    EXPECT_EQ(nearestName("rendr", commands), "render");
    EXPECT_EQ(nearestName("exprot", commands), "export");
    EXPECT_EQ(nearestName("meshinfo", commands), "mesh-info");
    EXPECT_EQ(nearestName("Render", commands), "render");  // the spelling that works
    EXPECT_EQ(nearestName("simm", commands), "sim");
    EXPECT_FALSE(nearestName("render", commands).has_value());  // nothing to correct
    EXPECT_FALSE(nearestName("view", commands).has_value());
    EXPECT_FALSE(nearestName("sx", commands).has_value());  // short names: one edit at most
    EXPECT_FALSE(nearestName("", commands).has_value());
}

TEST(NearestName, AnUnknownOptionSaysWhichWasMeant) {
    ArgParser parser("test", "a test");
    int width = 0;
    parser.integer("--width", "the width", &width, 1, 100);
    auto parsed = parser.parse({"--widht", "3"});
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.error().str(), "--widht: unknown option; did you mean --width? (see --help)");
    parsed = parser.parse({"--colour", "3"});
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.error().str(), "--colour: unknown option (see --help)");
}

}  // namespace
}  // namespace grass::core
