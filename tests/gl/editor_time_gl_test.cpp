// The editor's time is wall-clock time (issue 24): on a machine slow enough that every frame
// takes over 300 ms, 10 s of wall time still move the timeline 10 s, the physics that cannot
// keep up skips time instead of piling up work, and the autosave fires by the clock. Before, time
// advanced only by the part of each frame that was not rendering (0.02 s in 30 s on the meadow).
#include <gtest/gtest.h>

#include <algorithm>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "editor_runs.h"
#include "gl_context_fixture.h"
#include "maps/map_image.h"
#include "project/project.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

// The --wall-clock summary's first line: "wall clock W s, N frames, timeline moved T s, physics
// skipped S s".
struct WallClockSummary {
    bool found = false;
    double wallS = 0.0, movedS = 0.0, skippedS = 0.0;
    int frames = 0;
};
WallClockSummary wallClockSummary(const std::string& log) {
    WallClockSummary summary;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line))
        if (std::sscanf(line.c_str(),
                        "wall clock %lf s, %d frames, timeline moved %lf s, physics skipped %lf s",
                        &summary.wallS, &summary.frames, &summary.movedS, &summary.skippedS) == 4)
            summary.found = true;
    return summary;
}

TEST(EditorTime, TenSecondsOfSlowFramesMoveTheTimelineTenSecondsAndAutosave) {
    const auto dir = scratchDir("editor_time");
    writeTinyProject(dir);
    // T makes an unsaved edit (an autosave is due); then ten seconds with no input.
    std::ofstream(dir / "script.txt") << "key t\nwait-s 10\n";
    const std::string command =
        "xvfb-run -a -s '-screen 0 1024x768x24' " + std::string(GRASS_EDITOR_EXE) + " " +
        dir.string() + " --script " + (dir / "script.txt").string() +
        " --wall-clock --frame-delay-ms 300 --autosave-s 3 > " + (dir / "log.txt").string() +
        " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command << " (see " << dir / "log.txt" << ")";

    std::ifstream log(dir / "log.txt");
    std::stringstream text;
    text << log.rdbuf();
    const auto [found, wallS, movedS, skippedS, frames] = wallClockSummary(text.str());
    ASSERT_TRUE(found) << "no summary line in " << dir / "log.txt";
    EXPECT_GE(wallS, 10.0);
    // A frame here is at least the 300 ms delay: far fewer than 60 per second.
    EXPECT_LT(frames, int(wallS / 0.3) + 2);
    // ± 5 % (the bound): the timeline follows the clock, not the frames.
    EXPECT_NEAR(movedS, wallS, 0.05 * wallS) << frames << " frames";
    // Four physics steps a frame cannot follow 300 ms frames: the rest is skipped, and said.
    EXPECT_GT(skippedS, 0.0);
    EXPECT_TRUE(std::filesystem::exists(dir / "project.autosave.json"))
        << "the unsaved edit was not autosaved by the clock";
}

// A minimised window draws nothing and its timeline holds, while the autosave keeps its clock.
// On X11 a minimised window keeps its framebuffer's size, so before, an editor minimised while it
// played went on drawing the field on every core (llvmpipe) until it was shown again.
TEST(EditorTime, AMinimisedWindowDrawsNothingAndHoldsItsTimelineButStillAutosaves) {
    const auto dir = scratchDir("editor_minimised");
    writeTinyProject(dir, "tiny", 480, 320, /*windy=*/true);
    // T (an edit) and straight into 4 s minimised, past the 2 s autosave; then one frame shown.
    const std::string log =
        runEditor(dir, "key t\nminimise\nwait-s 4\nrestore\nwait 1\n", "--autosave-s 2");
    const WallClockSummary summary = wallClockSummary(log);
    ASSERT_TRUE(summary.found) << log;
    // The shown frames before and after, and the restored frame's time (at most one idle wait,
    // LONGEST_IDLE_WAIT_S = 1 s): well under the 4 s minimised.
    EXPECT_LT(summary.movedS, summary.wallS - 2.0) << log;
    // One frame per idle wait (1 s) at least, woken by nothing: about 4.
    int minimisedFrames = -1;
    if (const std::size_t at = log.find("minimised for "); at != std::string::npos)
        std::sscanf(log.c_str() + at, "minimised for %d frames", &minimisedFrames);
    EXPECT_GE(minimisedFrames, 1) << log;
    EXPECT_LE(minimisedFrames, 8) << log;
    EXPECT_TRUE(std::filesystem::exists(dir / "project.autosave.json"))
        << "the edit left minimised was not autosaved:\n"
        << log;
}

