// The per-layer environment maps and growth settings of project.json (SPEC §9, §12, issue 6):
// defaults, round trip, one-line errors naming the JSON pointer, and what buildScene makes of
// the maps (resampling, missing and bad files, the growth model through the real loading path).
#include <gtest/gtest.h>

// A map with a NaN texel needs OIIO directly: saveMapImage writes only finite maps.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "maps/map_image.h"
#include "project/project.h"
#include "scene/scene.h"
#include "support/plane_project.h"
#include "support/project_errors.h"

#include "support/scratch_folder.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

const std::string SOURCE = "projects/test/project.json";

// The current version (3 changed the default height-vs-light curve; project_migration_test).
std::string documentWithLayer(const std::string& members) {
    return R"({"format": "grass-project", "version": 3, "layers": [{)" + members + "}]}";
}

std::string documentWithGrowth(const std::string& members) {
    return documentWithLayer(R"("growth": {)" + members + "}");
}

void expectLayerError(const std::string& members, const std::string& pointer,
                      const std::string& problem) {
    test::expectProjectError(documentWithLayer(members), SOURCE, pointer, problem);
}

void expectGrowthError(const std::string& members, const std::string& pointer,
                       const std::string& problem) {
    test::expectProjectError(documentWithGrowth(members), SOURCE, pointer, problem);
}

// A project folder with its maps/ folder, removed afterwards.
struct ProjectFolder : test::ScratchFolder {
    explicit ProjectFolder(const std::string& name) : ScratchFolder("project-growth-" + name) {
        fs::create_directories(path() / "maps");
    }
};

// A 2 m plane at 50 blades/m² (about 200 blades): enough to compare halves, fast to grow.
LoadedProject smallPlane() {
    LoadedProject loaded = test::planeFieldProject({2.0f, 2, 50.0f, 0.3f, 0.5f});
    // The billboards are not under test; keep their placement cheap.
    loaded.project.billboards.placement.density = 1.0f;
    return loaded;
}

// Saves `project` as folder/project.json and loads it back, so the scene resolves its maps
// and names its errors exactly as for a user's project.
LoadedProject savedAndLoaded(const Project& project, const fs::path& folder) {
    const fs::path file = folder / "project.json";
    const Result<void> saved = saveProject(project, file);
    EXPECT_TRUE(saved.ok()) << saved.error().str();
    auto loaded = loadProject(folder);
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    return loaded.ok() ? *loaded : LoadedProject{};
}

