// The editor replaying recorded input under Xvfb (issue 8: `grass-editor --script`): a brush
// stroke with Ctrl held erases grass where it passes, Ctrl+Z brings the field back exactly as it
// was, Ctrl+Shift+Z takes it away again, and Ctrl+S saves the painted map next to the project.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "gl_context_fixture.h"
#include "maps/map_image.h"
#include "project/project.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

constexpr int WIDTH = 900, HEIGHT = 560;
// The 3D view in the window: right of the 330-point side panel, between the menu bar and the
// timeline strip and the status bar (whose playhead and timings differ from frame to frame).
constexpr int VIEW_X0 = 340, VIEW_Y0 = 30, VIEW_X1 = WIDTH, VIEW_Y1 = HEIGHT - 86;

// Share of the view's pixels whose colour differs by more than 24/255 in some channel.
double changedShare(const Rgba8Pixels& a, const Rgba8Pixels& b) {
    std::size_t changed = 0, total = 0;
    for (int y = VIEW_Y0; y < VIEW_Y1; ++y)
        for (int x = VIEW_X0; x < VIEW_X1; ++x, ++total) {
            const std::size_t i = (std::size_t(y) * WIDTH + std::size_t(x)) * 4;
            for (std::size_t c = 0; c < 3; ++c)
                if (std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > 24) {
                    ++changed;
                    break;
                }
        }
    return double(changed) / double(total);
}

// A 3 m plane of grass seen from above, the window wide enough for the side panel.
constexpr const char* PROJECT = R"({
  "format": "grass-project", "version": 1, "name": "tiny",
  "mesh": {"procedural": "plane", "size": 3, "resolution": 4},
  "layers": [{"name": "grass", "density": 300, "map_resolution": [96, 96]}],
  "cameras": [{"name": "above", "position": [0, 3.2, 2.2], "target": [0, 0, 0]}],
  "render": {"width": 900, "height": 560, "geometry": "strips", "msaa": 0}
})";

// The lowest texel of the project's saved density map (1 where nothing was painted).
float lowestSavedDensity(const std::filesystem::path& dir) {
    auto saved = core::loadProject(dir);
    EXPECT_TRUE(saved.ok()) << saved.error().str();
    if (!saved.ok() || saved->project.layers.front().densityMap.empty())
        return 1.0f;
    auto map = core::loadMapImageAt(dir / saved->project.layers.front().densityMap, 96, 96);
    EXPECT_TRUE(map.ok()) << map.error().str();
    float lowest = 1.0f;
    for (const float v : map.ok() ? map->texels : std::vector<float>{})
        lowest = std::min(lowest, v);
    return lowest;
}

// Runs the editor with GL debug output on; any GL error it reports fails the test.
int runEditor(const std::filesystem::path& dir, const std::string& arguments) {
    const std::string command = "xvfb-run -a -s '-screen 0 1024x768x24' " +
                                std::string(GRASS_EDITOR_EXE) + " --gl-debug " + arguments +
                                " > " + (dir / "log.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    expectNoGlErrorLines(dir / "log.txt");
    return status;
}

TEST(EditorScript, AStrokeUndoRedoAndSaveReplayedUnderXvfb) {
    const auto dir = scratchDir("editor_script");
    std::ofstream(dir / "project.json") << PROJECT;
    // The pointer rests on the menu bar's title for every screenshot, so no brush ring shows and
    // no setting's tooltip covers the view (over the side panel one would).
    std::ofstream(dir / "session.txt") << R"(# paint a bare path across the field, undo, redo, save
move 700 12
screenshot before.png
key b
hold ctrl
drag 420 280 860 300 12
hold none
move 700 12
screenshot painted.png
key ctrl+z
wait 1
screenshot undone.png
key ctrl+shift+z
wait 1
screenshot redone.png
key ctrl+s
wait 1
)";
    const int status = runEditor(dir, dir.string() + " --no-physics --script " +
                                          (dir / "session.txt").string());
    ASSERT_EQ(status, 0) << "see " << (dir / "log.txt");
    auto before = readRgba8Image((dir / "before.png").string());
    auto painted = readRgba8Image((dir / "painted.png").string());
    auto undone = readRgba8Image((dir / "undone.png").string());
    auto redone = readRgba8Image((dir / "redone.png").string());
    ASSERT_TRUE(before.ok() && painted.ok() && undone.ok() && redone.ok());
    ASSERT_EQ(before->width, WIDTH);
    ASSERT_EQ(before->height, HEIGHT);

    // The stroke shows: a path of the view changed. Without physics the renderer is
    // deterministic, so the undone field is the first one again: a few pixels may differ where
    // anti-aliased edges meet (the threshold is 24/255), none in bulk.
    EXPECT_GT(changedShare(before.value(), painted.value()), 0.02);
    EXPECT_LT(changedShare(before.value(), undone.value()), 0.001);
    EXPECT_LT(changedShare(painted.value(), redone.value()), 0.001);

    // Ctrl+S wrote the map and named it in the project.
    EXPECT_LT(lowestSavedDensity(dir), 0.6f);
}