// "status timings of frame T, last full picture drawn in frame F": {T, F}.
std::pair<int, int> statusTimingsFrames(const std::string& log) {
    int timings = -2, full = -2;
    const std::size_t at = log.find("status timings of frame ");
    if (at != std::string::npos)
        std::sscanf(log.c_str() + at,
                    "status timings of frame %d, last full picture drawn in frame %d", &timings,
                    &full);
    return {timings, full};
}

// "status bar: B blades, D drawn, picture full|reduced".
struct StatusBarCounts {
    bool found = false, reduced = false;
    std::size_t blades = 0, drawn = 0;
};
StatusBarCounts statusBarCounts(const std::string& log) {
    StatusBarCounts counts;
    char picture[16] = "";
    const std::size_t at = log.find("status bar: ");
    counts.found = at != std::string::npos &&
                   std::sscanf(log.c_str() + at, "status bar: %zu blades, %zu drawn, picture %15s",
                               &counts.blades, &counts.drawn, picture) == 3;
    counts.reduced = std::string(picture) == "reduced";
    return counts;
}

// Playback of a field that moves (a breeze) counts as interaction: with a budget no frame meets
// (5 ms, the least allowed), a playing editor draws the reduced picture for as long as it plays
// (it opens playing), and Space (pause) brings back the full one once the settle time has passed
// — the summary's "full quality after input stops" counts those returns.
TEST(EditorTime, PlaybackKeepsTheReducedPictureUntilPaused) {
    const auto dir = scratchDir("editor_playback_quality");
    writeTinyProject(dir, "tiny", 480, 320, /*windy=*/true);
    const std::string returned = "full quality after input stops:";
    const std::string playing = runEditor(dir, "wait-s 3\n", "--frame-budget-ms 5");
    EXPECT_EQ(playing.find(returned), std::string::npos)
        << "the picture refined while the timeline played:\n" << playing;
    // While it plays the status bar counts the blades of the reduced picture it shows (at a
    // budget no frame meets, the ladder's last rungs draw one blade in 16; a quarter of the
    // field leaves room). Before, it kept those of the full picture the window had opened with.
    const StatusBarCounts whilePlaying = statusBarCounts(playing);
    ASSERT_TRUE(whilePlaying.found) << playing;
    EXPECT_TRUE(whilePlaying.reduced) << playing;
    EXPECT_GT(whilePlaying.drawn, 0u) << playing;
    EXPECT_LE(whilePlaying.drawn, whilePlaying.blades / 4) << playing;
    const std::string paused = runEditor(dir, "wait-s 3\nkey space\nwait-s 2\n", "--frame-budget-ms 5");
    EXPECT_NE(paused.find(returned), std::string::npos)
        << "pausing did not bring back the full picture:\n" << paused;
    // The status bar's stage timings and blade counts are the full picture's that came back,
    // the frame the window then rests on. Before, they stayed those of the first frame.
    const auto [timingsFrame, fullFrame] = statusTimingsFrames(paused);
    EXPECT_GT(fullFrame, 0) << paused;
    EXPECT_EQ(timingsFrame, fullFrame) << paused;
    // Paused, an edit (T: the technique) draws one full picture between frames that draw
    // nothing: it measures them too.
    const std::string edited =
        runEditor(dir, "key space\nwait-s 1.5\nkey t\nwait-s 1.5\n", "--frame-budget-ms 5");
    const auto [editTimingsFrame, editFullFrame] = statusTimingsFrames(edited);
    EXPECT_EQ(editTimingsFrame, editFullFrame) << edited;
    // Without adaptive quality nothing is ever reduced, so nothing returns.
    const std::string off = runEditor(dir, "wait-s 3\n", "--no-adaptive");
    EXPECT_EQ(off.find(returned), std::string::npos) << off;
}

