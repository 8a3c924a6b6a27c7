// A layer's "rules" in project.json (issue 27): read, written back the same, and every bad value
// refused with its JSON pointer.
#include <gtest/gtest.h>

#include "project/project.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

std::string layerWithRules(const std::string& rules) {
    return R"({"format": "grass-project", "version": 2, "layers": [{"name": "grass", "rules": {)" +
           rules + "}}]}";
}

TEST(RulesJson, EveryRuleIsReadAndWrittenBack) {
    const auto parsed = parseProject(
        layerWithRules(R"("include": ["Ground", "node 3"], "exclude": ["Clouds"],
                          "slope": [5, 45], "slope_soft": 4, "altitude": [-2, 30.5],
                          "altitude_soft": 1.5, "clearance": 0.75, "clear_colliders": true,
                          "clear_of": ["Trunk"])"),
        "rules.json");
    ASSERT_TRUE(parsed) << parsed.error().str();
    const PlacementRules& rules = parsed->layers.at(0).rules;
    EXPECT_EQ(rules.include, (std::vector<std::string>{"Ground", "node 3"}));
    EXPECT_EQ(rules.exclude, (std::vector<std::string>{"Clouds"}));
    EXPECT_EQ(rules.slopeMinDeg, 5.0f);
    EXPECT_EQ(rules.slopeMaxDeg, 45.0f);
    EXPECT_EQ(rules.slopeSoftDeg, 4.0f);
    EXPECT_EQ(rules.altitudeMinM, -2.0f);
    EXPECT_EQ(rules.altitudeMaxM, 30.5f);
    EXPECT_EQ(rules.altitudeSoftM, 1.5f);
    EXPECT_EQ(rules.clearanceM, 0.75f);
    EXPECT_TRUE(rules.clearColliders);
    EXPECT_EQ(rules.clearOf, (std::vector<std::string>{"Trunk"}));
    const auto again = parseProject(serializeProject(*parsed), "again.json");
    ASSERT_TRUE(again) << again.error().str();
    EXPECT_EQ(again->layers.at(0).rules, rules);
}

TEST(RulesJson, AFileWithoutRulesGrowsEverywhere) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 2})", "old.json");
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_EQ(parsed->layers.at(0).rules, PlacementRules{});
}

TEST(RulesJson, BadRulesAreRefusedWithTheirPointer) {
    using test::expectProjectError;
    expectProjectError(layerWithRules(R"("include": "Ground")"), "r.json",
                       "/layers/0/rules/include", "must be an array of names");
    expectProjectError(layerWithRules(R"("exclude": ["Clouds", 3])"), "r.json",
                       "/layers/0/rules/exclude/1", "string");
    expectProjectError(layerWithRules(R"("clear_of": [""])"), "r.json",
                       "/layers/0/rules/clear_of/0", "empty");
    expectProjectError(layerWithRules(R"("slope": [50, 10])"), "r.json", "/layers/0/rules/slope",
                       "min");
    expectProjectError(layerWithRules(R"("slope": [0, 200])"), "r.json",
                       "/layers/0/rules/slope/1", "[0, 180]");
    expectProjectError(layerWithRules(R"("clearance": -1)"), "r.json",
                       "/layers/0/rules/clearance", ">= 0");
    expectProjectError(layerWithRules(R"("slop": [0, 10])"), "r.json",
                       "/layers/0/rules/slop", "did you mean \"slope\"");
}

}  // namespace
}  // namespace grass::core