// Replays `script` in the editor on the project in `dir` (no physics) and loads what it saved.
core::Project replayAndLoad(const std::filesystem::path& dir, const std::string& name,
                            const std::string& script) {
    std::ofstream(dir / name) << script;
    EXPECT_EQ(runEditor(dir, dir.string() + " --no-physics --script " + (dir / name).string()), 0)
        << "see " << (dir / "log.txt");
    auto saved = core::loadProject(dir);
    EXPECT_TRUE(saved.ok()) << saved.error().str();
    return saved.ok() ? saved->project : core::Project{};
}

// Issue 23: T and L are project edits, like the Render panel's combo boxes: Ctrl+S saves them
// and Ctrl+Z takes them back. Before, they changed the view only.
TEST(EditorScript, TechniqueAndLightingKeysAreSavedAndUndone) {
    const auto dir = scratchDir("editor_script_keys");
    std::ofstream(dir / "project.json") << PROJECT;
    core::Project saved = replayAndLoad(dir, "keys.txt", R"(# next technique, other lighting, save
move 600 300
key t
wait 1
key l
wait 1
key ctrl+s
wait 1
)");
    EXPECT_EQ(saved.render.technique, core::GrassTechnique::Billboards);
    EXPECT_EQ(saved.lighting.model, core::LightingModel::Simple);
    // The next session: T once more and undone, L once more; saved.
    saved = replayAndLoad(dir, "undo.txt", R"(# T undone, L kept, save
move 600 300
key t
wait 1
key ctrl+z
wait 1
key l
wait 1
key ctrl+s
wait 1
)");
    EXPECT_EQ(saved.render.technique, core::GrassTechnique::Billboards);
    EXPECT_EQ(saved.lighting.model, core::LightingModel::Grass);
}

// A session that ends without saving (the script stops as a crash would) leaves its autosave;
// the next start takes it back (--recover answers the recovery window's question), and a save
// then writes the painted map under its real name and removes the side files.
TEST(EditorScript, AnUnsavedStrokeIsAutosavedAndRecoveredAfterACrash) {
    const auto dir = scratchDir("editor_autosave");
    std::ofstream(dir / "project.json") << PROJECT;
    std::ofstream(dir / "paint.txt") << R"(key b
hold ctrl
drag 420 280 860 300 12
hold none
wait 40
)";
    // --autosave-s 0.5 at one 1/60 s step a frame: an autosave 30 frames after the stroke.
    ASSERT_EQ(runEditor(dir, dir.string() + " --no-physics --autosave-s 0.5 --script " +
                                 (dir / "paint.txt").string()),
              0)
        << "see " << (dir / "log.txt");
    ASSERT_TRUE(std::filesystem::exists(dir / "project.autosave.json"));
    ASSERT_TRUE(std::filesystem::exists(dir / "maps/grass-density.autosave.png"));
    // The real project was never touched.
    std::ifstream original(dir / "project.json");
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(original)), {}), PROJECT);

    std::ofstream(dir / "save.txt") << "wait 2\nkey ctrl+s\nwait 1\n";
    ASSERT_EQ(runEditor(dir, dir.string() + " --no-physics --recover --script " +
                                 (dir / "save.txt").string()),
              0)
        << "see " << (dir / "log.txt");
    auto saved = core::loadProject(dir);
    ASSERT_TRUE(saved.ok()) << saved.error().str();
    EXPECT_EQ(saved->project.layers.front().densityMap, "maps/grass-density.png");
    EXPECT_LT(lowestSavedDensity(dir), 0.6f);
    EXPECT_FALSE(std::filesystem::exists(dir / "project.autosave.json"));
    EXPECT_FALSE(std::filesystem::exists(dir / "maps/grass-density.autosave.png"));
}

