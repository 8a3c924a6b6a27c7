// Drags in the real editor as a slow window delivers them (1–3 frames a second on a software
// renderer): the press comes in the same frame as the first stretch of motion, the release with
// the last, and a quick flick (press, move, release) fits inside one frame. The script's
// `stroke X0 Y0 X1 Y1 N` sends exactly that, with each button change an event at its place, as
// GLFW reports them. Each such drag must do what the same drag spread over many frames does
// (`drag`, a press and a release in frames of their own). Before, the camera and the viewport's
// tools read only where the pointer was when the frame ended: a flick did not turn the camera
// at all, a flick of the brush painted one dab where it was released, a gizmo flick grabbed
// nothing at its press, and every drag lost the stretch that came with its release. Likewise a
// key typed just before a click in the same frame chooses the tool of that click, and a Delete
// just before one removes what was selected before it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "editor_runs.h"
#include "project/project.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

// The mean absolute difference of two 8-bit images' colour channels over the viewport of the
// ball project's 900 × 560 window (right of the side panel, between the menu bar and the
// timeline), in levels of 255; a huge value when either cannot be read, which fails the test.
double viewportDifference(const std::filesystem::path& a, const std::filesystem::path& b) {
    constexpr int LEFT = 340, TOP = 30, RIGHT = 890, BOTTOM = 470;
    auto first = readRgba8Image(a);
    auto second = readRgba8Image(b);
    EXPECT_TRUE(first.ok() && second.ok()) << a << ", " << b;
    if (!first.ok() || !second.ok() || first->width != 900 || second->width != 900 ||
        first->height < BOTTOM || second->height < BOTTOM)
        return 1e9;
    double sum = 0.0;
    for (int y = TOP; y < BOTTOM; ++y)
        for (int x = LEFT; x < RIGHT; ++x)
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = (std::size_t(y) * 900 + std::size_t(x)) * 4 + std::size_t(c);
                sum += std::abs(int(first->pixels[i]) - int(second->pixels[i]));
            }
    return sum / (double(RIGHT - LEFT) * double(BOTTOM - TOP) * 3.0);
}

// The mean absolute difference of two saved maps (8-bit PNGs of one size), levels of 255.
double mapDifference(const std::filesystem::path& a, const std::filesystem::path& b) {
    auto first = readRgba8Image(a);
    auto second = readRgba8Image(b);
    EXPECT_TRUE(first.ok() && second.ok()) << a << ", " << b;
    if (!first.ok() || !second.ok() || first->pixels.size() != second->pixels.size() ||
        first->pixels.empty())
        return 1e9;
    double sum = 0.0;
    for (std::size_t i = 0; i < first->pixels.size(); i += 4)
        sum += std::abs(int(first->pixels[i]) - int(second->pixels[i]));
    return sum / double(first->pixels.size() / 4);
}

// A fresh ball project in a scratch folder named `name`, the editor run on it with `script`
// replayed frame by frame: the folder.
std::filesystem::path runOnBall(const std::string& name, const std::string& script) {
    const auto dir = scratchDir(name);
    writeBallProject(dir);
    runEditor(dir, script, "", /*wallClock=*/false);
    return dir;
}

// The gizmo (g), and a click on the ball's marker selects it.
constexpr const char* SELECT_BALL = "wait 2\nkey g\nwait 2\nclick 615 189\nwait 2\n";
// The ball's up arrow, dragged 50 px down.
constexpr const char* ARROW_DOWN = "615 150 615 200";
constexpr const char* SAVE = "wait 3\nkey ctrl+s\nwait 2\n";

// A second ball, "second", 0.6 m left of the first, its marker at (515, 189).
void addSecondBall(const std::filesystem::path& dir) {
    const std::filesystem::path file = dir / "project.json";
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string first = R"("radius": 0.3})";
    const std::size_t at = text.find(first);
    ASSERT_NE(at, std::string::npos) << text;
    text.insert(at + first.size(), R"(,
    {"name": "second", "shape": "sphere", "position": [-0.6, 0.8, 0], "radius": 0.3})");
    std::ofstream(file) << text;
}
constexpr const char* SECOND_BALL_CLICK = "click 515 189\n";

