// A collider dragged with the gizmo in the real editor (app/editor.cpp, followMotionEdits): its
// prop follows the drag frame by frame, and its release grows nothing again. Before, the prop
// stood where it was until the mouse was released, and then the whole field grew again ("grew
// the field again" in the log) and its blades restarted from rest. So for the undo of an edit the
// field is not grown from.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "editor_runs.h"
#include "project/project.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

// Where the ball's upper half stands before any drag (25 px left of its marker, 24 px above):
// the red and blue of that pixel of a 900-pixel-wide screenshot, {-1, -1} when unreadable.
// Blue well above red: the sky shows there; about equal: the grey ball.
std::pair<int, int> ballTopRedBlue(const std::filesystem::path& shot) {
    auto image = readRgba8Image(shot);
    EXPECT_TRUE(image.ok()) << image.error().str();
    if (!image.ok() || image->width != 900 || image->height < 166)
        return {-1, -1};
    const std::uint8_t* pixel = &image->pixels[(std::size_t(165) * 900 + 590) * 4];
    return {int(pixel[0]), int(pixel[2])};
}

// The editor run on the ball project in `dir` with `script` (which ends saving it), replayed
// frame by frame: the colliders it saved. The run must grow the field nowhere again.
std::vector<core::ColliderDesc> collidersAfter(const std::filesystem::path& dir,
                                               const std::string& script) {
    writeBallProject(dir);
    const std::string log = runEditor(dir, script, "", /*wallClock=*/false);
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    return savedColliders(dir);
}

// The gizmo (g), and a click on the ball's marker selects it.
constexpr const char* SELECT_BALL = "wait 2\nkey g\nwait 2\nclick 615 189\nwait 2\n";

TEST(EditorMotion, ADraggedBallMovesAsItIsDraggedAndGrowsNothingAgain) {
    const auto dir = scratchDir("editor_motion");
    // The gizmo, the ball selected, its up arrow dragged 50 px down and held there for a
    // screenshot, released, saved.
    const std::vector<core::ColliderDesc> colliders =
        collidersAfter(dir, std::string(SELECT_BALL) +
                                "move 615 150\npress\nmove 615 170\nmove 615 190\n"
                                "move 615 200\nwait 3\nscreenshot held.png\nrelease\n"
                                "wait 3\nkey ctrl+s\nwait 2\n");
    ASSERT_EQ(colliders.size(), 1u);
    EXPECT_LT(colliders[0].position.y, 0.7f) << "the drag did not move the ball";
    // Held mid-drag: where the ball's upper half was, the sky shows, since the ball went down
    // with the pointer.
    const auto [red, blue] = ballTopRedBlue(dir / "held.png");
    EXPECT_GT(blue, red + 40) << "the ball's prop stayed where it was during the drag";
}

// Ctrl+Z after a drag puts the ball back where it stood, without growing the field either.
TEST(EditorMotion, AnUndoneDragPutsTheBallBackWithoutGrowingTheField) {
    const auto dir = scratchDir("editor_motion_undo");
    const std::vector<core::ColliderDesc> colliders =
        collidersAfter(dir, std::string(SELECT_BALL) +
                                "drag 615 150 615 200 6\nwait 3\nkey ctrl+z\nwait 3\n"
                                "screenshot undone.png\nkey ctrl+s\nwait 2\n");
    ASSERT_EQ(colliders.size(), 1u);
    EXPECT_EQ(colliders[0].position, glm::vec3(0.0f, 0.8f, 0.0f));
    // The ball's upper half is drawn where it was before the drag.
    const auto [red, blue] = ballTopRedBlue(dir / "undone.png");
    ASSERT_GE(red, 0);
    EXPECT_LT(blue, red + 40) << "the undone ball's prop did not come back";
}

// The gizmo's "add ball", then the new ball's "delete", grow nothing again either.
TEST(EditorMotion, ABallAddedAndDeletedGrowsNothingAgain) {
    const auto dir = scratchDir("editor_motion_add");
    writeBallProject(dir);
    // The gizmo's buttons at 900 × 560: "add ball" (142, 177); once a ball is selected the row
    // under it holds "delete" (236, 223).
    const std::string added = runEditor(dir,
                                        "wait 2\nkey g\nwait 2\nclick 142 177\nwait 3\n"
                                        "key ctrl+s\nwait 2\n",
                                        "", /*wallClock=*/false);
    EXPECT_EQ(added.find("grew the field again"), std::string::npos) << added;
    EXPECT_EQ(savedColliders(dir).size(), 2u) << added;
    const std::string deleted = runEditor(dir,
                                          "wait 2\nkey g\nwait 2\nclick 142 177\nwait 3\n"
                                          "click 236 223\nwait 3\nkey ctrl+s\nwait 2\n",
                                          "", /*wallClock=*/false);
    EXPECT_EQ(deleted.find("grew the field again"), std::string::npos) << deleted;
    EXPECT_EQ(savedColliders(dir).size(), 2u) << "added one, deleted it:\n" << deleted;
}