// Issue 26 item 1: a glTF dropped on the window becomes the project's surface (copied into the
// project with the files it names, the view framed on it, its own texture drawn), a picture
// dropped becomes the brush's map, and Ctrl+S saves both.
TEST(EditorScript, ADroppedMeshAndMapAreImportedAndSaved) {
    const auto dir = scratchDir("editor_script_drop");
    std::ofstream(dir / "project.json") << PROJECT;
    core::MapImage half = core::makeConstantMap(96, 96, 1.0f);
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 48; ++x)
            half.texels[static_cast<std::size_t>(y * 96 + x)] = 0.0f;
    std::filesystem::create_directories(dir / "elsewhere");
    ASSERT_TRUE(core::saveMapImage(half, dir / "elsewhere/half.png").ok());
    const auto stone = sourceDir() / "tests/data/projects/textured_stone/stone.gltf";
    std::ofstream(dir / "drop.txt") << "move 700 12\nscreenshot before.png\ndrop " << stone.string()
                                    << "\nwait 2\nscreenshot imported.png\ndrop elsewhere/half.png\n"
                                       "wait 2\nscreenshot painted.png\nkey ctrl+s\nwait 1\n";
    ASSERT_EQ(runEditor(dir, dir.string() + " --no-physics --script " + (dir / "drop.txt").string()), 0)
        << "see " << (dir / "log.txt");
    auto saved = core::loadProject(dir);
    ASSERT_TRUE(saved.ok()) << saved.error().str();
    EXPECT_EQ(saved->project.mesh.file, "meshes/stone/stone.gltf");
    for (const char* file : {"stone.gltf", "stone.bin", "stone.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / "meshes/stone" / file)) << file;
    EXPECT_EQ(saved->project.layers.front().densityMap, "maps/grass-density.png");
    EXPECT_LT(lowestSavedDensity(dir), 0.01f) << "the dropped picture is the density map";
    auto before = readRgba8Image((dir / "before.png").string());
    auto imported = readRgba8Image((dir / "imported.png").string());
    auto painted = readRgba8Image((dir / "painted.png").string());
    ASSERT_TRUE(before.ok() && imported.ok() && painted.ok());
    // Another surface, framed: most of the view changes; half the grass goes with the picture.
    EXPECT_GT(changedShare(before.value(), imported.value()), 0.2);
    EXPECT_GT(changedShare(imported.value(), painted.value()), 0.02);
}

TEST(EditorScript, ABadScriptIsRefusedBeforeAnyWindowOpens) {
    const auto dir = scratchDir("editor_script_bad");
    std::ofstream(dir / "bad.txt") << "move 10 10\ndrag 1 2 3\n";
    const std::string command = std::string(GRASS_EDITOR_EXE) + " --script " +
                                (dir / "bad.txt").string() + " > " +
                                (dir / "log.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    std::ifstream log(dir / "log.txt");
    const std::string text((std::istreambuf_iterator<char>(log)), {});
    EXPECT_NE(text.find("bad.txt:2: drag: expected X0 Y0 X1 Y1 N"), std::string::npos) << text;
}

}  // namespace
}  // namespace grass::test
