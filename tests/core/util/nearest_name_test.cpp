// "Did you mean …?" for mistyped commands and options (util/nearest_name.h).
#include "util/nearest_name.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
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
    const std::vector<std::string_view> commands = {
        "render", "sim", "mesh-info", "paint", "export", "bench", "tradeoff", "presets", "soak"};
    EXPECT_EQ(closestMatch("rendr", commands), "render");
    EXPECT_EQ(closestMatch("exprot", commands), "export");
    EXPECT_EQ(closestMatch("meshinfo", commands), "mesh-info");
    EXPECT_EQ(closestMatch("Render", commands), "render");  // the spelling that works
    EXPECT_EQ(closestMatch("simm", commands), "sim");
    EXPECT_FALSE(closestMatch("view", commands).has_value());
    EXPECT_FALSE(closestMatch("colour", commands).has_value());
    EXPECT_FALSE(closestMatch("", commands).has_value());
    // A project key: "fov" is no typo of "name" (project/json_reader.h's unknown keys).
    const std::vector<std::string_view> keys = {"name", "density", "size"};
    EXPECT_EQ(closestMatch("densty", keys), "density");
    EXPECT_EQ(closestMatch("sz", keys), "size");
    EXPECT_FALSE(closestMatch("fov", keys).has_value());
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