// "viewport drawn in N of M frames": {N, M}.
std::pair<int, int> viewportDrawn(const std::string& log) {
    int drawn = -1, frames = -1;
    const std::size_t at = log.find("viewport drawn in ");
    if (at != std::string::npos)
        std::sscanf(log.c_str() + at, "viewport drawn in %d of %d frames", &drawn, &frames);
    return {drawn, frames};
}

// A field that nothing moves (no wind: its blades settle under gravity within a fraction of a
// second) plays at full quality, and its picture is not drawn again while the timeline plays:
// it does not change. Before, playback counted as interaction whatever moved, so a new project
// from a mesh (no wind) played reduced, every frame drawn. With a breeze each step is drawn.
TEST(EditorTime, AFieldThatNothingMovesPlaysAtFullQualityAndIsNotDrawnAgain) {
    const std::string returned = "full quality after input stops:";
    const auto still = scratchDir("editor_playback_still");
    writeTinyProject(still);
    const std::string stillLog = runEditor(still, "wait-s 3\n", "--frame-budget-ms 5");
    EXPECT_NE(stillLog.find(returned), std::string::npos)
        << "the still field stayed reduced while it played:\n"
        << stillLog;
    const auto [drawn, frames] = viewportDrawn(stillLog);
    ASSERT_GT(frames, 20) << stillLog;
    EXPECT_LT(drawn, frames / 4) << stillLog;
    // Its few pictures are drawn at full quality between frames that draw nothing: the last one
    // measured the status bar's timings, as any full picture the window then rests on.
    const auto [timingsFrame, fullFrame] = statusTimingsFrames(stillLog);
    EXPECT_EQ(timingsFrame, fullFrame) << stillLog;
    const auto windy = scratchDir("editor_playback_windy");
    writeTinyProject(windy, "tiny", 480, 320, /*windy=*/true);
    const std::string windyLog = runEditor(windy, "wait-s 3\n", "--frame-budget-ms 5");
    // Drawn after each physics step (60 a second; a script's frames come faster, and those
    // between two steps draw nothing new): at least half of 3 s of steps, or every frame when
    // frames are slower than the steps.
    const auto [windyDrawn, windyFrames] = viewportDrawn(windyLog);
    EXPECT_GE(windyDrawn, std::min(windyFrames, 90)) << windyLog;
    EXPECT_GT(windyDrawn, 2 * drawn) << windyLog;
}

// The frames of a script phase, from the --wall-clock summary ("frames NAME: N, median …").
int framesOfPhase(const std::string& log, const std::string& phase) {
    const std::string head = "frames " + phase + ": ";
    const std::size_t at = log.find(head);
    return at == std::string::npos ? 0 : std::atoi(log.c_str() + at + head.size());
}

// The technique a project file names (none: the default, as our test projects are written).
std::string savedTechnique(const std::filesystem::path& projectFile) {
    auto loaded = core::loadProject(projectFile);
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    return loaded.ok() ? std::string(core::grassTechniqueName(loaded->project.render.technique))
                       : std::string();
}

