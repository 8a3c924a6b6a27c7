// The "lighting" object of project.json (SPEC §10, issue 5): defaults, round trip, one-line
// errors naming the JSON pointer, and the per-blade bake it drives when a scene is built.
#include <gtest/gtest.h>

#include "project/project.h"
#include "scene/scene.h"
#include "support/plane_project.h"
#include "support/test_paths.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

const std::string SOURCE = "projects/test/project.json";

void expectError(const std::string& members, const std::string& pointer,
                 const std::string& problem) {
    test::expectObjectError("lighting", members, SOURCE, pointer, problem);
}

TEST(ProjectLighting, MissingObjectMeansGrassLightingWithDefaults) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 1})", SOURCE);
    ASSERT_TRUE(parsed.ok()) << parsed.error().str();
    EXPECT_EQ(parsed->lighting, GrassLightingDesc{});
    EXPECT_EQ(parsed->lighting.model, LightingModel::Grass);
}

TEST(ProjectLighting, EveryFieldRoundTrips) {
    Project project;
    GrassLightingDesc& l = project.lighting;
    l.model = LightingModel::Simple;
    l.diffuseLow = {0.1f, 0.2f, 0.3f};
    l.diffuseMid = {0.4f, 0.5f, 0.6f};
    l.diffuseHigh = {1.5f, 1.25f, 1.0f};
    l.terrainNormalWeight = 0.25f;
    l.specular = 2.0f;
    l.specularFadeM = {1.0f, 3.0f};
    l.transmission = 0.1f;
    l.transmissionDistortion = 0.9f;
    l.transmissionPower = 12.0f;
    l.sss = 0.7f;
    l.sssIntensity = 0.2f;
    l.aoRadiusM = 0.3f;
    l.aoStrength = 0.02f;
    l.aoFloor = 0.1f;
    l.normalBlurRadiusM = 2.0f;
    l.water = {0.05f, 0.95f};
    const std::string text = serializeProject(project);
    const auto again = parseProject(text, SOURCE);
    ASSERT_TRUE(again.ok()) << again.error().str();
    EXPECT_EQ(again->lighting, project.lighting);
    EXPECT_EQ(serializeProject(*again), text);
}

TEST(ProjectLighting, TheArticleModelIsAChoice) {
    const auto parsed = parseProject(
        R"({"format": "grass-project", "version": 1, "lighting": {"model": "article"}})", SOURCE);
    ASSERT_TRUE(parsed.ok()) << parsed.error().str();
    EXPECT_EQ(parsed->lighting.model, LightingModel::Article);
    const auto again = parseProject(serializeProject(*parsed), SOURCE);
    ASSERT_TRUE(again.ok()) << again.error().str();
    EXPECT_EQ(again->lighting.model, LightingModel::Article);
}

TEST(ProjectLighting, BadValuesNameTheirPointer) {
    expectError(R"("model": "phong")", "/lighting/model", "\"phong\"");
    expectError(R"("water": [0.7, 0.2])", "/lighting/water", "");
    expectError(R"("ao_floor": 1.5)", "/lighting/ao_floor", "");
    expectError(R"("transmission_power": 0)", "/lighting/transmission_power", "");
    expectError(R"("diffuse_high": [1, 1])", "/lighting/diffuse_high", "");
    expectError(R"("ao_radius": -1)", "/lighting/ao_radius", "");
    expectError(R"("shadows": true)", "/lighting/shadows", "unknown key");
}

// The scene bakes one shading entry per blade slot; a dense field is darker than open ground,
// and AO 0 radius (off) leaves every blade open.
TEST(ProjectLighting, SceneBakesShadingPerBladeSlot) {
    LoadedProject dense = test::planeFieldProject({2.0f, 4, 400.0f, 0.2f, 0.3f},
                                                  test::sourceDir());
    auto scene = buildScene(dense);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const LayerField& field = scene->layers.front();
    ASSERT_EQ(field.shading.size(), field.patched.blades.size());
    double aoSum = 0.0;
    std::size_t live = 0;
    for (std::size_t i = 0; i < field.shading.size(); ++i) {
        if (field.patched.blades[i].h() <= 0.0f)
            continue;
        aoSum += field.shading[i].ao();
        ++live;
        EXPECT_GE(field.shading[i].water(), dense.project.lighting.water.x);
        EXPECT_LE(field.shading[i].water(), dense.project.lighting.water.y);
    }
    ASSERT_GT(live, 0u);
    EXPECT_LT(aoSum / static_cast<double>(live), 0.5) << "400 blades/m² should be well shaded";

    dense.project.lighting.aoRadiusM = 0.0f;
    auto open = buildScene(dense);
    ASSERT_TRUE(open.ok()) << open.error().str();
    for (const BladeShading& shading : open->layers.front().shading)
        EXPECT_EQ(shading.ao(), 1.0f);
}

}  // namespace
}  // namespace grass::core