TEST(EditorSlowFrames, AGizmoDragMovesTheBallAsFarWhateverFramesItsEventsCameIn) {
    const auto moved = [](const std::string& name, const std::string& drag) {
        const auto colliders =
            savedColliders(runOnBall(name, std::string(SELECT_BALL) + drag + "\n" + SAVE));
        return colliders.size() == 1 ? colliders[0].position : glm::vec3(1e9f);
    };
    const glm::vec3 slow = moved("slow_gizmo_drag", std::string("drag ") + ARROW_DOWN + " 6");
    ASSERT_LT(slow.y, 0.7f) << "the slow drag did not move the ball";
    // The same 50 px in one frame (a flick) and in four, the release with the last stretch.
    for (const int frames : {1, 4}) {
        const glm::vec3 quick =
            moved("slow_gizmo_stroke_" + std::to_string(frames),
                  std::string("stroke ") + ARROW_DOWN + " " + std::to_string(frames));
        EXPECT_NEAR(quick.x, slow.x, 1e-4f) << frames << " frame(s)";
        EXPECT_NEAR(quick.y, slow.y, 1e-4f) << frames << " frame(s)";
        EXPECT_NEAR(quick.z, slow.z, 1e-4f) << frames << " frame(s)";
    }
}

// A tool key and a click quicker than a frame (g, then a click on the ball's marker): the click
// goes to the tool the key chose. Before, the keys of a frame were applied after its clicks, so
// the camera took the click, nothing was selected and the drag after it orbited instead. The
// same holds for a key between two clicks of one frame (a click on the sky first).
TEST(EditorSlowFrames, AToolKeyTypedJustBeforeAClickChoosesTheToolOfThatClick) {
    for (const std::string& before : {std::string(), std::string("click 800 80\n")}) {
        const auto colliders = savedColliders(runOnBall(
            "slow_key_then_click", "wait 2\nbatch " + std::to_string(before.empty() ? 2 : 3) +
                                       "\n" + before + "key g\nclick 615 189\nwait 2\ndrag " +
                                       ARROW_DOWN + " 6\n" + SAVE));
        ASSERT_EQ(colliders.size(), 1u) << before;
        EXPECT_LT(colliders[0].position.y, 0.7f)
            << "the click did not select the ball for the gizmo; before it: " << before;
    }
}

// A Delete and a click quicker than a frame: two balls, the first selected (g, a click on its
// marker); then, inside one frame, Delete and a click on the second's marker. The Delete removes
// the ball selected before it and the click selects the second, which stays. Before, a frame's
// keys acted after its clicks: the click selected the second ball and the Delete removed it.
TEST(EditorSlowFrames, ADeleteJustBeforeAClickRemovesWhatWasSelectedBeforeTheClick) {
    const auto dir = scratchDir("slow_delete_then_click");
    writeBallProject(dir);
    addSecondBall(dir);
    runEditor(
        dir,
        std::string(SELECT_BALL) + "batch 2\nkey delete\n" + SECOND_BALL_CLICK + "wait 2\n" + SAVE,
        "", /*wallClock=*/false);
    const auto colliders = savedColliders(dir);
    ASSERT_EQ(colliders.size(), 1u) << "nothing was deleted";
    EXPECT_EQ(colliders[0].name, "second") << "the Delete removed the ball the click selected";
}

// Ctrl+O and a click on the ball's marker inside one frame: the key opens the file browser, a
// dialog, and the click behind it selects nothing; the drag after the browser is closed (its
// × button) orbits the camera and leaves the ball where it was. Before, the click selected
// the ball behind the browser, and that drag moved it.
TEST(EditorSlowFrames, AClickAfterAKeyThatOpensADialogIsNotTheToolsInTheSameFrame) {
    const auto colliders =
        savedColliders(runOnBall("slow_open_then_click",
                                 "wait 2\nkey g\nwait 2\nbatch 2\nkey ctrl+o\nclick "
                                 "615 189\nwait 2\nclick 758 70\nwait 2\ndrag " +
                                     std::string(ARROW_DOWN) + " 6\n" + SAVE));
    ASSERT_EQ(colliders.size(), 1u);
    EXPECT_FLOAT_EQ(colliders[0].position.y, 0.8f)
        << "the click behind the dialog selected the ball";
}

// "35" typed into the layer's density box (a click opened it for typing) and a click on the sky
// inside one frame: the box takes the 35 before the click ends its entry. Before, the frame's
// text came after its clicks, when the box had lost the keyboard, and the 35 was lost (the
// density stayed 20; typed in a frame before the click it was taken).
TEST(EditorSlowFrames, ANumberTypedJustBeforeAClickElsewhereIsTaken) {
    const auto dir = runOnBall("slow_type_then_click",
                               "wait 2\nclick 198 339\nwait 2\nbatch "
                               "2\ntype 35\nclick 800 80\nwait 2\n" +
                                   std::string(SAVE));
    const auto saved = core::loadProject(dir / "project.json");
    ASSERT_TRUE(saved.ok()) << saved.error().str();
    ASSERT_EQ(saved->project.layers.size(), 1u);
    EXPECT_FLOAT_EQ(saved->project.layers[0].scatter.density, 35.0f);
}