// File › Open grows the next field on a worker (app/document_job.h): held back 1.5 s here
// (--load-delay-ms, standing for a large mesh), the window goes on drawing frames meanwhile and
// the opened project is the one a later edit and Ctrl+S change. Cancel, clicked while it loads,
// keeps the project that was open. Before, the window stood still on its last frame for the whole
// load, with no way back.
TEST(EditorTime, AnOpenGrowsWhileTheWindowGoesOnAndCancelKeepsTheProject) {
    // The viewport wide enough for the loading box beside the side panel.
    const auto project = [](const std::filesystem::path& folder, const std::string& name) {
        writeTinyProject(folder, name, 900, 560);
    };
    // T (the technique, a project edit) then Ctrl+S mark the project open at the end.
    const std::string openScript =
        "phase before\nwait 2\ndrop other\nphase loading\nwait-s 1.5\nphase after\n"
        "wait-s 1.5\nkey t\nkey ctrl+s\nwait 2\n";
    {
        const auto dir = scratchDir("editor_open_async");
        project(dir, "first");
        project(dir / "other", "other");
        const std::string log = runEditor(dir, openScript, "--no-physics --load-delay-ms 1500");
        // 1.5 s of a 2-point field: tens of frames at llvmpipe's speed; one if the load blocked.
        EXPECT_GE(framesOfPhase(log, "loading"), 4) << log;
        EXPECT_EQ(savedTechnique(dir / "other/project.json"), "billboards") << log;
        EXPECT_EQ(savedTechnique(dir / "project.json"), "blades") << log;
    }
    {
        // The box's Cancel at the viewport's centre (the window is 900 × 560).
        const auto dir = scratchDir("editor_open_cancelled");
        project(dir, "first");
        project(dir / "other", "other");
        const std::string log =
            runEditor(dir,
                      "wait 2\ndrop other\nwait-s 0.5\nclick 464 265\nwait-s 2\nkey t\nkey ctrl+s\n"
                      "wait 2\n",
                      "--no-physics --load-delay-ms 1500");
        EXPECT_EQ(savedTechnique(dir / "project.json"), "billboards") << log;
        EXPECT_EQ(savedTechnique(dir / "other/project.json"), "blades") << log;
    }
}

// The first blade count the log reports with `pattern` (a regex with one number group), or -1.
long bladesIn(const std::string& log, const std::string& pattern) {
    std::smatch match;
    return std::regex_search(log, match, std::regex(pattern)) ? std::stol(match[1]) : -1;
}

// The log of a 900×560 editor on the tiny project running `script`, its re-grows held back
// `delayMs` (--load-delay-ms, standing for a large mesh, where they take seconds); with the
// blade count of the first field and of the first field grown again (-1: none).
struct RegrowRun {
    std::string log;
    long firstBlades = -1;
    long regrownBlades = -1;
};
RegrowRun runRegrows(const std::string& name, const std::string& script, int delayMs) {
    const auto dir = scratchDir(name);
    writeTinyProject(dir, "tiny", 900, 560);
    RegrowRun run;
    run.log = runEditor(dir, script, "--no-physics --load-delay-ms " + std::to_string(delayMs));
    run.firstBlades = bladesIn(run.log, ", ([0-9]+) blades, geometry ");
    run.regrownBlades = bladesIn(run.log, "grew the field again: ([0-9]+) blades");
    return run;
}

// An edit of the layers grows the field again on a worker (Editor::startRegrow): held back 1.5 s
// here (--load-delay-ms, standing for a large mesh, where it takes seconds), the window goes on
// drawing the field before the edit, then takes in the new one. The edit is the layer's
// "duplicate" button: twice the blades. Before, the re-grow ran on the UI thread: the window
// stood still for it.
TEST(EditorTime, AnEditOfTheLayersGrowsTheFieldWhileTheWindowGoesOn) {
    const RegrowRun run = runRegrows(
        "editor_regrow_async",
        "wait 2\nclick 80 208\nphase growing\nwait-s 1.5\nphase after\nwait-s 1\n", 1500);
    // 1.5 s of a 2-point field: tens of frames at llvmpipe's speed; one if the re-grow blocked.
    EXPECT_GE(framesOfPhase(run.log, "growing"), 4) << run.log;
    EXPECT_GT(run.firstBlades, 0) << run.log;
    EXPECT_EQ(run.regrownBlades, 2 * run.firstBlades) << run.log;
}

