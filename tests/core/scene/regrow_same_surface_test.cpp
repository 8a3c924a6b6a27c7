// Re-growing on the surface at hand (core::regrowOnSameSurface): the editor's re-grow after an
// edit of the layers grows what reading the mesh again would, without reading it; a change of
// the surface itself (file, unit, up axis, folder, the coarsest map a generated atlas is made
// for) reads it again.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "support/rules_terrain.h"
#include "support/scratch_folder.h"

namespace grass::core {
namespace {

// A terrain without UVs, so its paintable UVs are a generated atlas the re-grow must carry.
const std::string PROJECT = R"({"format": "grass-project", "version": 3, "name": "regrow",
  "mesh": {"file": "terrain.glb"},
  "layers": [{"name": "grass", "density": 20, "map_resolution": [256, 256]}]})";


TEST(RegrowOnSameSurface, GrowsWhatTheFileWouldWithoutReadingIt) {
    const test::ScratchFolder folder("regrow-same-surface");
    const LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    auto first = buildScene(loaded);
    ASSERT_TRUE(first) << first.error().str();
    ASSERT_TRUE(first->paintUvs.generated) << "the terrain has no UVs of its own";

    LoadedProject next = loaded;
    next.project.layers.at(0).scatter.density = 35.0f;
    next.project.seed = 7;
    ASSERT_TRUE(sameSurface(loaded, next));
    auto expected = buildScene(next);
    ASSERT_TRUE(expected) << expected.error().str();

    std::filesystem::remove(folder / "terrain.glb");
    ASSERT_FALSE(buildScene(next)) << "the file is gone: only the mesh at hand can grow the field";
    auto regrown = regrowOnSameSurface(next, *first);
    ASSERT_TRUE(regrown) << regrown.error().str();

    EXPECT_EQ(regrown->mesh->n_faces(), expected->mesh->n_faces());
    EXPECT_EQ(regrown->mesh->n_vertices(), expected->mesh->n_vertices());
    EXPECT_EQ(regrown->bounds, expected->bounds);
    EXPECT_EQ(regrown->area, expected->area);
    EXPECT_EQ(regrown->groundOrigin, expected->groundOrigin);
    EXPECT_TRUE(regrown->paintUvs.generated);
    EXPECT_EQ(regrown->paintUvs.fingerprint, expected->paintUvs.fingerprint);
    EXPECT_EQ(regrown->paintUvs.corners.size(), expected->paintUvs.corners.size());
    ASSERT_GT(expected->totalBlades(), first->totalBlades()) << "the edit grew more blades";
    EXPECT_EQ(regrown->totalBlades(), expected->totalBlades());
    const auto& blades = regrown->layers.at(0).patched.blades;
    const auto& bladesExpected = expected->layers.at(0).patched.blades;
    ASSERT_EQ(blades.size(), bladesExpected.size());
    for (std::size_t i = 0; i < blades.size(); ++i) {
        ASSERT_EQ(blades[i].v0Theta, bladesExpected[i].v0Theta) << "blade " << i;
        ASSERT_EQ(blades[i].v2W, bladesExpected[i].v2W) << "blade " << i;
    }
    EXPECT_EQ(regrown->billboards.placed.size(), expected->billboards.placed.size());
    // The first scene shares its mesh (a copy cost 0.3 s on an 8-million-triangle ground), which
    // outlives it; a copy of a scene is still a copy.
    EXPECT_EQ(&*first->mesh, &*regrown->mesh);
    EXPECT_TRUE(regrown->mesh.sameMeshAs(first->mesh));
    const MovableSurfaceMesh copied = first->mesh;
    EXPECT_NE(&*copied, &*first->mesh);
    EXPECT_EQ(copied->n_faces(), first->mesh->n_faces());
    const std::size_t faces = first->mesh->n_faces();
    { const Scene dropped = std::move(*first); }
    EXPECT_EQ(regrown->mesh->n_faces(), faces);
    EXPECT_GT(surfaceArea(regrown->mesh), 0.0);
}