TEST(EditorSlowFrames, AFlickInsideOneFrameTurnsTheCameraAsASlowDragDoes) {
    // The field settles first (no wind: its blades come to rest), so the pictures differ only
    // by the view. The pointer then leaves the viewport for the screenshot.
    const std::string settle = "wait 30\nmove 100 540\nwait 1\nscreenshot still.png\n";
    const std::string shot = "wait 3\nmove 100 540\nwait 1\nscreenshot turned.png\n";
    const auto slow = runOnBall("slow_camera_drag", settle + "drag 450 420 550 420 6\n" + shot);
    const auto flick = runOnBall("slow_camera_flick", settle + "stroke 450 420 550 420 1\n" + shot);
    // A 100 px orbit moves the plane, the ball and the sky's edge across most of the view
    // (measured: 11.3 levels on average); a flick that turned nothing leaves the still picture.
    const double turned = viewportDifference(slow / "still.png", slow / "turned.png");
    ASSERT_GT(turned, 5.0) << "the slow drag did not turn the camera";
    EXPECT_GT(viewportDifference(flick / "still.png", flick / "turned.png"), 5.0)
        << "the flick did not turn the camera";
    // Turned alike: the same orbit gives the same picture, up to the blades' last settling
    // (a tenth of the turn's difference allowed; measured: 0.0006 levels).
    EXPECT_LT(viewportDifference(slow / "turned.png", flick / "turned.png"), 0.1 * turned);
}

// The brush (b), Ctrl held to take density away (the map starts at 1 everywhere), `stroke`
// across the plane, saved: the map the project keeps.
std::filesystem::path paintedMap(const std::string& name, const std::string& stroke) {
    return runOnBall(name, "wait 2\nkey b\nwait 1\nhold ctrl\n" + stroke + "\nhold none\n" + SAVE) /
           "maps" / "grass-density.png";
}

// How much a painted map took away from an untouched one (all 255), levels of 255 on average.
double takenAway(const std::filesystem::path& map) {
    auto image = readRgba8Image(map);
    EXPECT_TRUE(image.ok()) << map;
    if (!image.ok() || image->pixels.empty())
        return 0.0;
    double taken = 0.0;
    for (std::size_t i = 0; i < image->pixels.size(); i += 4)
        taken += 255 - image->pixels[i];
    return taken / double(image->pixels.size() / 4);
}

TEST(EditorSlowFrames, ABrushStrokeInsideOneFramePaintsFromItsPressToItsRelease) {
    const auto slow = paintedMap("slow_brush_drag", "drag 480 330 750 330 8");
    const auto flick = paintedMap("slow_brush_flick", "stroke 480 330 750 330 1");
    const auto lastStretch = paintedMap("slow_brush_stroke", "stroke 480 330 750 330 3");
    ASSERT_TRUE(std::filesystem::exists(slow)) << "the slow stroke painted nothing";
    const double taken = takenAway(slow);
    ASSERT_GT(taken, 5.0) << "the slow stroke took too little away to compare with";
    // The same dabs along the same line, up to the dabs' spacing carried across the segments
    // (the screen line maps onto the plane's line, so they land alike; allowed: a tenth of the
    // stroke; measured: 0.00002 of the 19.9 levels taken away). A flick that painted one dab at its
    // release leaves most of the line untouched.
    EXPECT_LT(mapDifference(slow, flick), 0.1 * taken);
    EXPECT_LT(mapDifference(slow, lastStretch), 0.1 * taken);
}

// A stroke that turns a corner inside one frame follows the pointer round it, as the same path
// over four frames does: the window records where the pointer went while the button was held,
// and the brush paints along it. Before, it painted the chord from where the last frame saw the
// pointer to where this one did, cutting the corner.
TEST(EditorSlowFrames, ABrushStrokeThatTurnsACornerInsideOneFrameFollowsIt) {
    const std::string corner = "480 330 550 330 620 330 620 362 620 395";
    const auto slow = paintedMap("slow_brush_corner", "strokepath 4 " + corner);
    const auto flick = paintedMap("slow_brush_corner_flick", "strokepath 1 " + corner);
    const auto chord = paintedMap("slow_brush_chord", "stroke 480 330 620 395 1");
    const double taken = takenAway(slow);
    ASSERT_GT(taken, 5.0) << "the slow stroke took too little away to compare with";
    // Cutting the corner differs from going round it by much of the stroke; going round it
    // in one frame or four, by the dabs' spacing (measured: 18.0 levels taken away; the chord
    // 24.0 off, the one-frame path 0; without the path the one frame painted the chord).
    ASSERT_GT(mapDifference(slow, chord), 0.3 * taken) << "the chord is no test of the corner";
    EXPECT_LT(mapDifference(slow, flick), 0.1 * taken);
}

}  // namespace
}  // namespace grass::test
