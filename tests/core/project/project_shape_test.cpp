// Per-layer blade shapes in project.json (SPEC §7, issue 5): the "shape" and "tip_start" keys
// of a layer, their defaults, round trip and one-line errors.
#include <gtest/gtest.h>

#include "blade/blade_shape.h"
#include "project/project.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

const std::string SOURCE = "projects/test/project.json";

std::string documentWithLayer(const std::string& layerMembers) {
    return R"({"format": "grass-project", "version": 1, "layers": [{)" + layerMembers + "}]}";
}

void expectError(const std::string& text, const std::string& pointer, const std::string& problem) {
    test::expectProjectError(text, SOURCE, pointer, problem);
}

TEST(BladeShape, NamesParseBackToTheirShape) {
    for (std::size_t i = 0; i < BLADE_SHAPE_COUNT; ++i) {
        const auto shape = static_cast<BladeShape>(i);
        const auto parsed = parseBladeShape(bladeShapeName(shape));
        ASSERT_TRUE(parsed.ok()) << bladeShapeName(shape);
        EXPECT_EQ(*parsed, shape);
    }
    EXPECT_EQ(bladeShapeName(BladeShape::TriangleTip), "triangle-tip");
    EXPECT_EQ(bladeShapeName(BladeShape::Dandelion), "dandelion");
}

TEST(BladeShape, UnknownNameListsTheValidOnes) {
    const auto parsed = parseBladeShape("leaf");
    ASSERT_FALSE(parsed.ok());
    EXPECT_NE(parsed.error().message.find("\"leaf\""), std::string::npos);
    EXPECT_NE(parsed.error().message.find("\"dandelion\""), std::string::npos);
}

TEST(ProjectShape, LayerWithoutShapeKeysDrawsTrianglesWithHalfTip) {
    const auto parsed = parseProject(documentWithLayer(R"("name": "old")"), SOURCE);
    ASSERT_TRUE(parsed.ok()) << parsed.error().str();
    EXPECT_EQ(parsed->layers.front().shape, BladeShape::Triangle);
    EXPECT_EQ(parsed->layers.front().tipStart, 0.5f);
}

TEST(ProjectShape, EveryShapeAndTipStartRoundTrip) {
    for (std::size_t i = 0; i < BLADE_SHAPE_COUNT; ++i) {
        Project project;
        project.layers.front().shape = static_cast<BladeShape>(i);
        project.layers.front().tipStart = 0.125f * static_cast<float>(i);
        const std::string text = serializeProject(project);
        const auto again = parseProject(text, SOURCE);
        ASSERT_TRUE(again.ok()) << again.error().str();
        EXPECT_EQ(*again, project) << text;
        EXPECT_NE(text.find("\"shape\": \"" + std::string(bladeShapeName(project.layers[0].shape)) +
                            "\""),
                  std::string::npos)
            << text;
    }
}

TEST(ProjectShape, ShapeKeysSitBetweenBladeAndRootColor) {
    const std::string text = serializeProject(Project{});
    const std::size_t blade = text.find("\"blade\"");
    const std::size_t shape = text.find("\"shape\"");
    const std::size_t tipStart = text.find("\"tip_start\"");
    const std::size_t rootColor = text.find("\"root_color\"");
    ASSERT_NE(shape, std::string::npos) << text;
    ASSERT_NE(tipStart, std::string::npos) << text;
    EXPECT_LT(blade, shape);
    EXPECT_LT(shape, tipStart);
    EXPECT_LT(tipStart, rootColor);
}

TEST(ProjectShape, UnknownShapeIsRejectedWithASuggestion) {
    expectError(documentWithLayer(R"("shape": "dandelon")"), "/layers/0/shape",
                "did you mean \"dandelion\"?");
    expectError(documentWithLayer(R"("shape": "leaf")"), "/layers/0/shape", "\"triangle-tip\"");
    expectError(documentWithLayer(R"("shape": 3)"), "/layers/0/shape", "must be one of");
}

TEST(ProjectShape, TipStartOutsideZeroToOneIsRejected) {
    // τ = 1 would divide by zero in the triangle-tip shape.
    expectError(documentWithLayer(R"("tip_start": 1.0)"), "/layers/0/tip_start",
                "must be a finite number");
    expectError(documentWithLayer(R"("tip_start": -0.1)"), "/layers/0/tip_start",
                "must be a finite number");
    expectError(documentWithLayer(R"("tip_start": "half")"), "/layers/0/tip_start",
                "must be a finite number");
    const auto zero = parseProject(documentWithLayer(R"("tip_start": 0)"), SOURCE);
    ASSERT_TRUE(zero.ok()) << zero.error().str();
    EXPECT_EQ(zero->layers.front().tipStart, 0.0f);
}

}  // namespace
}  // namespace grass::core