// A stop requested (the editor's: a later edit makes the re-grow useless, or the user cancels a
// load) ends the growing with an error naming the project, whichever way the field grows; the
// billboards' placing too. Without one, the same calls grow the field.
TEST(RegrowOnSameSurface, AStopRequestedEndsTheGrowing) {
    const test::ScratchFolder folder("regrow-stopped");
    const LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    std::stop_source source;
    auto first = buildScene(loaded, nullptr, source.get_token());
    ASSERT_TRUE(first) << first.error().str();
    ASSERT_GT(first->totalBlades(), 0u);
    source.request_stop();
    const auto stopped = [&](const auto& result) {
        return !result && result.error() == buildStopped(loaded) &&
               result.error().path == loaded.file.string();
    };
    EXPECT_TRUE(stopped(buildScene(loaded, nullptr, source.get_token())));
    EXPECT_TRUE(stopped(regrowOnSameSurface(loaded, *first, source.get_token())));
    EXPECT_TRUE(
        stopped(buildSceneFromMesh(loaded, first->mesh.shared(), {}, {}, source.get_token())));
    EXPECT_TRUE(regrowOnSameSurface(loaded, *first));
    ASSERT_TRUE(first->billboards.unplaced) << "the project draws blades: billboards wait";
    const auto placed = placedBillboardsUnfollowed(*first, source.get_token());
    ASSERT_FALSE(placed);
    EXPECT_NE(placed.error().message.find("stopped"), std::string::npos) << placed.error().str();
    EXPECT_TRUE(placedBillboardsUnfollowed(*first));
}

// A build says what it is doing as it goes (the editor's loading box shows it): the mesh's
// read and the check of its UVs, then each layer, then the billboards when the technique draws
// them; a re-grow on the same surface only grows.
TEST(RegrowOnSameSurface, ABuildSaysEachStageInOrder) {
    const test::ScratchFolder folder("build-progress");
    LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    loaded.project.layers.push_back(loaded.project.layers.at(0));
    loaded.project.layers.back().name = "moss";
    loaded.project.render.technique = GrassTechnique::Hybrid;
    std::vector<std::string> stages;
    const BuildProgress record = [&](const std::string& stage) { stages.push_back(stage); };
    auto first = buildScene(loaded, nullptr, {}, record);
    ASSERT_TRUE(first) << first.error().str();
    EXPECT_EQ(stages, (std::vector<std::string>{
                          "reading terrain.glb", "checking the UVs of terrain.glb",
                          "growing layer \"grass\" (1 of 2)", "growing layer \"moss\" (2 of 2)",
                          "placing the billboards"}));
    stages.clear();
    loaded.project.render.technique = GrassTechnique::Blades;
    ASSERT_TRUE(regrowOnSameSurface(loaded, *first, {}, record));
    EXPECT_EQ(stages, (std::vector<std::string>{"growing layer \"grass\" (1 of 2)",
                                                "growing layer \"moss\" (2 of 2)"}));
}

TEST(RegrowOnSameSurface, AnotherSurfaceIsReadAgain) {
    const test::ScratchFolder folder("regrow-other-surface");
    const LoadedProject loaded = test::writeRulesTerrainProject(folder.path(), PROJECT);
    const auto differs = [&](auto change) {
        LoadedProject next = loaded;
        change(next);
        return !sameSurface(loaded, next);
    };
    EXPECT_TRUE(differs([](LoadedProject& p) { p.project.mesh.file = "other.glb"; }));
    EXPECT_TRUE(differs([](LoadedProject& p) { p.project.mesh.metresPerUnit = 0.01f; }));
    EXPECT_TRUE(differs([](LoadedProject& p) { p.project.mesh.up = UpAxis::Z; }));
    EXPECT_TRUE(differs([](LoadedProject& p) { p.project.mesh.uvAtlas = "terrain.uvatlas"; }));
    EXPECT_TRUE(differs([](LoadedProject& p) { p.folder = p.folder / "elsewhere"; }));
    EXPECT_TRUE(differs([](LoadedProject& p) {
        p.project.layers.at(0).mapResolution = {128, 256};  // the atlas keeps gutters for 128
    }));
    EXPECT_FALSE(differs([](LoadedProject& p) {
        p.project.layers.at(0).mapResolution = {512, 512};  // the coarsest is still 256
        p.project.layers.push_back(p.project.layers.at(0));
        p.project.layers.back().mapResolution = {256, 1024};
    }));
    EXPECT_FALSE(differs([](LoadedProject& p) { p.project.layers.at(0).scatter.density = 1.0f; }));
}

}  // namespace
}  // namespace grass::core