// A second edit while the first one's re-grow still runs stops that re-grow and grows its own
// at once: the re-grows are held back 3 s each here (--load-delay-ms, standing for a large
// mesh), the layer duplicated twice 0.5 s apart (its duplicate button moves right once a
// second layer gives it a "down" button). The field that comes in is the second edit's
// (three layers), 3 s after it; the first edit's (two layers) never does. Before, the first
// re-grow ran to its end and the second began only then: the field of the last edit came a
// whole re-grow later (after the script here has ended).
TEST(EditorTime, AnEditWhileTheFieldGrowsAgainStopsThatGrowing) {
    const RegrowRun run =
        runRegrows("editor_regrow_superseded",
                   "wait 2\nclick 80 208\nwait-s 0.5\nclick 138 208\nwait-s 4.5\n", 3000);
    ASSERT_GT(run.firstBlades, 0) << run.log;
    EXPECT_NE(run.log.find("stopped growing the field again after"), std::string::npos) << run.log;
    EXPECT_EQ(run.regrownBlades, 3 * run.firstBlades) << run.log;
    EXPECT_EQ(
        run.log.find("grew the field again: " + std::to_string(2 * run.firstBlades) + " blades"),
        std::string::npos)
        << run.log;
}

// The log of the editor run on `dir` (its script: 10 s of wall clock, `flags` added) while a
// shell beside it makes `changes` in order, each as soon as the log holds its line (then 1.5 s
// later, so that a slow start under load cannot read the changed file first): a command run in
// `dir`, as another program saving there would.
struct FileChange {
    std::string afterLine;
    std::string command;
};
std::string runWhileFilesChange(const std::filesystem::path& dir,
                                const std::vector<FileChange>& changes, const std::string& flags) {
    std::ofstream(dir / "script.txt") << "wait-s 10\n";
    const std::string d = dir.string();
    std::string inner = "(cd " + d + "; ";
    for (const FileChange& change : changes)
        inner += "n=0; until grep -q \"" + change.afterLine + "\" log.txt || [ $n -ge 60 ]; do " +
                 "sleep 0.25; n=$((n+1)); done; sleep 1.5; " + change.command + "; ";
    inner += ") & " + std::string(GRASS_EDITOR_EXE) + " " + d + " " + flags +
             " --wall-clock --script " + d + "/script.txt > " + d + "/log.txt 2>&1";
    const std::string command = "xvfb-run -a -s '-screen 0 1024x768x24' sh -c '" + inner + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream in(dir / "log.txt");
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Files of the project changed by another program while the editor plays: project.json saved
// from a text editor (density 20 → 40, and a density map named) is taken as an edit, and the
// field grows again with twice the blades; then that map saved again at half (as `grass paint`
// or an image editor saves one; copies prepared before, each moved into place as an editor
// saves) grows it again from the map, with about half. Before, the editor never looked at its
// files again once open.
TEST(EditorTime, FilesChangedByAnotherProgramAreFollowed) {
    const auto dir = scratchDir("editor_follow_files");
    writeTinyProject(dir, "tiny", 900, 560);
    std::filesystem::create_directories(dir / "maps");
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 1.0f), dir / "maps/d.png").ok());
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.5f), dir / "half.png").ok());
    auto edited = core::loadProject(dir);
    ASSERT_TRUE(edited.ok()) << edited.error().str();
    edited->project.layers.front().scatter.density *= 2.0f;
    edited->project.layers.front().densityMap = "maps/d.png";
    ASSERT_TRUE(core::saveProject(edited->project, dir / "edited.json").ok());
    const std::string log =
        runWhileFilesChange(dir,
                            {{"blades, geometry", "cp edited.json p.tmp && mv p.tmp project.json"},
                             {"grew the field again", "cp half.png m.tmp && mv m.tmp maps/d.png"}},
                            "--no-physics");
    const long first = bladesIn(log, ", ([0-9]+) blades, geometry ");
    std::vector<long> regrown;
    const std::regex grew("grew the field again: ([0-9]+) blades");
    for (auto it = std::sregex_iterator(log.begin(), log.end(), grew); it != std::sregex_iterator();
         ++it)
        regrown.push_back(std::stol((*it)[1]));
    ASSERT_GT(first, 0) << log;
    ASSERT_EQ(regrown.size(), 2u) << log;
    EXPECT_EQ(regrown[0], 2 * first) << log;
    EXPECT_GT(regrown[1], regrown[0] / 4) << log;
    EXPECT_LT(regrown[1], regrown[0] * 3 / 4) << "the half map: " << log;
}

