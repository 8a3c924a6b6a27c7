// A collider dragged with the gizmo in the real editor (app/editor.cpp, followMotionEdits): its
// prop follows the drag frame by frame, and its release grows nothing again. Before, the prop
// stood where it was until the mouse was released, and then the whole field grew again ("grew
// the field again" in the log) and its blades restarted from rest.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "editor_runs.h"
#include "project/project.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

TEST(EditorMotion, ADraggedBallMovesAsItIsDraggedAndGrowsNothingAgain) {
    const auto dir = scratchDir("editor_motion");
    // A ball above a small field, seen from the front: 900 × 560, its marker at (615, 189) and
    // its radius about 50 px on screen.
    std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 2,
  "name": "ball", "mesh": {"procedural": "plane", "size": 2, "resolution": 2},
  "layers": [{"name": "grass", "density": 20}],
  "colliders": [{"name": "ball", "shape": "sphere", "position": [0, 0.8, 0], "radius": 0.3}],
  "cameras": [{"name": "main", "position": [0.0, 1.6, 3.2], "target": [0, 0.4, 0]}],
  "render": {"width": 900, "height": 560, "geometry": "strips", "msaa": 0}})";
    // The gizmo, the ball selected, its up arrow dragged 50 px down and held there for a
    // screenshot, released, saved.
    const std::string log = runEditor(dir,
                                      "wait 2\nkey g\nwait 2\nclick 615 189\nwait 2\n"
                                      "move 615 150\npress\nmove 615 170\nmove 615 190\n"
                                      "move 615 200\nwait 3\nscreenshot held.png\nrelease\n"
                                      "wait 3\nkey ctrl+s\nwait 2\n",
                                      "", /*wallClock=*/false);
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    auto saved = core::loadProject(dir / "project.json");
    ASSERT_TRUE(saved.ok()) << saved.error().str();
    ASSERT_EQ(saved->project.colliders.size(), 1u);
    EXPECT_LT(saved->project.colliders[0].position.y, 0.7f) << "the drag did not move the ball";
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

}  // namespace
}  // namespace grass::test
