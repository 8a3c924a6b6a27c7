// A collider dragged with the gizmo in the real editor (app/editor.cpp, followMotionEdits): its
// prop follows the drag frame by frame, and its release grows nothing again. Before, the prop
// stood where it was until the mouse was released, and then the whole field grew again ("grew
// the field again" in the log) and its blades restarted from rest.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "editor_runs.h"
#include "project/project.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

// A ball above a small field, seen from the front: 900 × 560, its marker at (615, 189) and its
// radius about 50 px on screen.
void writeBallProject(const std::filesystem::path& dir) {
    std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 2,
  "name": "ball", "mesh": {"procedural": "plane", "size": 2, "resolution": 2},
  "layers": [{"name": "grass", "density": 20}],
  "colliders": [{"name": "ball", "shape": "sphere", "position": [0, 0.8, 0], "radius": 0.3}],
  "cameras": [{"name": "main", "position": [0.0, 1.6, 3.2], "target": [0, 0.4, 0]}],
  "render": {"width": 900, "height": 560, "geometry": "strips", "msaa": 0}})";
}

// The colliders of the project `dir` holds (saved by the script's Ctrl+S); none when it cannot
// be read, which fails the test.
std::vector<core::ColliderDesc> savedColliders(const std::filesystem::path& dir) {
    auto saved = core::loadProject(dir / "project.json");
    EXPECT_TRUE(saved.ok()) << saved.error().str();
    return saved.ok() ? saved->project.colliders : std::vector<core::ColliderDesc>{};
}

TEST(EditorMotion, ADraggedBallMovesAsItIsDraggedAndGrowsNothingAgain) {
    const auto dir = scratchDir("editor_motion");
    writeBallProject(dir);
    // The gizmo, the ball selected, its up arrow dragged 50 px down and held there for a
    // screenshot, released, saved.
    const std::string log = runEditor(dir,
                                      "wait 2\nkey g\nwait 2\nclick 615 189\nwait 2\n"
                                      "move 615 150\npress\nmove 615 170\nmove 615 190\n"
                                      "move 615 200\nwait 3\nscreenshot held.png\nrelease\n"
                                      "wait 3\nkey ctrl+s\nwait 2\n",
                                      "", /*wallClock=*/false);
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    const std::vector<core::ColliderDesc> colliders = savedColliders(dir);
    ASSERT_EQ(colliders.size(), 1u);
    EXPECT_LT(colliders[0].position.y, 0.7f) << "the drag did not move the ball";
    // Held mid-drag: where the ball's upper half was (25 px left of its marker, 24 px above),
    // the sky shows, since the ball went down with the pointer.
    auto held = readRgba8Image(dir / "held.png");
    ASSERT_TRUE(held.ok()) << held.error().str();
    ASSERT_EQ(held->width, 900);
    const std::uint8_t* pixel = &held->pixels[(std::size_t(165) * 900 + 590) * 4];
    EXPECT_GT(int(pixel[2]), int(pixel[0]) + 40)
        << "the ball's prop stayed where it was during the drag (rgb " << int(pixel[0]) << " "
        << int(pixel[1]) << " " << int(pixel[2]) << ")";
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

}  // namespace
}  // namespace grass::test