// A mesh collider's file re-exported while the editor plays (a rock made a tall post in the
// modeller, moved into place as exporters save) is packed again on a worker and its prop made
// from the new mesh, while the field keeps its blades and their motion: the log says the
// packing of the new mesh (another share of it covered) and never that the field grew again.
// Before, the whole field grew again for it and its blades restarted from rest.
TEST(EditorTime, AMeshColliderChangedOnDiskIsPackedAgainWithoutTheFieldGrowing) {
    const auto dir = scratchDir("editor_follow_collider_file");
    writeTinyProject(dir, "tiny", 900, 560, /*windy=*/true);
    auto project = core::loadProject(dir);
    ASSERT_TRUE(project.ok()) << project.error().str();
    core::ColliderDesc rock;
    rock.name = "rock";
    rock.shape = core::ColliderShape::Mesh;
    rock.file = "rock.gltf";
    rock.sphereCount = 16;
    project->project.colliders = {rock};
    ASSERT_TRUE(core::saveProject(project->project, dir / "project.json").ok());
    writeGltf(dir / "rock.gltf",
              singleMeshAsset(boxPrimitive({-0.3f, 0.0f, -0.3f}, {0.3f, 0.4f, 0.3f})));
    writeGltf(dir / "post.gltf",
              singleMeshAsset(boxPrimitive({-0.1f, 0.0f, -0.1f}, {0.1f, 1.2f, 0.1f})));
    const std::string log = runWhileFilesChange(
        dir, {{"blades, geometry", "cp post.gltf r.tmp && mv r.tmp rock.gltf"}}, "");
    EXPECT_EQ(log.find("grew the field again"), std::string::npos) << log;
    EXPECT_NE(log.find("rock.gltf changed on disk: packing the collider again"), std::string::npos)
        << log;
    std::vector<std::string> covered;
    const std::regex packed(
        "note: collider rock: rock.gltf as .*, ([0-9.]+) % of the mesh covered");
    for (auto it = std::sregex_iterator(log.begin(), log.end(), packed);
         it != std::sregex_iterator(); ++it)
        covered.push_back((*it)[1]);
    ASSERT_EQ(covered.size(), 2u) << "packed when grown, and again: " << log;
    EXPECT_NE(covered[0], covered[1]) << "the new mesh was packed: " << log;
}

#ifdef GRASS_CLOSE_WINDOW_EXE
// The first project grows on a worker too (a large mesh takes seconds before the first frame):
// the window says what it is doing and its close button is answered meanwhile. Held back 60 s
// here (--load-delay-ms), the window is closed after 3 s, as a window manager's close button
// asks (close_window); the editor ends cleanly without growing anything. Before, the first
// field grew on the UI thread and the window could not be closed until it was done.
TEST(EditorTime, TheWindowClosesWhileTheFirstFieldGrows) {
    const auto dir = scratchDir("editor_close_while_opening");
    writeTinyProject(dir);
    const auto log = dir / "log.txt";
    const std::string inner = std::string(GRASS_EDITOR_EXE) + " " + dir.string() +
                              " --load-delay-ms 60000 > " + log.string() + " 2>&1 & pid=$!; " +
                              "sleep 3; " + GRASS_CLOSE_WINDOW_EXE + " grass || exit 3; " +
                              "wait $pid";
    const std::string command = "xvfb-run -a -s '-screen 0 1024x768x24' sh -c '" + inner + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(
        text.str().find("window closed while growing tiny (Opening editor_close_while_opening"),
        std::string::npos)
        << text.str();
    // The field was never brought up (that line follows it).
    EXPECT_EQ(text.str().find(" blades, geometry "), std::string::npos) << text.str();
}
#endif

}  // namespace
}  // namespace grass::test
