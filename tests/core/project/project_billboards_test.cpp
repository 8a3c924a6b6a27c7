// The "billboards" object and render "technique" of project.json (SPEC §8, issue 5): defaults,
// round trip, one-line errors, and a texture file that is not a grass texture.
#include <gtest/gtest.h>

#include "project/project.h"
#include "scene/scene.h"
#include "support/plane_project.h"
#include "support/project_errors.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

const std::string SOURCE = "projects/test/project.json";

void expectError(const std::string& members, const std::string& pointer,
                 const std::string& problem) {
    test::expectProjectError(R"({"format": "grass-project", "version": 1, )" + members + "}",
                             SOURCE, pointer, problem);
}

TEST(ProjectBillboards, DefaultsAreBladesWithPerObjectBillboards) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 1})", SOURCE);
    ASSERT_TRUE(parsed.ok()) << parsed.error().str();
    EXPECT_EQ(parsed->render.technique, GrassTechnique::Blades);
    EXPECT_EQ(parsed->billboards, BillboardDesc{});
    EXPECT_EQ(parsed->billboards.animation, BillboardWindMode::PerObject);
}

TEST(ProjectBillboards, EveryFieldRoundTrips) {
    Project project;
    project.render.technique = GrassTechnique::Hybrid;
    BillboardDesc& b = project.billboards;
    b.placement = {12.5f, {0.2f, 0.7f}, 0.9f, 3.0f};
    b.texture = "tufts.png";
    b.animation = BillboardWindMode::PerCluster;
    b.wind = {{0.6f, -0.8f}, 0.125f, 1.5f};
    b.crossFadeM = {5.0f, 9.0f};
    const std::string text = serializeProject(project);
    const auto again = parseProject(text, SOURCE);
    ASSERT_TRUE(again.ok()) << again.error().str();
    EXPECT_EQ(again->billboards, project.billboards);
    EXPECT_EQ(again->render.technique, GrassTechnique::Hybrid);
    EXPECT_EQ(serializeProject(*again), text);
}

TEST(ProjectBillboards, BadValuesNameTheirPointer) {
    expectError(R"("render": {"technique": "sprites"})", "/render/technique", "\"sprites\"");
    expectError(R"("billboards": {"animation": "per-blade"})", "/billboards/animation",
                "\"per-blade\"");
    expectError(R"("billboards": {"density": -1})", "/billboards/density", "");
    expectError(R"("billboards": {"cross_fade": [9, 3]})", "/billboards/cross_fade", "");
    expectError(R"("billboards": {"wind_direction": [0, 1, 0]})", "/billboards/wind_direction",
                "horizontal");
    expectError(R"("billboards": {"texture": "../outside.png"})", "/billboards/texture", "");
}

TEST(ProjectBillboards, NamesParseBack) {
    for (auto technique :
         {GrassTechnique::Blades, GrassTechnique::Billboards, GrassTechnique::Hybrid})
        EXPECT_EQ(*parseGrassTechnique(grassTechniqueName(technique)), technique);
    for (auto mode : {BillboardWindMode::PerCluster, BillboardWindMode::PerVertex,
                      BillboardWindMode::PerObject})
        EXPECT_EQ(*parseBillboardAnimation(billboardAnimationName(mode)), mode);
    const auto bad = parseGrassTechnique("sprites");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("\"hybrid\""), std::string::npos);
}

TEST(ProjectBillboards, SceneGrowsObjectsAndGeneratesATexture) {
    LoadedProject loaded = test::planeFieldProject({2.0f, 2, 10.0f}, test::sourceDir());
    loaded.project.billboards.placement.density = 20.0f;
    loaded.project.render.technique = GrassTechnique::Billboards;
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    EXPECT_FALSE(scene->billboards.unplaced.has_value());
    EXPECT_NEAR(static_cast<double>(scene->billboards.objects.size()), 80.0, 1.0);
    EXPECT_GT(scene->billboards.texture.width, 0);
}

// A scene its technique draws by blades alone places no billboards (a pass over the mesh and
// ~100 bytes each, for nothing drawn); they are placed, the same ones, once something draws them.
TEST(ProjectBillboards, ABladesSceneKeepsItsBillboardsUnplacedUntilTheyAreDrawn) {
    LoadedProject loaded = test::planeFieldProject({2.0f, 2, 10.0f}, test::sourceDir());
    loaded.project.billboards.placement.density = 20.0f;
    ASSERT_EQ(loaded.project.render.technique, GrassTechnique::Blades);
    auto blades = buildScene(loaded);
    ASSERT_TRUE(blades.ok()) << blades.error().str();
    EXPECT_TRUE(blades->billboards.placed.empty());
    EXPECT_TRUE(blades->billboards.objects.empty());
    ASSERT_TRUE(blades->billboards.unplaced.has_value());
    EXPECT_GT(blades->billboards.texture.width, 0) << "the texture is read at once: its errors too";

    loaded.project.render.technique = GrassTechnique::Hybrid;
    auto hybrid = buildScene(loaded);
    ASSERT_TRUE(hybrid.ok()) << hybrid.error().str();
    const auto placed = placedBillboards(*blades);
    ASSERT_TRUE(placed.ok()) << placed.error().str();
    ASSERT_EQ(placed->placed.size(), hybrid->billboards.placed.size());
    ASSERT_GT(placed->placed.size(), 60u);
    for (std::size_t i = 0; i < placed->placed.size(); ++i) {
        EXPECT_EQ(placed->placed[i].centre, hybrid->billboards.placed[i].centre) << i;
        EXPECT_EQ(placed->placed[i].cluster, hybrid->billboards.placed[i].cluster) << i;
    }
    ASSERT_EQ(placed->objects.size(), hybrid->billboards.objects.size());
    EXPECT_EQ(placed->follow.stiffness, hybrid->billboards.follow.stiffness);
    ASSERT_TRUE(placeBillboards(*blades).ok());
    EXPECT_FALSE(blades->billboards.unplaced.has_value());
    EXPECT_EQ(blades->billboards.objects.size(), hybrid->billboards.objects.size());
}

TEST(ProjectBillboards, MissingTextureFileIsNamed) {
    LoadedProject loaded = test::planeFieldProject({1.0f, 2, 10.0f}, test::sourceDir());
    loaded.file = "projects/x/project.json";
    loaded.project.billboards.texture = "no-such-tufts.png";
    auto scene = buildScene(loaded);
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().str().find("no-such-tufts.png"), std::string::npos)
        << scene.error().str();
}

}  // namespace
}  // namespace grass::core
