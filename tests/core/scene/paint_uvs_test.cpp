// Painting on any mesh (issue 27 item 3): a surface without UVs gets a generated atlas, so a
// stroke on the tree's canopy leaves the ground under it as it was and one on the ground leaves
// the canopy (with the planar projection the ground's stroke reached the canopy), and a saved
// atlas is what the next open paints in.
#include <gtest/gtest.h>

#include <fstream>

#include "edit/scene_paint.h"
#include "mesh/gltf_loader.h"
#include "mesh/mesh_parts.h"
#include "mesh/uv_atlas_file.h"
#include "scene/scene.h"
#include "support/rules_terrain.h"
#include "support/scratch_folder.h"

namespace grass::core {
namespace {

const std::string PROJECT = R"({"format": "grass-project", "version": 2, "name": "uvs",
  "mesh": {"file": "terrain.glb"},
  "layers": [{"name": "grass", "density": 20, "map_resolution": [256, 256]}]})";


// Which candidates of layer 0 live, and which stand on the ground.
std::vector<char> liveCandidates(const Scene& scene) {
    const LayerSource& source = scene.layers.at(0).source;
    std::vector<char> live(source.candidates.blades.size());
    for (std::size_t i = 0; i < live.size(); ++i)
        live[i] = growCandidate(source, i).live ? 1 : 0;
    return live;
}

bool onGround(const Scene& scene, std::size_t candidate) {
    const MeshParts& table = *meshPartsOf(scene.mesh);
    const std::uint32_t face = scene.layers.at(0).source.candidates.faces[candidate];
    return table.parts[table.faceParts[face]].nodes.front() == "Ground";
}

const glm::vec3 CANOPY_TOP = test::RULES_TREE_BASE + glm::vec3(0.0f, 3.2f + 1.6f, 0.0f);
// On the ground under the canopy's edge, clear of the trunk.
const glm::vec3 UNDER_CANOPY = test::RULES_TREE_BASE + glm::vec3(1.0f, 0.0f, 0.0f);

// Subtracts density in 0.8 m dabs at `at`; returns how many ground candidates and how many
// others changed between living and not.
std::pair<std::size_t, std::size_t> strokeAt(Scene& scene, glm::vec3 at) {
    const std::vector<char> before = liveCandidates(scene);
    ScenePainter painter(scene, GrassLightingDesc{});
    BrushSettings brush;
    brush.mode = BrushMode::Subtract;
    brush.strength = 1.0f;
    brush.radiusM = 0.8f;
    painter.begin(0, LayerMap::Density, {256, 256}, brush);
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(painter.paintTo(at).ok());
    painter.end();
    const std::vector<char> after = liveCandidates(scene);
    std::size_t ground = 0, elsewhere = 0;
    for (std::size_t i = 0; i < after.size(); ++i)
        if (after[i] != before[i])
            ++(onGround(scene, i) ? ground : elsewhere);
    return {ground, elsewhere};
}

TEST(PaintUvs, AMeshWithoutUvsGetsAnAtlasAndAStrokeStaysOnItsSurface) {
    const test::ScratchFolder folder("paint-uvs-atlas");
    const LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    auto scene = buildScene(loaded);
    ASSERT_TRUE(scene) << scene.error().str();
    EXPECT_TRUE(scene->paintUvs.generated);
    EXPECT_TRUE(findUvOverlaps(cornerUvsOf(scene->mesh), scene->mesh).paintable());
    const auto [ground, canopy] = strokeAt(*scene, CANOPY_TOP);
    EXPECT_EQ(ground, 0u) << "the ground under the canopy kept every blade";
    EXPECT_GT(canopy, 5u) << "the stroke removed blades on the canopy";
    const auto [groundBelow, canopyAbove] = strokeAt(*scene, UNDER_CANOPY);
    EXPECT_GT(groundBelow, 5u);
    EXPECT_EQ(canopyAbove, 0u) << "the canopy over the painted ground kept every blade";
}