// Soil quality rising from 0 at u = 0 (left column) to 1 at u = 1 (right column).
MapImage soilRamp(int width, int height) {
    MapImage map = makeConstantMap(width, height, 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            map.texels[static_cast<std::size_t>(y * width + x)] =
                static_cast<float>(x) / static_cast<float>(width - 1);
    return map;
}

bool containsNote(const std::vector<std::string>& notes, const std::string& text) {
    return std::any_of(notes.begin(), notes.end(), [&](const std::string& note) {
        return note.find(text) != std::string::npos;
    });
}

std::string joined(const std::vector<std::string>& notes) {
    std::string out;
    for (const std::string& note : notes)
        out += note + "\n";
    return out;
}

TEST(ProjectGrowth, AbsentKeysMeanNoMapsAndGrowthOff) {
    for (const std::string& text :
         {std::string(R"({"format": "grass-project", "version": 1})"), documentWithLayer("")}) {
        const auto parsed = parseProject(text, SOURCE);
        ASSERT_TRUE(parsed.ok()) << parsed.error().str();
        ASSERT_EQ(parsed->layers.size(), 1u);
        const GrassLayer& layer = parsed->layers.front();
        EXPECT_EQ(layer.densityMap, "");
        EXPECT_EQ(layer.soilMap, "");
        EXPECT_EQ(layer.lightMap, "");
        EXPECT_EQ(layer.mapResolution, glm::ivec2(512, 512));
        EXPECT_EQ(layer.growth, GrowthDesc{});
        EXPECT_FALSE(layer.growth.enabled);
        EXPECT_EQ(layer.growth.curves, GrowthCurves{});
        EXPECT_EQ(layer.growth.levels, 4);
        EXPECT_EQ(parsed->render.technique, GrassTechnique::Blades);
    }
    // An empty growth object is the defaults too.
    const auto empty = parseProject(documentWithGrowth(""), SOURCE);
    ASSERT_TRUE(empty.ok()) << empty.error().str();
    EXPECT_EQ(empty->layers.front().growth, GrowthDesc{});
}

TEST(ProjectGrowth, EveryFieldRoundTrips) {
    Project project;
    GrassLayer& layer = project.layers.front();
    layer.densityMap = "maps/density.png";
    layer.soilMap = "maps/soil.png";
    layer.lightMap = "maps/light.exr";
    layer.mapResolution = {64, 32};
    GrowthDesc& g = layer.growth;
    g.enabled = true;
    g.curves = GrowthCurves{0.0f, 0.3f, 0.9f,  0.05f, 0.15f, 0.25f, 0.6f,
                            1.0f, 0.2f, 0.35f, 0.45f, 0.7f,  0.95f};
    g.levels = 2;
    g.poorRootColor = {0.2f, 0.1f, 0.0f};
    g.poorTipColor = {0.9f, 0.8f, 0.1f};
    project.render.technique = GrassTechnique::Growth;
    ASSERT_FALSE(layer == GrassLayer{});
    ASSERT_FALSE(g.curves == GrowthCurves{});

    const std::string text = serializeProject(project);
    const auto again = parseProject(text, SOURCE);
    ASSERT_TRUE(again.ok()) << again.error().str() << "\n" << text;
    EXPECT_EQ(*again, project);
    EXPECT_EQ(serializeProject(*again), text);
    for (const char* key :
         {"\"soil_map\": \"maps/soil.png\"", "\"light_map\": \"maps/light.exr\"",
          "\"map_resolution\": [64, 32]", "\"enabled\": true", "\"soil_curve\": [0.0, 0.3, 0.9]",
          "\"width_light_curve\": [0.05, 0.15, 0.25, 0.6, 1.0]",
          "\"height_light_curve\": [0.2, 0.35, 0.45, 0.7, 0.95]", "\"levels\": 2",
          "\"poor_root_color\": [0.2, 0.1, 0.0]", "\"poor_tip_color\": [0.9, 0.8, 0.1]",
          "\"technique\": \"growth\""})
        EXPECT_NE(text.find(key), std::string::npos) << key << " missing from\n" << text;
}

// Saving writes every key, defaults included, in the order docs/project-format.md lists them.
TEST(ProjectGrowth, SaveWritesEveryKeyInDocumentedOrder) {
    const std::string text = serializeProject(Project{});
    const std::vector<std::string> keys{
        "density_map",   "soil_map",        "light_map",         "map_resolution",
        "clump_spacing", "blade",           "tip_color",         "growth",
        "enabled",       "soil_curve",      "width_light_curve", "height_light_curve",
        "levels",        "poor_root_color", "poor_tip_color",    "cameras"};
    std::size_t previous = 0;
    for (const std::string& key : keys) {
        const std::size_t at = text.find('"' + key + '"', previous);
        ASSERT_NE(at, std::string::npos) << key << " missing or out of order in\n" << text;
        previous = at;
    }
    EXPECT_NE(text.find("\"map_resolution\": [512, 512]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"soil_curve\": [0.1, 0.6, 1.0]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"levels\": 4"), std::string::npos) << text;
}

TEST(ProjectGrowth, BadCurveValuesNameTheirPointer) {
    expectGrowthError(R"("soil_curve": [0.1, 1.5, 1])", "/layers/0/growth/soil_curve/1",
                      "in [0, 1] (got 1.5)");
    expectGrowthError(R"("width_light_curve": [-0.1, 0.3, 0.5, 0.8, 0.9])",
                      "/layers/0/growth/width_light_curve/0", "in [0, 1] (got -0.1)");
    expectGrowthError(R"("height_light_curve": [0.1, 0.2, "high", 0.7, 0.8])",
                      "/layers/0/growth/height_light_curve/2", "must be a finite number");
    expectGrowthError(R"("width_light_curve": [0.2, 0.35, 0.5, 0.85])",
                      "/layers/0/growth/width_light_curve",
                      "array of 5 numbers [wy0, wy1, wy2, wy3, wy4]");
    expectGrowthError(R"("soil_curve": 0.5)", "/layers/0/growth/soil_curve",
                      "array of 3 numbers [gy0, gy1, gy2]");
}

TEST(ProjectGrowth, BadGrowthSettingsNameTheirPointer) {
    expectGrowthError(R"("levels": 0)", "/layers/0/growth/levels", "1..4");
    expectGrowthError(R"("levels": 5)", "/layers/0/growth/levels", "1..4");
    expectGrowthError(R"("enabled": "yes")", "/layers/0/growth/enabled",
                      "must be true or false (got string \"yes\")");
    expectGrowthError(R"("poor_root_color": [0.3, 1.2, 0])", "/layers/0/growth/poor_root_color/1",
                      "in [0, 1]");
    expectGrowthError(R"("poor_tip_color": [-0.5, 0.5, 0.5])", "/layers/0/growth/poor_tip_color/0",
                      "in [0, 1]");
    expectLayerError(R"("growth": true)", "/layers/0/growth", "must be an object");
    // A key far from any valid one: the hint lists them all.
    expectGrowthError(R"("shadows": 1)", "/layers/0/growth/shadows",
                      "unknown key (expected one of \"enabled\", \"soil_curve\", "
                      "\"width_light_curve\", \"height_light_curve\", \"levels\", "
                      "\"stem_tip_width\", \"poor_root_color\", \"poor_tip_color\")");
    // A typo: the hint names the key meant.
    expectGrowthError(R"("level": 2)", "/layers/0/growth/level", "did you mean \"levels\"");
}

TEST(ProjectGrowth, BadMapSettingsNameTheirPointer) {
    expectLayerError(R"("map_resolution": [0, 10])", "/layers/0/map_resolution/0", "1..8192");
    expectLayerError(R"("map_resolution": [10, 9000])", "/layers/0/map_resolution/1", "1..8192");
    expectLayerError(R"("map_resolution": [9000, 10])", "/layers/0/map_resolution/0", "1..8192");
    expectLayerError(R"("map_resolution": [10])", "/layers/0/map_resolution",
                     "array of 2 integers [width, height]");
    expectLayerError(R"("map_resolution": [10.5, 10])", "/layers/0/map_resolution/0", "integer");
    expectLayerError(R"("soil_map": "maps/../../soil.png")", "/layers/0/soil_map",
                     "leaves the project folder");
    expectLayerError(R"("soil_map": "/tmp/soil.png")", "/layers/0/soil_map", "relative");
    expectLayerError(R"("light_map": "../light.png")", "/layers/0/light_map",
                     "leaves the project folder");
    expectLayerError(R"("light_map": 3)", "/layers/0/light_map", "must be a string");
    // The map keys are layer keys, not growth keys.
    expectGrowthError(R"("soil_map": "s.png")", "/layers/0/growth/soil_map", "unknown key");
}

TEST(ProjectGrowth, GrowthTechniqueParses) {
    const auto parsed = parseProject(
        R"({"format": "grass-project", "version": 1, "render": {"technique": "growth"}})", SOURCE);
    ASSERT_TRUE(parsed.ok()) << parsed.error().str();
    EXPECT_EQ(parsed->render.technique, GrassTechnique::Growth);
    EXPECT_EQ(grassTechniqueName(GrassTechnique::Growth), "growth");
    test::expectProjectError(
        R"({"format": "grass-project", "version": 1, "render": {"technique": "grow"}})", SOURCE,
        "/render/technique", "\"growth\"");
}

TEST(ProjectGrowth, SceneResamplesAMapOfAnotherSizeWithANote) {
    const ProjectFolder dir("resample");
    ASSERT_TRUE(saveMapImage(soilRamp(20, 12), dir.path() / "maps" / "soil.png").ok());
    LoadedProject plane = smallPlane();
    GrassLayer& layer = plane.project.layers.front();
    layer.soilMap = "maps/soil.png";
    layer.mapResolution = {32, 16};
    layer.growth.enabled = true;
    const LoadedProject loaded = savedAndLoaded(plane.project, dir.path());
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const MapImage& soil = scene->layers.front().source.maps.soil;
    EXPECT_EQ(soil.width, 32);
    EXPECT_EQ(soil.height, 16);
    EXPECT_EQ(soil.texels.size(), 32u * 16u);
    EXPECT_TRUE(containsNote(scene->notes, "resampled from 20×12 to 32×16"))
        << joined(scene->notes);
    EXPECT_TRUE(containsNote(scene->notes, "soil.png")) << joined(scene->notes);

    // A map already at map_resolution is used as is, without a note.
    ASSERT_TRUE(saveMapImage(soilRamp(32, 16), dir.path() / "maps" / "soil.png").ok());
    auto exact = buildScene(loaded);
    ASSERT_TRUE(exact.ok()) << exact.error().str();
    EXPECT_FALSE(containsNote(exact->notes, "resampled")) << joined(exact->notes);
}

TEST(ProjectGrowth, SceneNamesAMissingMapAndItsPointer) {
    const ProjectFolder dir("missing");
    LoadedProject plane = smallPlane();
    plane.project.layers.front().soilMap = "maps/nowhere.png";
    plane.project.layers.front().growth.enabled = true;
    const LoadedProject loaded = savedAndLoaded(plane.project, dir.path());
    const auto scene = buildScene(loaded);
    ASSERT_FALSE(scene.ok());
    const std::string error = scene.error().str();
    EXPECT_NE(error.find("project.json"), std::string::npos) << error;
    EXPECT_NE(error.find("/layers/0/soil_map"), std::string::npos) << error;
    EXPECT_NE(error.find("nowhere.png"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "not one line: " << error;
}

TEST(ProjectGrowth, SceneNotesMapsThatNeedGrowthEnabled) {
    const ProjectFolder dir("disabled");
    ASSERT_TRUE(saveMapImage(soilRamp(16, 16), dir.path() / "maps" / "soil.png").ok());
    LoadedProject plane = smallPlane();
    GrassLayer& layer = plane.project.layers.front();
    layer.soilMap = "maps/soil.png";
    layer.mapResolution = {16, 16};
    const LoadedProject loaded = savedAndLoaded(plane.project, dir.path());
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    EXPECT_TRUE(containsNote(scene->notes, "take effect only with growth.enabled = true"))
        << joined(scene->notes);
    // Growth off: every candidate grows as scattered, whatever the soil says.
    const LayerField& field = scene->layers.front();
    for (std::size_t slot = 0; slot < field.patched.blades.size(); ++slot) {
        const std::uint32_t candidate = field.patched.sourceIndex[slot];
        if (candidate == UINT32_MAX)
            continue;
        EXPECT_EQ(field.patched.blades[slot].h(), field.source.candidates.blades[candidate].h());
        EXPECT_EQ(field.wilt[slot], 0.0f);
    }

    // With growth on, the note goes away.
    plane.project.layers.front().growth.enabled = true;
    auto enabled = buildScene(savedAndLoaded(plane.project, dir.path()));
    ASSERT_TRUE(enabled.ok()) << enabled.error().str();
    EXPECT_FALSE(containsNote(enabled->notes, "growth.enabled")) << joined(enabled->notes);
}

// The growth model through the real loading path: a soil map poor on the left (u = 0) and good
// on the right (u = 1) grows taller, healthier blades on the right.
TEST(ProjectGrowth, SoilRampGrowsTallerBladesOnTheGoodSide) {
    const ProjectFolder dir("ramp");
    ASSERT_TRUE(saveMapImage(soilRamp(32, 32), dir.path() / "maps" / "soil.png").ok());
    LoadedProject plane = smallPlane();
    GrassLayer& layer = plane.project.layers.front();
    layer.soilMap = "maps/soil.png";
    layer.mapResolution = {32, 32};
    layer.growth.enabled = true;
    auto scene = buildScene(savedAndLoaded(plane.project, dir.path()));
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const LayerField& field = scene->layers.front();
    double heightSum[2] = {0.0, 0.0};
    double wiltSum[2] = {0.0, 0.0};
    int count[2] = {0, 0};
    for (std::size_t slot = 0; slot < field.patched.blades.size(); ++slot) {
        const std::uint32_t candidate = field.patched.sourceIndex[slot];
        if (candidate == UINT32_MAX || !(field.patched.blades[slot].h() > 0.0f))
            continue;
        const float u = field.source.candidates.uvs[candidate].x;
        // Leave the middle out: there both halves grow alike.
        if (u > 0.3f && u < 0.7f)
            continue;
        const int side = u >= 0.7f ? 1 : 0;
        heightSum[side] += static_cast<double>(field.patched.blades[slot].h());
        wiltSum[side] += static_cast<double>(field.wilt[slot]);
        ++count[side];
    }
    ASSERT_GT(count[0], 10);
    ASSERT_GT(count[1], 10);
    const double poorHeight = heightSum[0] / count[0];
    const double goodHeight = heightSum[1] / count[1];
    // Default curves, full light: β runs from (0.1 + 0.8)/2 = 0.45 at g = 0 to 0.9 at g = 1; over
    // the outer thirds it averages about 0.52 and 0.84, a ratio of 1.6 (1.4 leaves room for the
    // random blade heights of ~60 blades a side).
    EXPECT_GT(goodHeight, 1.4 * poorHeight) << "poor " << poorHeight << ", good " << goodHeight;
    EXPECT_LT(wiltSum[1] / count[1], wiltSum[0] / count[0]);
}

TEST(ProjectGrowth, SceneRefusesALightMapWithNan) {
    const ProjectFolder dir("nan");
    const fs::path file = dir.path() / "maps" / "light.exr";
    {
        std::vector<float> texels(16 * 16, 0.5f);
        texels[3 * 16 + 5] = std::nanf("");
        auto out = OIIO::ImageOutput::create(file.string());
        ASSERT_TRUE(out) << file;
        const OIIO::ImageSpec spec(16, 16, 1, OIIO::TypeDesc::FLOAT);
        ASSERT_TRUE(out->open(file.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, texels.data()));
        ASSERT_TRUE(out->close());
    }
    LoadedProject plane = smallPlane();
    GrassLayer& layer = plane.project.layers.front();
    layer.lightMap = "maps/light.exr";
    layer.mapResolution = {16, 16};
    layer.growth.enabled = true;
    const auto scene = buildScene(savedAndLoaded(plane.project, dir.path()));
    ASSERT_FALSE(scene.ok());
    const std::string error = scene.error().str();
    EXPECT_NE(error.find("light.exr"), std::string::npos) << error;
    EXPECT_NE(error.find("/layers/0/light_map"), std::string::npos) << error;
    EXPECT_NE(error.find("NaN"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "not one line: " << error;
}

}  // namespace
}  // namespace grass::core