// Colliders › add mesh… in the real editor: the mesh is packed on a worker and followed like
// any collider, and the field grows nothing again (before, adding a mesh collider grew the whole
// field again, and its blades restarted from rest).
TEST(EditorMotion, AMeshColliderAddedIsPackedWithoutGrowingTheField) {
    const auto dir = scratchDir("editor_motion_add_mesh");
    writeBallProject(dir);
    // Layers collapsed (60, 131), Colliders opened (66, 208): under the ball's rows "add mesh…"
    // (148, 313) opens the file browser, whose path field takes the typed path.
    const std::string log =
        runEditor(dir,
                  "wait 2\nclick 60 131\nwait 2\nclick 66 208\nwait 2\nclick 148 313\nwait 2\n"
                  "type " +
                      (sourceDir() / "tests/data/gltf/cube.glb").string() +
                      "\nkey enter\nwait 3\nkey ctrl+s\nwait 2\n",
                  "", /*wallClock=*/false);
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    EXPECT_NE(log.find("collider cube: meshes/cube/cube.glb as "), std::string::npos)
        << "packed, with the note a build prints:\n"
        << log;
    const std::vector<core::ColliderDesc> colliders = savedColliders(dir);
    ASSERT_EQ(colliders.size(), 2u) << log;
    EXPECT_EQ(colliders[1].shape, core::ColliderShape::Mesh);
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / colliders[1].file));
}

// A ball dragged over a layer that clears the ground near colliders (clear_colliders, 1 m of
// clearance): once the drag ends, the blades grow back where it was and go where it now is in
// the patches around it alone (core::followColliderPlacement), the rest of the field keeping its
// motion; before, the whole field grew again on release and every blade restarted from rest.
TEST(EditorMotion, ADraggedBallOverClearedGroundGrowsOnlyThePatchesAroundIt) {
    const auto dir = scratchDir("editor_motion_cleared");
    writeBallProject(dir);
    {
        std::ifstream in(dir / "project.json");
        std::string text((std::istreambuf_iterator<char>(in)), {});
        const std::string layer = R"("name": "grass", "density": 20)";
        text.replace(
            text.find(layer), layer.size(),
            std::string(layer) + R"(, "rules": {"clearance": 1.0, "clear_colliders": true})");
        std::ofstream(dir / "project.json") << text;
    }
    const std::string log = runEditor(
        dir, std::string(SELECT_BALL) + "drag 615 150 615 200 6\nwait 3\nkey ctrl+s\nwait 2\n", "",
        /*wallClock=*/false);
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    std::smatch grew;
    ASSERT_TRUE(std::regex_search(log, grew,
                                  std::regex("grew ([0-9]+) patches again around the colliders")))
        << log;
    EXPECT_GT(std::stoi(grew[1]), 0) << log;
    const std::vector<core::ColliderDesc> colliders = savedColliders(dir);
    ASSERT_EQ(colliders.size(), 1u);
    EXPECT_LT(colliders[0].position.y, 0.7f) << "the drag did not move the ball";
}

// Ctrl+Z of a render setting shows the setting as it was and grows nothing again: before
// 2026-12-07 every undo grew the whole field again, and its blades restarted from rest.
TEST(EditorMotion, AnUndoneLightingChangeGrowsNothingAgain) {
    const auto dir = scratchDir("editor_undo_lighting");
    writeBallProject(dir);
    // Layers collapsed (60, 131) brings the Render section up: its lighting combo box at
    // (85, 487) lists grass, simple (57, 433) and article (57, 459) above it once clicked.
    const std::string log = runEditor(dir,
                                      "wait 2\nclick 60 131\nwait 2\n"
                                      "click 85 487\nwait 2\nclick 57 433\nwait 2\n"
                                      "click 85 487\nwait 2\nclick 57 459\nwait 2\n"
                                      "key ctrl+z\nwait 3\nkey ctrl+s\nwait 2\n",
                                      "", /*wallClock=*/false);
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    auto saved = core::loadProject(dir / "project.json");
    ASSERT_TRUE(saved.ok()) << saved.error().str();
    EXPECT_EQ(saved->project.lighting.model, core::LightingModel::Simple)
        << "the second change (article) was undone:\n"
        << log;
}

}  // namespace
}  // namespace grass::test