TEST(PaintUvs, WithThePlanarProjectionTheSameStrokeReachedTheGround) {
    // What the atlas fixes, shown on the loader's planar UVs (the mesh as imported).
    const test::ScratchFolder folder("paint-uvs-planar");
    const LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    auto imported = loadGltf(folder / "terrain.glb");
    ASSERT_TRUE(imported);
    EXPECT_FALSE(findUvOverlaps(cornerUvsOf(imported->mesh), imported->mesh).paintable());
    auto scene = buildSceneFromMesh(loaded, std::move(imported->mesh), {});
    ASSERT_TRUE(scene) << scene.error().str();
    // The shared texels belong to the ground (first in face order, texel_surface.h): a stroke
    // on the ground thins the canopy above it too.
    const auto [ground, canopy] = strokeAt(*scene, UNDER_CANOPY);
    EXPECT_GT(ground, 0u);
    EXPECT_GT(canopy, 0u) << "planar UVs share the ground's texels with the canopy";
}

// A stop requested while a load makes the UVs paintable (the editor's Cancel: the overlap search
// and the atlas take seconds on a large mesh) leaves the mesh's UVs as they are and makes no
// atlas; loadProjectMesh then ends with the build's stop error, naming the project.
TEST(PaintUvs, AStopRequestedMakesNoAtlas) {
    const test::ScratchFolder folder("paint-uvs-stopped");
    const LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    auto imported = loadGltf(folder / "terrain.glb");
    ASSERT_TRUE(imported);
    const CornerUvs planar = cornerUvsOf(imported->mesh);
    std::stop_source source;
    source.request_stop();
    std::vector<std::string> notes;
    const PaintUvs stopped = makeUvsPaintable(
        imported->mesh, imported->hasUv, [] { return false; }, {}, 256, notes, source.get_token());
    EXPECT_FALSE(stopped.generated);
    EXPECT_TRUE(notes.empty());
    EXPECT_EQ(cornerUvsOf(imported->mesh), planar) << "the UVs were changed";
    const PaintUvs made = makeUvsPaintable(
        imported->mesh, imported->hasUv, [] { return false; }, {}, 256, notes);
    EXPECT_TRUE(made.generated) << "without the stop the planar UVs get an atlas";

    auto mesh =
        loadProjectMesh(loaded, nullptr, nullptr, nullptr, nullptr, nullptr, source.get_token());
    ASSERT_FALSE(mesh);
    EXPECT_EQ(mesh.error(), buildStopped(loaded));
    EXPECT_TRUE(loadProjectMesh(loaded, nullptr));
}

TEST(PaintUvs, AKeptAtlasIsWhatTheNextOpenPaintsIn) {
    const test::ScratchFolder folder("paint-uvs-kept");
    LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    auto first = buildScene(loaded);
    ASSERT_TRUE(first) << first.error().str();
    ASSERT_TRUE(first->paintUvs.generated);
    // The atlas as a save keeps it, with its UVs moved a little so a regenerated one would differ.
    CornerUvs kept = first->paintUvs.corners;
    for (auto& face : kept)
        for (glm::vec2& uv : face)
            uv *= 0.5f;
    ASSERT_TRUE(saveUvAtlas(folder / "terrain.uvatlas", kept, first->paintUvs.fingerprint).ok());
    loaded.project.mesh.uvAtlas = "terrain.uvatlas";
    auto second = buildScene(loaded);
    ASSERT_TRUE(second) << second.error().str();
    EXPECT_TRUE(second->paintUvs.fromFile);
    EXPECT_FALSE(second->paintUvs.generated);
    EXPECT_EQ(cornerUvsOf(second->mesh), kept);

    // An atlas made for another mesh: noted, and a new one made.
    std::ofstream(folder / "terrain.uvatlas", std::ios::binary) << "GRASSUV1 not an atlas";
    auto third = buildScene(loaded);
    ASSERT_TRUE(third) << third.error().str();
    EXPECT_TRUE(third->paintUvs.generated);
    bool noted = false;
    for (const std::string& note : third->notes)
        noted = noted || note.find("terrain.uvatlas") != std::string::npos;
    EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace grass::core
