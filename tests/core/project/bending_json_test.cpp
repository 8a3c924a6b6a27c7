// A layer's "bending" in project.json (issue 30 item 1): read, written back the same, absent in
// old files, and every bad value refused with its JSON pointer.
#include <gtest/gtest.h>

#include "project/project.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

std::string layerWithBending(const std::string& bending) {
    return R"({"format": "grass-project", "version": 2, "layers": [{"name": "grass", "bending": {)" +
           bending + "}}]}";
}

TEST(BendingJson, EveryCueIsReadAndWrittenBack) {
    const auto parsed = parseProject(
        layerWithBending(R"("slope": 0.5, "neighbours": 25, "neighbour_radius": 0.2, "sway": 0.75)"),
        "bending.json");
    ASSERT_TRUE(parsed) << parsed.error().str();
    const BendingCues& cues = parsed->layers.at(0).bending;
    EXPECT_EQ(cues.slope, 0.5f);
    EXPECT_EQ(cues.neighboursDeg, 25.0f);
    EXPECT_EQ(cues.neighbourRadiusM, 0.2f);
    EXPECT_EQ(cues.sway, 0.75f);
    const auto again = parseProject(serializeProject(*parsed), "again.json");
    ASSERT_TRUE(again) << again.error().str();
    EXPECT_EQ(again->layers.at(0).bending, cues);
}

TEST(BendingJson, AFileWithoutBendingHasItOff) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 2})", "old.json");
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_EQ(parsed->layers.at(0).bending, BendingCues{});
}

TEST(BendingJson, BadCuesAreRefusedWithTheirPointer) {
    using test::expectProjectError;
    expectProjectError(layerWithBending(R"("slope": 1.5)"), "b.json", "/layers/0/bending/slope",
                       "[0, 1]");
    expectProjectError(layerWithBending(R"("neighbours": 90)"), "b.json",
                       "/layers/0/bending/neighbours", "[0, 60]");
    expectProjectError(layerWithBending(R"("neighbour_radius": 0)"), "b.json",
                       "/layers/0/bending/neighbour_radius", "[0.01, 10]");
    expectProjectError(layerWithBending(R"("sway": "much")"), "b.json", "/layers/0/bending/sway",
                       "number");
    expectProjectError(layerWithBending(R"("slop": 0.5)"), "b.json", "/layers/0/bending/slop",
                       "did you mean \"slope\"");
}

}  // namespace
}  // namespace grass::core
