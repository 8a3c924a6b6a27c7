// The editor's panels driven as a user drives them (issue 7), with simulated input and no window:
// File → Save As… with a typed path writes the project elsewhere and takes its files along;
// Quit with unsaved changes asks first. (In grass_gl_tests because the panels link the renderer's
// options; no GL context is used.)
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <variant>

#include "app/autosave.h"
#include "app/edit_actions.h"
#include "app/editor_keys.h"
#include "app/mesh_import.h"
#include "app/panels.h"
#include "app/project_file_watch.h"
#include "app/viewport_tools.h"
#include "app/worker_job.h"
#include "maps/map_image.h"
#include "panel_driver.h"
#include "physics/wind.h"
#include "quality/quality_presets.h"
#include "scene/scene_physics.h"
#include "scene/scene_props.h"
#include "support/scratch_folder.h"
#include "support/test_fonts.h"
#include "support/test_paths.h"
#include "ui/font.h"
#include "ui/number_text.h"
#include "util/atomic_file.h"
#include "util/version.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;

// The editor on a copy of the tiny growth project with a soil map, in `folder`.
struct EditorDriver {
    explicit EditorDriver(const fs::path& folder) : ctx(testFonts()) {
        fs::copy_file(sourceDir() / "tests/data/projects/growth_tiny/project.json",
                      folder / "project.json");
        fs::create_directories(folder / "maps");
        EXPECT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.5f), folder / "maps/soil.png")
                        .ok());
        auto loaded = core::loadProject(folder);
        EXPECT_TRUE(loaded.ok()) << loaded.error().str();
        loaded->project.layers.front().soilMap = "maps/soil.png";
        auto built = core::buildScene(*loaded);
        EXPECT_TRUE(built.ok()) << built.error().str();
        scene = std::move(*built);
        state.doc.loaded = std::move(*loaded);
        state.scene = &scene;
        state.doc.dirty = true;  // the soil map was just added
        input.screenRect = {{0.0f, 0.0f}, {1280.0f, 720.0f}};
        input.hasPointer = true;
        input.pointerPos = {1000.0f, 700.0f};
    }

    // No history step each frame: a test records one where it wants it (recordProjectEdit).
    const ui::Output& frame() { return panelFrame(ctx, input, state, false); }

    // Every text drawn in the next frame.
    std::set<std::string> shownTexts() {
        std::set<std::string> shown;
        for (const ui::ClippedShape& shape : frame().shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape))
                shown.insert(t->text);
        return shown;
    }

    // File › `item`, which opens the file browser.
    void browseFrom(std::string_view item) {
        click("File");
        click(item);
        ASSERT_TRUE(state.transient.browser.has_value()) << item << " opened no browser";
    }

    // Clicks the topmost text shape reading exactly `text` (hover, press, release).
    void click(std::string_view text) {
        clickWhere([&](std::string_view shown) { return shown == text; }, text);
    }
    // The topmost text shape starting with `prefix` (a file list's row: name, then its size).
    void clickStartingWith(std::string_view prefix, bool twice = false) {
        clickWhere([&](std::string_view shown) { return shown.starts_with(prefix); }, prefix, twice);
    }
    void clickWhere(const std::function<bool(std::string_view)>& matches, std::string_view what,
                    bool twice = false) {
        std::optional<ui::Vec2> at;
        const ui::Output& out = frame();
        for (const ui::ClippedShape& shape : out.shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && matches(t->text))
                at = t->pos + ui::Vec2(3.0f, 6.0f);
        ASSERT_TRUE(at.has_value()) << "nothing reads \"" << what << "\"";
        clickAt(*at);
        if (twice)
            clickAt(*at);
    }
    void clickAt(ui::Vec2 at) {
        input.pointerPos = at;
        frame();
        input.buttonDown[0] = true;
        frame();
        input.buttonDown[0] = false;
        frame();
    }
    // Types `text` into the browser's path field (right of its label), replacing what it held,
    // and presses Enter.
    void typePathAndEnter(const std::string& text, std::string_view fieldLabel = "Name or path:") {
        std::optional<ui::Vec2> label;
        for (const ui::ClippedShape& shape : frame().shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == fieldLabel)
                label = t->pos;
        ASSERT_TRUE(label.has_value()) << "no path field";
        clickAt(*label + ui::Vec2(150.0f, 6.0f));
        input.keys.push_back({ui::Key::A, {false, true, false}});
        frame();
        input.text = text;
        frame();
        input.keys.push_back({ui::Key::Enter, {}});
        frame();
    }

    // Drags the value box of the row whose label starts at `label` (the box sits left of it) 40
    // points to the right, a frame per 10 points.
    void dragRightOfLabel(ui::Vec2 label) {
        input.pointerPos = label + ui::Vec2(-20.0f, 6.0f);
        frame();
        input.buttonDown[0] = true;
        frame();
        for (int i = 0; i < 4; ++i) {
            input.pointerPos.x += 10.0f;
            frame();
        }
        input.buttonDown[0] = false;
        frame();
    }

    ui::Context ctx;
    ui::Input input;
    core::Scene scene;
    editor::EditorState state;
};

TEST(EditorPanels, SaveAsTypedPathWritesTheProjectAndItsFilesThere) {
    const ScratchFolder from("editor-save-as-from"), to("editor-save-as-to");
    EditorDriver editor(from.path());
    editor.click("File");
    editor.click("Save As…");
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.transient.browser->purpose(), editor::BrowsePurpose::SaveProject);
    // The path field shows the project's folder name: replace it with the new folder.
    EXPECT_EQ(editor.state.transient.browser->typed(), from.path().filename().string());
    editor.typePathAndEnter((to.path() / "copy").string(), "Project folder:");

    const fs::path saved = to.path() / "copy" / "project.json";
    ASSERT_TRUE(fs::exists(saved)) << editor.state.transient.message;
    EXPECT_FALSE(editor.state.doc.dirty);
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.doc.loaded.file, saved);
    // The copy loads and grows on its own: its map came along.
    EXPECT_TRUE(fs::exists(to.path() / "copy/maps/soil.png"));
    auto reloaded = core::loadProject(saved);
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().str();
    EXPECT_EQ(reloaded->project, editor.state.doc.loaded.project);
    auto grown = core::buildScene(*reloaded);
    EXPECT_TRUE(grown.ok()) << grown.error().str();
}

// Issue 22: a failed save stays on screen; the autosave that follows a few minutes later must
// not replace its message with "autosaved to …" (the user would think the work is saved).
TEST(EditorPanels, AFailedSaveStaysInTheStatusBarUntilASaveSucceeds) {
    const ScratchFolder folder("editor-failed-save");
    EditorDriver editor(folder.path());
    fs::create_directories(folder.path() / "blocked" / "project.json");  // a folder in the way
    EXPECT_FALSE(editor::saveTo(editor.state, (folder.path() / "blocked/project.json").string()));
    const std::string failed = editor.state.transient.message;
    ASSERT_EQ(failed.rfind("not saved: ", 0), 0u) << failed;
    EXPECT_NE(failed.find("Save As"), std::string::npos) << failed << ": the way out";
    EXPECT_TRUE(editor.state.transient.messageIsSaveError);
    editor::autosaveNow(editor.state);
    EXPECT_EQ(editor.state.transient.message, failed);
    EXPECT_TRUE(fs::exists(editor::autosavePath(editor.state.doc.loaded)));  // the work is kept
    ASSERT_TRUE(editor::saveTo(editor.state, (folder.path() / "project.json").string()));
    EXPECT_FALSE(editor.state.transient.messageIsSaveError);
    editor.state.doc.dirty = true;
    editor::autosaveNow(editor.state);
    EXPECT_EQ(editor.state.transient.message.rfind("autosaved to ", 0), 0u) << editor.state.transient.message;
}

// A project file another program changed since it was opened here (a text editor, a second
// editor window, a checkout) is not replaced by Save without asking: before, Ctrl+S wrote over
// it and that work was gone. Replace it, Save As… or Cancel.
TEST(EditorPanels, ASaveAsksBeforeReplacingAProjectFileChangedOnDisk) {
    const ScratchFolder folder("editor-changed-on-disk");
    EditorDriver editor(folder.path());
    const fs::path file = folder.path() / "project.json";
    const auto text = [&] {
        auto bytes = readFile(file);
        return bytes.ok() ? *bytes : std::string();
    };
    ASSERT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    // Another program renames the project in the file.
    auto theirs = core::loadProject(file);
    ASSERT_TRUE(theirs.ok());
    theirs->project.name = "theirs";
    ASSERT_TRUE(core::saveProject(theirs->project, file).ok());
    const std::string theirText = text();
    editor.state.doc.loaded.project.name = "mine";
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    EXPECT_EQ(text(), theirText) << "replaced without asking";
    EXPECT_TRUE(editor.state.transient.changedOnDisk);
    EXPECT_NE(editor.state.transient.message.find("changed by another program"), std::string::npos)
        << editor.state.transient.message;
    // Cancel keeps both; a second Save asks again.
    editor.click("Cancel");
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    EXPECT_EQ(text(), theirText);
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    editor.click("Replace it");
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    auto saved = core::loadProject(file);
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved->project.name, "mine");
    EXPECT_FALSE(editor.state.doc.dirty);
    // The editor's own save is not a change by another program; a file gone has nothing to lose.
    editor.state.doc.loaded.project.name = "mine again";
    EXPECT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    fs::remove(file);
    EXPECT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    // Save As… from the window: the changed file stays, the browser asks where.
    theirs->project.name = "theirs again";
    ASSERT_TRUE(core::saveProject(theirs->project, file).ok());
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    editor.click("Save As…");
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.transient.browser->purpose(), editor::BrowsePurpose::SaveProject);
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    EXPECT_EQ(core::loadProject(file)->project.name, "theirs again");
    // Quitting with unsaved changes: "Save and quit" asks too, and replacing the file quits.
    editor.state.transient.browser.reset();
    editor.state.doc.dirty = true;
    editor::askQuit(editor.state);
    ASSERT_TRUE(editor.state.transient.quitDialog);
    editor.click("Save and quit");
    EXPECT_TRUE(editor.state.transient.changedOnDisk);
    EXPECT_FALSE(editor.state.quitRequested);
    editor.click("Replace it");
    EXPECT_TRUE(editor.state.quitRequested);
    EXPECT_EQ(core::loadProject(file)->project.name, "mine again");
}

// "Take the file's" in the Changed on disk window: the other program's project wins as one
// undoable edit, and Ctrl+Z brings back the changes made here (before, the only way was to open
// the project again, losing them).
TEST(EditorPanels, TheChangedFileCanBeTakenInsteadAndUndone) {
    const ScratchFolder folder("editor-take-the-files");
    EditorDriver editor(folder.path());
    const fs::path file = folder.path() / "project.json";
    ASSERT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    auto theirs = core::loadProject(file);
    ASSERT_TRUE(theirs.ok());
    theirs->project.name = "theirs";
    ASSERT_TRUE(core::saveProject(theirs->project, file).ok());
    editor::apply(editor.state, editor::EditProject{.after =
                                                        [&] {
                                                            core::Project mine =
                                                                editor.state.doc.project();
                                                            mine.name = "mine";
                                                            return mine;
                                                        }(),
                                                    .effect = editor::EditEffect::Live,
                                                    .label = "rename"});
    ASSERT_TRUE(editor.state.doc.dirty);
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    ASSERT_TRUE(editor.state.transient.changedOnDisk);
    editor.click("Take the file's");
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    EXPECT_EQ(editor.state.doc.project().name, "theirs");
    EXPECT_FALSE(editor.state.doc.dirty) << "the document is the file";
    EXPECT_TRUE(editor::saveTo(editor.state, file.string())) << "nothing to ask any more";
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(editor.state.doc.project().name, "mine");
    EXPECT_TRUE(editor.state.doc.dirty);
    // A map alone changed elsewhere offers no such choice (the project file is the editor's).
    editor.state.transient.changedOnDisk = false;
    ASSERT_TRUE(editor::saveTo(editor.state, file.string()));
    const fs::path soil = folder.path() / "maps/soil.png";
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.9f), soil).ok());
    editor.state.doc.loaded.project.layers.front().soilMap = "maps/soil.png";
    ASSERT_TRUE(editor::saveTo(editor.state, file.string()));
    // The editor's look stamps the map as it is.
    editor::followProjectFileOnDisk(editor.state, 10.0, false);
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.2f), soil).ok());
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    EXPECT_TRUE(editor.state.transient.changedOnDisk);
    EXPECT_FALSE(editor.state.transient.changedOnDiskProjectFile);
}

// The first text of a frame starting with `prefix` (the status bar's figures: "N blades · …").
std::optional<ui::TextShape> textStarting(const ui::Output& out, std::string_view prefix) {
    for (const ui::ClippedShape& shape : out.shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape);
            t && t->text.starts_with(prefix))
            return *t;
    return std::nullopt;
}

// The project's files looked at as the Editor looks at them, a look a second.
struct WatchLooks {
    editor::EditorState& state;
    double nowS = 0.0;
    bool operator()() {
        nowS += editor::PROJECT_FILE_LOOK_S;
        return editor::followProjectFileOnDisk(state, nowS, false);
    }
};

// The project's file edited in a text editor while the editor has it open: the change is taken
// as one undoable edit once the file loads, the document counting as saved; with unsaved changes
// here it is said and left (Save then asks). Before, the editor never looked at the file again.
TEST(EditorPanels, AProjectFileEditedElsewhereIsTakenAsAnEdit) {
    const ScratchFolder folder("editor-file-watch");
    EditorDriver editor(folder.path());
    const fs::path file = folder.path() / "project.json";
    ASSERT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    WatchLooks look{editor.state};
    EXPECT_FALSE(look()) << "the editor's own save is no change";
    auto edited = core::loadProject(file);
    ASSERT_TRUE(edited.ok());
    const float density = edited->project.layers.front().scatter.density;
    edited->project.layers.front().scatter.density = density + 5.0f;
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    // Not while an edit is under way here (a drag, a text entry): taken when it ends.
    EXPECT_FALSE(editor::followProjectFileOnDisk(editor.state, look.nowS + 5.0, true));
    ASSERT_TRUE(look()) << editor.state.transient.message;
    EXPECT_EQ(editor.state.doc.project().layers.front().scatter.density, density + 5.0f);
    EXPECT_TRUE(editor.state.rebuildPending) << "the field grows again for it";
    EXPECT_FALSE(editor.state.doc.dirty) << "the document is the file";
    EXPECT_NE(editor.state.transient.message.find("on disk"), std::string::npos);
    EXPECT_FALSE(look()) << "taken once";
    // A Save after it replaces nothing of the other program's.
    EXPECT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    // Ctrl+Z goes back to the project before, which is now unsaved.
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(editor.state.doc.project().layers.front().scatter.density, density);
    EXPECT_TRUE(editor.state.doc.dirty);
    // With unsaved changes here the file is said, not taken, and Save asks before replacing it.
    edited->project.name = "renamed elsewhere";
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    EXPECT_FALSE(look());
    EXPECT_NE(editor.state.doc.project().name, "renamed elsewhere");
    EXPECT_NE(editor.state.transient.message.find("unsaved changes here are kept"),
              std::string::npos)
        << editor.state.transient.message;
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    EXPECT_TRUE(editor.state.transient.changedOnDisk);
    editor.state.transient.changedOnDisk = false;
    // Back to no unsaved changes (redo): the file is taken.
    ASSERT_TRUE(editor::redo(editor.state));
    ASSERT_FALSE(editor.state.doc.dirty);
    EXPECT_TRUE(look());
    EXPECT_EQ(editor.state.doc.project().name, "renamed elsewhere");
    // A file that does not load (half typed) is said with its error and taken once it loads.
    { std::ofstream(file) << "{\"format\": \"grass-project\", "; }
    EXPECT_FALSE(look());
    EXPECT_NE(editor.state.transient.message.find("does not load"), std::string::npos)
        << editor.state.transient.message;
    // In warning orange, as something to fix there; the routine message after it is not.
    const ui::Color32 orange = ui::Color32::rgb(255, 150, 60);
    const std::optional<ui::TextShape> broken =
        textStarting(editor.frame(), "project.json was changed on disk but");
    ASSERT_TRUE(broken);
    EXPECT_EQ(broken->color, orange);
    editor.state.transient.message = "autosaved";
    const std::optional<ui::TextShape> routine = textStarting(editor.frame(), "autosaved");
    ASSERT_TRUE(routine);
    EXPECT_NE(routine->color, orange);
    EXPECT_EQ(editor.state.doc.project().name, "renamed elsewhere");
    edited->project.name = "fixed";
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    EXPECT_TRUE(look());
    EXPECT_EQ(editor.state.doc.project().name, "fixed");
}

// A map changed on disk (painted in another program, written by `grass paint`) grows the field
// again from it, and a surface re-exported from a modeller is read again; unsaved painting of
// that map here is kept and said; the maps a Save writes are not changes by another program.
TEST(EditorPanels, AMapOrSurfaceChangedOnDiskGrowsTheFieldAgainUnlessPaintedHere) {
    const ScratchFolder folder("editor-asset-watch");
    EditorDriver editor(folder.path());
    fs::copy_file(sourceDir() / "tests/data/gltf/cube.glb", folder.path() / "ground.glb");
    editor.state.doc.loaded.project.mesh.isFile = true;
    editor.state.doc.loaded.project.mesh.file = "ground.glb";
    const fs::path file = folder.path() / "project.json";
    ASSERT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    WatchLooks look{editor.state};
    editor.state.regrowFromDisk = false;
    EXPECT_FALSE(look()) << "first seen: stamped only";
    const fs::path soil = folder.path() / "maps/soil.png";
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.9f), soil).ok());
    EXPECT_TRUE(look());
    EXPECT_TRUE(editor.state.regrowFromDisk);
    EXPECT_FALSE(editor.state.surfaceChangedOnDisk);
    EXPECT_NE(editor.state.transient.message.find("maps/soil.png"), std::string::npos)
        << editor.state.transient.message;
    EXPECT_FALSE(editor.state.doc.dirty) << "the file is the project's already";
    editor.state.regrowFromDisk = false;
    EXPECT_FALSE(look()) << "taken once";
    // The surface re-exported: read again by the re-grow, not taken from the mesh at hand.
    fs::copy_file(sourceDir() / "tests/data/gltf/box_meshopt.glb", folder.path() / "ground.glb",
                  fs::copy_options::overwrite_existing);
    EXPECT_TRUE(look());
    EXPECT_TRUE(editor.state.regrowFromDisk);
    EXPECT_TRUE(editor.state.surfaceChangedOnDisk);
    editor.state.regrowFromDisk = editor.state.surfaceChangedOnDisk = false;
    // Painting here not saved: kept and said, once.
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.2f), soil).ok());
    EXPECT_FALSE(look());
    EXPECT_FALSE(editor.state.regrowFromDisk);
    EXPECT_NE(editor.state.transient.message.find("painting here is kept"), std::string::npos)
        << editor.state.transient.message;
    editor.state.transient.message = "later";
    EXPECT_FALSE(look());
    EXPECT_EQ(editor.state.transient.message, "later") << "said once";
    // A Save asks before writing the painting over the other program's map, naming it...
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    EXPECT_TRUE(editor.state.transient.changedOnDisk);
    EXPECT_NE(editor.state.transient.message.find("soil.png was changed by another program"),
              std::string::npos)
        << editor.state.transient.message;
    const auto soilNow = core::loadMapImage(soil);
    ASSERT_TRUE(soilNow.ok());
    EXPECT_NEAR(soilNow->sample({0.5f, 0.5f}), 0.2f, 0.01f) << "the other program's map stays";
    // Replace it (the window's first button): the painting is written, its own write no change.
    ASSERT_TRUE(editor::saveTo(editor.state, file.string(), true))
        << editor.state.transient.message;
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    EXPECT_FALSE(look());
    EXPECT_FALSE(editor.state.regrowFromDisk);
    // A map written elsewhere in the second before the Save, before the watch looked: asked too.
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.4f), soil).ok());
    EXPECT_FALSE(editor::saveTo(editor.state, file.string()));
    EXPECT_TRUE(editor.state.transient.changedOnDisk);
    ASSERT_TRUE(editor::saveTo(editor.state, file.string(), true));
    // A second Save at once finds the painting it wrote: nothing to ask.
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    EXPECT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    EXPECT_FALSE(look());
    // A map that project.json, edited elsewhere, names anew is the file the re-grow reads: saved
    // again right after, that is a change too (stamped when the edit is taken, not a look later).
    const fs::path light = folder.path() / "maps/light.png";
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.6f), light).ok());
    auto edited = core::loadProject(file);
    ASSERT_TRUE(edited.ok());
    edited->project.layers.front().lightMap = "maps/light.png";
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    ASSERT_TRUE(look()) << editor.state.transient.message;
    editor.state.regrowFromDisk = false;
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.3f), light).ok());
    EXPECT_TRUE(look());
    EXPECT_TRUE(editor.state.regrowFromDisk);
    // The billboards' texture repainted: grown again too (buildScene reads it), on the same
    // surface.
    editor.state.regrowFromDisk = editor.state.surfaceChangedOnDisk = false;
    const fs::path texture = folder.path() / "tuft.png";
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.5f), texture).ok());
    edited->project.billboards.texture = "tuft.png";
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    ASSERT_TRUE(look());
    editor.state.regrowFromDisk = false;
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.8f), texture).ok());
    EXPECT_TRUE(look());
    EXPECT_TRUE(editor.state.regrowFromDisk);
    EXPECT_FALSE(editor.state.surfaceChangedOnDisk);
    // A mesh collider's file re-exported: packed again and its prop read again, the field
    // keeping its blades (Editor::followMotionEdits), where a layer's placement clears the
    // ground under the colliders too (the patches around them grow again then); with a map
    // changed beside it, the field grows again.
    editor.state.regrowFromDisk = false;
    // The rock's file exported again from the modeller as `source`.
    const auto reexportRock = [&](const char* source) {
        fs::copy_file(sourceDir() / "tests/data/gltf" / source, folder.path() / "rock.glb",
                      fs::copy_options::overwrite_existing);
    };
    reexportRock("cube.glb");
    // Two rocks of one file, as projects/winter has.
    core::ColliderDesc rock;
    rock.shape = core::ColliderShape::Mesh;
    rock.file = "rock.glb";
    rock.name = "big rock";
    edited->project.colliders.push_back(rock);
    rock.name = "small rock";
    rock.position.x = 1.0f;
    edited->project.colliders.push_back(rock);
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    ASSERT_TRUE(look());
    editor.state.regrowFromDisk = false;
    reexportRock("box_meshopt.glb");
    EXPECT_TRUE(look());
    EXPECT_FALSE(editor.state.regrowFromDisk);
    EXPECT_EQ(editor.state.colliderFilesChangedOnDisk, std::set<std::string>{"rock.glb"});
    EXPECT_NE(editor.state.transient.message.find("rock.glb changed on disk: packing"),
              std::string::npos)
        << editor.state.transient.message;
    editor.state.colliderFilesChangedOnDisk.clear();
    edited->project.layers.front().rules.clearColliders = true;
    ASSERT_TRUE(core::saveProject(edited->project, file).ok());
    ASSERT_TRUE(look());
    editor.state.regrowFromDisk = false;
    reexportRock("cube.glb");
    EXPECT_TRUE(look());
    EXPECT_FALSE(editor.state.regrowFromDisk);
    EXPECT_EQ(editor.state.colliderFilesChangedOnDisk, std::set<std::string>{"rock.glb"});
    editor.state.colliderFilesChangedOnDisk.clear();
    reexportRock("box_meshopt.glb");
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.35f), light).ok());
    EXPECT_TRUE(look());
    EXPECT_TRUE(editor.state.regrowFromDisk);
    EXPECT_TRUE(editor.state.colliderFilesChangedOnDisk.empty());
    EXPECT_FALSE(editor.state.surfaceChangedOnDisk);
    EXPECT_NE(editor.state.transient.message.find("growing the field again from"),
              std::string::npos)
        << editor.state.transient.message;
    // A painted map changed elsewhere does not hold up a save into another folder: the painting
    // goes to new files there.
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.7f), soil).ok());
    ASSERT_FALSE(editor::paintedMapsChangedOnDisk(editor.state).empty());
    EXPECT_TRUE(editor::saveTo(editor.state, (folder.path() / "copy/project.json").string()))
        << editor.state.transient.message;
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
}

// A project opened again (or another one opened) is grown from its files as they are: the
// stamps the watch took of them before are not compared with them. Before, a map changed while
// another project was open was taken for a change at the first look after opening it again,
// and the field just grown was grown again.
TEST(EditorPanels, AProjectOpenedAgainIsNotTakenForAChangeOnDisk) {
    const ScratchFolder folder("editor-watch-reopen");
    EditorDriver editor(folder.path());
    const fs::path soil = folder.path() / "maps/soil.png";
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.9f), soil).ok());
    editor.state.doc.loaded.project.layers.front().soilMap = "maps/soil.png";
    const fs::path file = folder.path() / "project.json";
    ASSERT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    WatchLooks look{editor.state};
    EXPECT_FALSE(look());
    EXPECT_FALSE(look()) << "stamped";
    // Changed while another project was open; then this one opened again (resetHistory is what
    // every open, new and recovery does once its field is up).
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.3f), soil).ok());
    editor::resetHistory(editor.state);
    editor.state.regrowFromDisk = false;
    EXPECT_FALSE(look());
    EXPECT_FALSE(editor.state.regrowFromDisk);
    // Changes after the opening are followed as ever.
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.5f), soil).ok());
    EXPECT_TRUE(look());
    EXPECT_TRUE(editor.state.regrowFromDisk);
}

// A map file two layers read (a duplicated layer's) is not written over by a Save: the painting
// goes to the painted layer's own file. A change to the shared file is then nothing to ask about.
TEST(EditorPanels, ASharedMapChangedOnDiskIsNotAskedAbout) {
    const ScratchFolder folder("editor-watch-shared-map");
    EditorDriver editor(folder.path());
    const fs::path soil = folder.path() / "maps/soil.png";
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.9f), soil).ok());
    core::Project& project = editor.state.doc.loaded.project;
    project.layers.front().soilMap = "maps/soil.png";
    project.layers.push_back(project.layers.front());
    project.layers.back().name = "second";
    const fs::path file = folder.path() / "project.json";
    ASSERT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    WatchLooks look{editor.state};
    EXPECT_FALSE(look());
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    ASSERT_TRUE(core::saveMapImage(core::makeConstantMap(8, 8, 0.3f), soil).ok());
    EXPECT_TRUE(editor::paintedMapsChangedOnDisk(editor.state).empty());
    EXPECT_TRUE(editor::saveTo(editor.state, file.string())) << editor.state.transient.message;
    EXPECT_FALSE(editor.state.transient.changedOnDisk);
    const auto kept = core::loadMapImage(soil);
    ASSERT_TRUE(kept.ok());
    EXPECT_NEAR(kept->sample({0.5f, 0.5f}), 0.3f, 0.01f)
        << "the shared file is the other program's";
}

TEST(EditorPanels, OpenTypedPathAsksTheEditorToLoadIt) {
    const ScratchFolder folder("editor-open");
    EditorDriver editor(folder.path());
    ASSERT_NO_FATAL_FAILURE(editor.browseFrom("Open…"));
    EXPECT_EQ(editor.state.transient.browser->purpose(), editor::BrowsePurpose::OpenProject);
    const fs::path meadow = sourceDir() / "projects/meadow";
    editor.typePathAndEnter(meadow.string());
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    // The project has unsaved changes: nothing is replaced before the user says so.
    EXPECT_TRUE(editor.state.openRequested.empty());
    ASSERT_TRUE(editor.state.transient.quitDialog);
    editor.click("Discard changes");
    EXPECT_EQ(editor.state.openRequested, meadow.lexically_normal().string());
    EXPECT_TRUE(editor.state.doc.dirty) << "if the open fails, the edits still count as unsaved";
}

// Typing in the file browser while no field has the keyboard (after a click in its list) types
// a new name into its field: under Xvfb at the editor's 1–2 fps the keys of "maps/ctc24.tga" went
// to the viewport's shortcuts behind the window instead (the gizmo, a cull test, the technique).
TEST(EditorPanels, TypingInTheBrowserWithNoFieldFocusedTypesAName) {
    const ScratchFolder folder("editor-browser-typing");
    EditorDriver editor(folder.path());
    ASSERT_NO_FATAL_FAILURE(editor.browseFrom("Import map image…"));
    editor.state.transient.browser->enter(folder.path());
    editor.clickStartingWith("maps/");
    ASSERT_EQ(editor.ctx.focusedId().value, 0u) << "the click in the list left a field focused";
    editor.input.text = "maps/soil.png";
    EXPECT_TRUE(editor.frame().wantsKeyboard) << "the keys would reach the viewport";
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.transient.browser->typed(), "maps/soil.png");
    editor.input.keys.push_back({ui::Key::Enter, {}});
    editor.frame();
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    EXPECT_EQ(fs::path(editor.state.importMapRequested), folder.path() / "maps/soil.png");
}

// Issue 26 item 1: File › Import mesh… browses to a mesh; a double-click on it in the list asks
// the Editor to import it (the list shows folders and glTF files only).
TEST(EditorPanels, ImportMeshByDoubleClickInTheBrowser) {
    const ScratchFolder folder("editor-import-mesh");
    EditorDriver editor(folder.path());
    editor.state.transient.meshFolder = sourceDir() / "tests/data/gltf";
    editor.click("File");
    editor.click("Import mesh…");
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.transient.browser->folder(), sourceDir() / "tests/data/gltf");
    for (const auto& entry : editor.state.transient.browser->listing().entries)
        EXPECT_TRUE(entry.isFolder || entry.name.ends_with(".glb") || entry.name.ends_with(".gltf"))
            << entry.name;
    editor.clickStartingWith("cube.glb", true);
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.importMeshRequested, (sourceDir() / "tests/data/gltf/cube.glb").string());
}

// Colliders › add mesh…: a glTF becomes a mesh collider, copied into the project's folder, one
// undo step that grows the field again (its spheres are packed then). Before 2026-12-07 a mesh
// collider could be made only by writing project.json by hand.
TEST(EditorPanels, AMeshColliderIsAddedFromItsFileAndCopiedIntoTheProject) {
    const ScratchFolder folder("editor-add-mesh-collider");
    EditorDriver editor(folder.path());
    editor::resetHistory(editor.state);
    const core::Project& project = editor.state.doc.loaded.project;
    editor.state.transient.meshFolder = sourceDir() / "tests/data/gltf";
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Colliders (0)");
    editor.click("add mesh…");
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor::browseTitle(editor.state.transient.browser->purpose()), "Add mesh collider");
    editor.clickStartingWith("cube.glb", true);
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    // The browser asks the Editor, which reads and copies the file on a worker and then adds
    // it (EditorMotion.AMeshColliderAddedIsPackedWithoutGrowingTheField runs that); here the
    // same three halves run at once.
    const std::string chosen = std::exchange(editor.state.addColliderRequested, {});
    EXPECT_EQ(fs::path(chosen).filename(), "cube.glb");
    EXPECT_TRUE(project.colliders.empty()) << "added on the window's thread";
    ASSERT_TRUE(editor::addMeshCollider(editor.state, chosen));
    ASSERT_EQ(project.colliders.size(), 1u) << editor.state.transient.message;
    const core::ColliderDesc& cube = project.colliders[0];
    EXPECT_EQ(cube.shape, core::ColliderShape::Mesh);
    EXPECT_EQ(cube.name, "cube");
    EXPECT_EQ(cube.file, "meshes/cube/cube.glb");
    EXPECT_TRUE(fs::is_regular_file(folder.path() / cube.file));
    EXPECT_TRUE(editor.state.rebuildPending) << "its spheres are packed as the field grows";
    ASSERT_TRUE(editor.state.view.place.selected.has_value());
    EXPECT_EQ(editor.state.view.place.selected->index, 0u);
    EXPECT_EQ(editor.state.doc.history.nextUndo()->label, "add collider cube");
    // Its box's centre stands where a new ball would, above the scene's centre, at its own
    // size (a 1 m cube on a 2 m plane: within a hundredth and half of the scene's diagonal).
    auto read = core::readColliderMesh(project, folder.path() / cube.file);
    ASSERT_TRUE(read.ok()) << read.error().str();
    const glm::vec3 centre = cube.position + cube.scale * core::meshBounds(read->mesh).centre();
    const glm::vec3 wanted = editor::newObjectPosition(editor.state);
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_NEAR(centre[axis], wanted[axis], 1e-5f) << axis;
    EXPECT_EQ(cube.scale, 1.0f);

    // The project as saved builds its physics and props from the copy: packed, drawn.
    auto physics = core::buildScenePhysics(editor.state.doc.loaded);
    ASSERT_TRUE(physics.ok()) << physics.error().str();
    EXPECT_FALSE(physics->colliders.empty());
    auto props = core::loadSceneProps(editor.state.doc.loaded);
    ASSERT_TRUE(props.ok()) << props.error().str();
    EXPECT_EQ(props->size(), 1u);

    // The same file again: another name, the same copy (not copied twice).
    ASSERT_TRUE(editor::addMeshCollider(editor.state, sourceDir() / "tests/data/gltf/cube.glb"));
    ASSERT_EQ(project.colliders.size(), 2u);
    EXPECT_EQ(project.colliders[1].name, "cube 2");
    EXPECT_EQ(project.colliders[1].file, "meshes/cube/cube.glb");
    EXPECT_FALSE(fs::exists(folder.path() / "meshes/cube-2"));
    EXPECT_NE(editor.state.transient.message.find("uses its copy in"), std::string::npos)
        << editor.state.transient.message;
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(project.colliders.size(), 1u);

    // Refused: the file of tests/data/gltf added, the reason must say `why`; nothing changes.
    const auto expectRefused = [&](const char* file, const char* why) {
        const auto added =
            editor::addMeshCollider(editor.state, sourceDir() / "tests/data/gltf" / file);
        ASSERT_FALSE(added.ok()) << file;
        EXPECT_NE(added.error().str().find(why), std::string::npos) << added.error().str();
        EXPECT_EQ(project.colliders.size(), 1u) << file;
    };
    // A broken file changes nothing, copies nothing, and says which file and why.
    expectRefused("truncated.gltf", "truncated.gltf");
    EXPECT_FALSE(fs::exists(folder.path() / "meshes/truncated"));
    // A mesh far out in a georeferenced frame the (procedural) ground does not share: its
    // positions are too coarse there to draw or pack, refused with where it lies.
    expectRefused("far_quad.gltf", "5437 km from the scene's origin");
    // A project never saved has no folder to keep the mesh in: saved first.
    editor.state.doc.loaded.folder.clear();
    expectRefused("cube.glb", "save the project first");
}

// Colliders › add mesh… in the halves the Editor runs: the request taken on the window, the
// file read and copied on a worker (WorkerJob), the collider added once it is in, named among
// the colliders of that moment (a cube added meanwhile makes it "cube 2"), with its mesh as read
// for the prop.
TEST(EditorPanels, AMeshColliderReadOnAWorkerIsNamedWhenItIsAdded) {
    const ScratchFolder folder("editor-add-mesh-collider-worker");
    EditorDriver editor(folder.path());
    const fs::path cube = sourceDir() / "tests/data/gltf/cube.glb";
    auto request = editor::colliderImportRequest(editor.state, cube);
    ASSERT_TRUE(request.ok()) << request.error().str();
    bool woken = false;
    editor::WorkerJob<Result<editor::ImportedCollider>> job(
        [request = *request] { return editor::importColliderMesh(request); },
        [&woken] { woken = true; });
    auto imported = job.take();
    // Another cube added on the window once the file is read, before the read one is added
    // (after the worker's copy: two copies made at once into one folder would race).
    ASSERT_TRUE(editor::addMeshCollider(editor.state, cube));
    EXPECT_TRUE(job.done());
    EXPECT_TRUE(woken) << "the window is not woken when the mesh is in";
    ASSERT_TRUE(imported.ok()) << imported.error().str();
    EXPECT_GT(imported->mesh->n_faces(), 0u);
    EXPECT_EQ(editor::addImportedCollider(editor.state, std::move(*imported)),
              "meshes/cube/cube.glb");
    const auto& colliders = editor.state.doc.project().colliders;
    ASSERT_EQ(colliders.size(), 2u);
    EXPECT_EQ(colliders[0].name, "cube");
    EXPECT_EQ(colliders[1].name, "cube 2");
    EXPECT_EQ(colliders[1].position, colliders[0].position);
    ASSERT_TRUE(editor.state.view.place.selected.has_value());
    EXPECT_EQ(editor.state.view.place.selected->index, 1u);
}

// Issue 26 item 1: File › New from mesh… asks first about unsaved changes, then asks the Editor
// for a project around the typed mesh; a typed path of the wrong kind stays with its reason.
TEST(EditorPanels, NewFromMeshAsksFirstAndRefusesTheWrongKindOfFile) {
    const ScratchFolder folder("editor-new-from-mesh");
    EditorDriver editor(folder.path());
    editor.click("File");
    editor.click("New from mesh…");
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    editor.typePathAndEnter((sourceDir() / "tests/data/projects/textured_stone/stone.png").string());
    ASSERT_TRUE(editor.state.transient.browser.has_value()) << "a picture is not a mesh";
    const std::set<std::string> shown = editor.shownTexts();
    EXPECT_TRUE(shown.count("stone.png is not one of glTF (.gltf .glb)"));
    const fs::path stone = sourceDir() / "tests/data/projects/textured_stone/stone.gltf";
    editor.typePathAndEnter(stone.string());
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    ASSERT_TRUE(editor.state.transient.quitDialog);
    editor.click("Discard changes");
    EXPECT_EQ(editor.state.newFromMeshRequested, stone.lexically_normal().string());
}

// Issue 26 item 1: File › Open Recent lists the projects opened last; a click opens one.
TEST(EditorPanels, OpenRecentListsTheLastProjects) {
    const ScratchFolder folder("editor-recent");
    EditorDriver editor(folder.path());
    editor.state.doc.dirty = false;
    const fs::path meadow = sourceDir() / "projects/meadow/project.json";
    editor.state.transient.recent.add(meadow);
    editor.state.transient.recent.add(folder.path() / "gone/project.json");  // not shown
    editor.click("File");
    const std::set<std::string> shown = editor.shownTexts();
    EXPECT_TRUE(shown.count("Open Recent"));
    EXPECT_FALSE(shown.count("   gone"));
    editor.click("   meadow");
    EXPECT_EQ(editor.state.openRequested, meadow.lexically_normal().string());
}

// Issue 26 item 1: files dropped on the window go where their kind says.
TEST(EditorPanels, DroppedFilesGoWhereTheirKindSays) {
    const ScratchFolder folder("editor-drop");
    EditorDriver editor(folder.path());
    editor.state.doc.dirty = false;
    editor::routeDroppedFiles(editor.state, {"/m/Rock.GLB", "/m/moss.png"});
    EXPECT_EQ(editor.state.importMeshRequested, "/m/Rock.GLB");
    EXPECT_EQ(editor.state.importMapRequested, "/m/moss.png");
    editor::routeDroppedFiles(editor.state, {(sourceDir() / "projects/meadow").string()});
    EXPECT_EQ(editor.state.openRequested, (sourceDir() / "projects/meadow").string());
    editor::routeDroppedFiles(editor.state, {"/m/notes.txt"});
    EXPECT_NE(editor.state.transient.message.find("drop a .gltf/.glb mesh"), std::string::npos)
        << editor.state.transient.message;
    EXPECT_EQ(editor.state.transient.message.find("looks like"), std::string::npos);
    // A mesh of another format is named, with the way to a glTF.
    editor::routeDroppedFiles(editor.state, {"/m/Rock.OBJ"});
    EXPECT_NE(
        editor.state.transient.message.find("it looks like an OBJ file: grass reads glTF 2.0"),
        std::string::npos)
        << editor.state.transient.message;
}

// Issue 26 item 1: Ctrl+O opens the browser for a project, Ctrl+N starts a new one.
TEST(EditorPanels, CtrlOAndCtrlN) {
    const ScratchFolder folder("editor-ctrl-keys");
    EditorDriver editor(folder.path());
    editor.state.doc.dirty = false;
    editor::InputState input;
    input.keys.push_back({ui::Key::O, {false, true, false}});
    editor::applyEditorKeys(editor.state, input, true);
    ASSERT_TRUE(editor.state.transient.browser.has_value());
    EXPECT_EQ(editor.state.transient.browser->purpose(), editor::BrowsePurpose::OpenProject);
    input.keys = {{ui::Key::N, {false, true, false}}};
    editor::applyEditorKeys(editor.state, input, true);
    EXPECT_TRUE(editor.state.newRequested);
}

// While Open grows the next field on its worker (app/document_job.h), the panels wait: a click
// on the menu opens nothing and the editing keys do nothing; the box says what is being read,
// and Cancel gives the window back at once with the document as it was.
TEST(EditorPanels, WhileAFieldGrowsThePanelsWaitAndCancelGivesThemBack) {
    const ScratchFolder folder("editor-loading");
    EditorDriver editor(folder.path());
    editor.state.doc.dirty = false;
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    editor.state.documentJob = std::make_unique<editor::DocumentJob>(
        editor::DocumentAction::Open, "elsewhere/meadow/project.json", "reading project.json",
        [released](editor::DocumentJob&) -> Result<editor::GrownDocument> {
            released.wait();
            return makeError("meadow", "not wanted");
        });
    const std::set<std::string> shown = editor.shownTexts();
    EXPECT_TRUE(shown.contains("Opening meadow"));
    EXPECT_TRUE(shown.contains("reading project.json … 0 s"));
    editor.click("File");
    EXPECT_FALSE(editor.shownTexts().contains("Quit")) << "the menu opened under the veil";
    editor.click("brush (b)");
    EXPECT_EQ(editor.state.view.tool, editor::ViewportTool::Camera) << "a click went through";
    editor::InputState keys;
    keys.keys.push_back({ui::Key::O, {false, true, false}});
    keys.nextTechnique = true;  // T: the technique, an edit of the project
    editor::applyEditorKeys(editor.state, keys, true);
    EXPECT_FALSE(editor.state.transient.browser.has_value());
    EXPECT_FALSE(editor.state.doc.dirty);
    // A file dropped meanwhile is refused in words, not queued behind the load.
    editor::routeDroppedFiles(editor.state, {(sourceDir() / "tests/data/gltf/cube.glb").string()});
    EXPECT_TRUE(editor.state.importMeshRequested.empty());
    EXPECT_TRUE(editor.state.transient.message.starts_with("not taken: "))
        << editor.state.transient.message;
    editor.click("Cancel");
    EXPECT_FALSE(editor.state.loading());
    ASSERT_EQ(editor.state.cancelledJobs.size(), 1u);
    EXPECT_EQ(editor.state.transient.message, "cancelled: Opening meadow");
    editor.click("brush (b)");
    EXPECT_EQ(editor.state.view.tool, editor::ViewportTool::Paint) << "the panels are free again";
    editor.click("File");
    EXPECT_TRUE(editor.shownTexts().contains("Quit"));
    release.set_value();
}

TEST(EditorPanels, QuitWithUnsavedChangesAsksFirst) {
    const ScratchFolder folder("editor-quit");
    EditorDriver editor(folder.path());
    editor.click("File");
    editor.click("Quit");
    EXPECT_FALSE(editor.state.quitRequested) << "unsaved changes must not be dropped silently";
    ASSERT_TRUE(editor.state.transient.quitDialog);
    editor.click("Cancel");
    EXPECT_FALSE(editor.state.transient.quitDialog);
    EXPECT_FALSE(editor.state.quitRequested);
    editor.click("File");
    editor.click("Quit");
    editor.click("Quit without saving");
    EXPECT_TRUE(editor.state.quitRequested);
}

// Issue 22: an export reads what already lies in its folder; whatever happens there, the
// unsaved work is in the autosave before the export starts.
TEST(EditorPanels, UnsavedWorkIsAutosavedBeforeAnExport) {
    const ScratchFolder folder("editor-export-autosave");
    EditorDriver editor(folder.path());
    ASSERT_TRUE(editor.state.doc.dirty);
    ASSERT_FALSE(fs::exists(editor::autosavePath(editor.state.doc.loaded)));
    editor.state.transient.exportDir = "exported";
    editor::startExport(editor.state);
    EXPECT_TRUE(fs::exists(editor::autosavePath(editor.state.doc.loaded)));
    ASSERT_TRUE(editor.state.exportJob);
    editor.state.exportJob.reset();  // waits for the worker
    EXPECT_TRUE(fs::exists(folder.path() / "exported" / "grass.gltf"));
}

// An export asked for while the field grows again after an edit (or before that starts) waits
// for the new field: the field before the edit is not the project saved beside the export. The
// Editor starts it once the field is in (exportWhenGrown).
TEST(EditorPanels, AnExportWaitsForTheFieldAfterAnEdit) {
    const ScratchFolder folder("editor-export-waits");
    EditorDriver editor(folder.path());
    editor.state.transient.exportDir = "exported";
    editor.state.rebuildPending = true;
    editor::startExport(editor.state);
    EXPECT_FALSE(editor.state.exportJob);
    EXPECT_TRUE(editor.state.exportWhenGrown);
    EXPECT_NE(editor.state.transient.message.find("once the field has grown"), std::string::npos)
        << editor.state.transient.message;
    editor.state.rebuildPending = false;
    editor::startExport(editor.state);
    ASSERT_TRUE(editor.state.exportJob);
    EXPECT_FALSE(editor.state.exportWhenGrown);
    // Its end is said on the status line as it comes, the window still open (before, the line
    // said "exporting to …" until the window was closed).
    editor.state.transient.exportDialog = true;
    editor.state.exportJob->wait();
    editor.frame();
    EXPECT_EQ(editor.state.transient.message.rfind("exported ", 0), 0u)
        << editor.state.transient.message;
    ASSERT_TRUE(editor.state.exportJob) << "the window still shows it";
    editor.state.transient.message = "a later message";
    editor.frame();
    EXPECT_EQ(editor.state.transient.message, "a later message") << "said once";
    editor.state.exportJob.reset();
}

// Issue 23: a collider on a keyed path stands where the path says; before, typing its position
// marked the project unsaved and moved nothing. Now the row edits the path at the timeline's
// time, so the object moves where the user typed.
TEST(EditorPanels, ATypedPositionMovesAKeyedCollider) {
    const ScratchFolder folder("editor-keyed-collider");
    EditorDriver editor(folder.path());
    core::ColliderDesc ball;
    ball.name = "ball";
    ball.path = {{0.0f, {-1.0f, 0.2f, 0.0f}}, {2.0f, {1.0f, 0.2f, 0.0f}}};
    editor.state.doc.loaded.project.colliders.push_back(ball);
    editor::resetHistory(editor.state);
    editor.state.view.timeline = core::timelineFor(editor.state.doc.loaded.project);
    const glm::vec3 before = core::samplePath(ball.path, 0.0f, ball.position);

    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Colliders (1)");
    // The row's last box sits left of its label; a press there and a drag to the right.
    std::optional<ui::Vec2> label;
    for (const ui::ClippedShape& shape : editor.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape);
            t && t->text == "keyed position")
            label = t->pos;
    ASSERT_TRUE(label.has_value()) << "a keyed collider's position row names the key";
    editor.dragRightOfLabel(*label);
    editor::recordProjectEdit(editor.state, false);

    const core::ColliderDesc& edited = editor.state.doc.loaded.project.colliders.back();
    const glm::vec3 after = core::samplePath(edited.path, 0.0f, edited.position);
    EXPECT_GT(after.z, before.z + 0.05f) << "the collider must move where the field says";
    EXPECT_EQ(after.x, before.x);
    EXPECT_EQ(edited.path.size(), 2u) << "the key at the timeline's time was edited in place";
    EXPECT_TRUE(editor.state.doc.dirty);
    EXPECT_TRUE(editor.state.rebuildPending);
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(editor.state.doc.loaded.project.colliders.back().path, ball.path);
}

// The Wind and Colliders sections add and delete their objects where a user looks for them;
// before, only the gizmo tool's settings had "add wind" and "add ball", and a wind source could
// be deleted only once selected there (or by Delete in the viewport).
TEST(EditorPanels, WindSourcesAndBallsAreAddedAndDeletedInTheirSections) {
    const ScratchFolder folder("editor-wind-section");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};  // no scrolling
    editor::resetHistory(d.state);
    const core::Project& project = d.state.doc.loaded.project;
    const std::size_t winds = project.wind.size();
    const std::size_t colliders = project.colliders.size();

    d.click("Wind (" + std::to_string(winds) + ")");
    d.click("add wind");
    editor::recordProjectEdit(d.state, false);
    ASSERT_EQ(project.wind.size(), winds + 1);
    EXPECT_EQ(project.wind.back().source.kind, core::WindKind::Point);
    EXPECT_TRUE(d.state.rebuildPending);
    ASSERT_TRUE(d.state.view.place.selected.has_value()) << "selected, for the gizmo";
    EXPECT_EQ(d.state.view.place.selected->index, winds);

    d.click("Colliders (" + std::to_string(colliders) + ")");
    d.click("add ball");
    editor::recordProjectEdit(d.state, false);
    ASSERT_EQ(project.colliders.size(), colliders + 1);
    EXPECT_EQ(d.state.view.place.selected->kind, editor::PlacedKind::Collider);

    d.click("Colliders (" + std::to_string(colliders + 1) + ")");  // closed: one delete shows
    d.click(project.wind.back().name);  // its header: open, with its delete button
    d.click("delete");
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(project.wind.size(), winds);
    EXPECT_TRUE(d.state.view.place.selected.has_value()) << "the selected ball stays selected";
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_EQ(project.wind.size(), winds + 1) << "Ctrl+Z brings it back";

    d.click(project.wind.back().name);  // closed again
    d.click("Colliders (" + std::to_string(colliders + 1) + ")");
    d.click("delete");  // the ball's, beside its name
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(project.colliders.size(), colliders);
    EXPECT_FALSE(d.state.view.place.selected.has_value()) << "the deleted ball was selected";
}

// Issue 26 item 5: the sun and the sky are edited in the side panel, undoably, and saved.
TEST(EditorPanels, TheLightSectionEditsTheSunAndTheSky) {
    const ScratchFolder folder("editor-light");
    EditorDriver editor(folder.path());
    editor::resetHistory(editor.state);
    const core::SunDesc before = editor.state.doc.loaded.project.sun;
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Light");
    std::optional<ui::Vec2> label;
    bool sky = false;
    for (const ui::ClippedShape& shape : editor.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape)) {
            if (t->text == "intensity")
                label = t->pos;
            sky = sky || t->text == "sky colour";
        }
    ASSERT_TRUE(label.has_value()) << "the Light section shows the sun's intensity";
    EXPECT_TRUE(sky) << "and the sky's colour";
    // Drag the intensity's box (left of its label) to the right.
    editor.dragRightOfLabel(*label);
    editor::recordProjectEdit(editor.state, false);
    EXPECT_GT(editor.state.doc.loaded.project.sun.intensity, before.intensity);
    EXPECT_FALSE(editor.state.rebuildPending) << "light is live: nothing re-grows";
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(editor.state.doc.loaded.project.sun, before);
    EXPECT_FALSE(editor.state.rebuildPending) << "nor does its undo";
}

// A quality preset that changes only the AO kernel's cells grows the field again: the blades'
// ambient occlusion is baked with them. Before 2026-12-07 only a change of the physics step did,
// and the field kept the AO of the cells before.
TEST(EditorPanels, APresetThatChangesTheAoCellsGrowsTheFieldAgain) {
    const ScratchFolder folder("editor-preset-ao");
    EditorDriver editor(folder.path());
    core::Project& project = editor.state.doc.loaded.project;
    const core::QualitySettings draft = core::qualitySettings(core::QualityPreset::Draft);
    ASSERT_TRUE(draft.aoCellSigmas.has_value());
    core::applyQuality(draft, project);
    project.lighting.aoCellSigmas = *draft.aoCellSigmas * 0.5f;  // the physics already the draft's
    const core::PhysicsParams physics = project.physics;
    editor::resetHistory(editor.state);
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Layers (1)");  // closed: the Render section comes up
    editor.click("custom");
    editor.click("draft");
    editor::recordProjectEdit(editor.state, false);
    EXPECT_EQ(project.lighting.aoCellSigmas, *draft.aoCellSigmas);
    EXPECT_EQ(project.physics, physics);
    EXPECT_TRUE(editor.state.rebuildPending);
}

// Issue 26 item 5: camera bookmarks are the project's cameras: keep the view as one, go to one.
TEST(EditorPanels, CameraBookmarksKeepTheViewAndGoBack) {
    const ScratchFolder folder("editor-cameras");
    EditorDriver editor(folder.path());
    editor::resetHistory(editor.state);
    const std::size_t before = editor.state.doc.loaded.project.cameras.size();
    ASSERT_GE(before, 1u);
    editor.state.view.camera = core::OrbitCamera::lookAt({3.0f, 2.0f, 1.0f}, {0.5f, 0.0f, 0.0f}, 0.6f);
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Cameras (" + std::to_string(before) + ")");
    editor.click("keep this view");
    editor::recordProjectEdit(editor.state, false);
    const auto& cameras = editor.state.doc.loaded.project.cameras;
    ASSERT_EQ(cameras.size(), before + 1);
    EXPECT_LT(glm::distance(cameras.back().position, glm::vec3(3.0f, 2.0f, 1.0f)), 1e-4f);
    EXPECT_LT(glm::distance(cameras.back().target, glm::vec3(0.5f, 0.0f, 0.0f)), 1e-5f);
    EXPECT_NEAR(cameras.back().fovYDeg, glm::degrees(0.6f), 1e-3f);
    EXPECT_TRUE(editor.state.doc.dirty);
    // "go" (the driver clicks the last one drawn: the kept view's) asks the viewport for it, from
    // wherever the view is now.
    editor.state.view.camera = core::OrbitCamera::lookAt({-5.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.8f);
    editor.click("go");
    ASSERT_TRUE(editor.state.view.cameraRequest.has_value());
    EXPECT_LT(glm::distance(editor.state.view.cameraRequest->position(), glm::vec3(3.0f, 2.0f, 1.0f)), 1e-3f);
    EXPECT_NEAR(editor.state.view.cameraRequest->fovYRad, 0.6f, 1e-5f);
    // Kept again under a name no camera has, though one is called "view 3" already: the format
    // wants names unique.
    editor.state.doc.loaded.project.cameras.back().name = "view 3";
    editor.click("keep this view");
    editor::recordProjectEdit(editor.state, false);
    ASSERT_EQ(cameras.size(), before + 2);
    EXPECT_EQ(cameras.back().name, "view 4");
    ASSERT_TRUE(editor::undo(editor.state));
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(editor.state.doc.loaded.project.cameras.size(), before);
}

// Issue 26 item 4: the timeline strip under the view draws a tick per key; a click on one selects
// the object that key moves and goes to its time.
TEST(EditorPanels, AClickOnAKeyTickSelectsItsObjectAndGoesThere) {
    const ScratchFolder folder("editor-timeline-strip");
    EditorDriver editor(folder.path());
    core::ColliderDesc ball;
    ball.name = "ball";
    ball.path = {{10.0f, {-1.0f, 0.2f, 0.0f}}, {50.0f, {1.0f, 0.2f, 0.0f}}};
    editor.state.doc.loaded.project.colliders.push_back(ball);
    editor::resetHistory(editor.state);
    editor.state.view.timeline = core::timelineFor(editor.state.doc.loaded.project);
    ASSERT_EQ(editor.state.view.timeline.endS(), 50.0);
    // The track spans the strip from its first button's left edge to 8 points from the window's
    // right; its centre is 43 points above the window's bottom (status bar 26, strip 56).
    std::optional<ui::Vec2> first;
    for (const ui::ClippedShape& shape : editor.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == "|<")
            first = t->pos;
    ASSERT_TRUE(first.has_value()) << "the strip's transport row";
    const float left = first->x - 6.0f, right = 1280.0f - 8.0f;
    editor.clickAt({left + 0.2f * (right - left) + 1.0f, 720.0f - 43.0f});
    ASSERT_TRUE(editor.state.view.place.selected.has_value());
    EXPECT_EQ(editor.state.view.place.selected->kind, editor::PlacedKind::Collider);
    EXPECT_EQ(editor.state.view.place.selected->index, 0u);
    EXPECT_NEAR(editor.state.view.timeline.timeS(), 10.0, 1e-4);
    // Away from the ticks a click scrubs.
    editor.clickAt({left + 0.6f * (right - left), 720.0f - 43.0f});
    EXPECT_NEAR(editor.state.view.timeline.timeS(), 30.0, 0.5);
}

// Issue 26 item 2: the Surface section sets a glTF surface's unit; the field re-grows and the
// view frames it again.
TEST(EditorPanels, TheSurfaceSectionSetsTheMeshUnit) {
    const ScratchFolder folder("editor-surface");
    EditorDriver editor(folder.path());
    core::MeshSource& mesh = editor.state.doc.loaded.project.mesh;
    mesh.isFile = true;
    mesh.file = "stone.gltf";
    editor::resetHistory(editor.state);
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Surface");
    const std::set<std::string> shown = editor.shownTexts();
    EXPECT_TRUE(shown.count("file: stone.gltf"));
    editor.click("m");   // the unit combo, showing metres
    editor.click("mm");  // its list
    editor::recordProjectEdit(editor.state, false);
    EXPECT_EQ(editor.state.doc.loaded.project.mesh.metresPerUnit, 0.001f);
    EXPECT_TRUE(editor.state.rebuildPending);
    EXPECT_TRUE(editor.state.view.frameSurfacePending);
    ASSERT_TRUE(editor::undo(editor.state));
    EXPECT_EQ(editor.state.doc.loaded.project.mesh.metresPerUnit, 1.0f);
}

// The environment variable `name` set to `value` (unset when null) for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : mName(name) {
        if (const char* old = std::getenv(name))
            mOld = old;
        if (value)
            ::setenv(name, value, 1);
        else
            ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (mOld)
            ::setenv(mName, mOld->c_str(), 1);
        else
            ::unsetenv(mName);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* mName;
    std::optional<std::string> mOld;
};

// Whether the recovery offer's Recover and Discard buttons are drawn whole, within what the
// window shows.
bool recoveryButtonsShown(EditorDriver& editor) {
    const ui::Output& out = editor.frame();
    int whole = 0;
    for (const char* button : {"Recover", "Discard"})
        for (const ui::ClippedShape& shape : out.shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == button)
                whole += shape.clip.contains(t->pos) &&
                         shape.clip.contains(t->pos + ui::Vec2(0.0f, t->sizePt));
    return whole == 2;
}

// A project never saved (New, New from mesh) has no folder of its own: its autosave goes to the
// user's unsaved folder as a project of its own, the files it names copied along, and is offered
// back after a crash (not while another editor that owns it runs); a save removes it. Before,
// such a project was never autosaved, in silence.
TEST(EditorPanels, ANeverSavedProjectIsAutosavedIntoTheUsersFolderAndOfferedBack) {
    const ScratchFolder folder("editor-unsaved-autosave");
    const ScratchFolder stateHome("editor-unsaved-state");
    const ScopedEnv state("XDG_STATE_HOME", stateHome.path().c_str());
    EditorDriver editor(folder.path());
    editor.state.doc.loaded.file.clear();  // as File > New from mesh leaves it
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    editor::autosaveNow(editor.state);
    const fs::path slot = editor.state.doc.unsavedSlot;
    ASSERT_FALSE(slot.empty());
    EXPECT_EQ(slot.parent_path(), stateHome.path() / "grass/unsaved");
    EXPECT_EQ(editor.state.transient.message.rfind("autosaved to ", 0), 0u)
        << editor.state.transient.message;
    EXPECT_FALSE(editor.state.transient.messageIsSaveError);
    EXPECT_TRUE(fs::exists(slot / "project.autosave.json"));
    EXPECT_TRUE(fs::exists(slot / "maps/soil.png")) << "the files it names, copied along";
    EXPECT_TRUE(fs::exists(slot / "maps/soil.autosave.png")) << "the painted map";

    // Another editor's slot (its process runs: pid 1) is not offered, though it is newer.
    fs::create_directories(stateHome.path() / "grass/unsaved/1-1");
    fs::copy_file(slot / "project.autosave.json",
                  stateHome.path() / "grass/unsaved/1-1/project.autosave.json");
    const auto offered = editor::findUnsavedAutosave();
    ASSERT_TRUE(offered.has_value());
    EXPECT_EQ(offered->folder, slot);
    EXPECT_TRUE(offered->file.empty()) << "still never saved: Save asks where";
    EXPECT_EQ(offered->project.layers.front().soilMap, "maps/soil.autosave.png");
    EXPECT_TRUE(core::buildScene(*offered).ok()) << "it grows from the slot's files";
    // The offer says which project and when: the editor may have opened another one.
    editor.state.recoveryOffer = *offered;
    std::string offer;
    for (const std::string& text : editor.shownTexts())
        offer += text + " ";
    EXPECT_NE(offer.find("\"" + offered->project.name + "\","), std::string::npos) << offer;
    EXPECT_NE(offer.find("just now."), std::string::npos) << offer;
    EXPECT_TRUE(recoveryButtonsShown(editor));
    editor.state.recoveryOffer.reset();
    // However many lines a long name wraps onto, the window (first shown, in a window system of
    // its own) is tall enough for its buttons (before, its height was fixed and they went below
    // its edge).
    {
        const ScratchFolder elsewhere("editor-unsaved-long-name");
        EditorDriver fresh(elsewhere.path());
        fresh.state.recoveryOffer = *offered;
        for (int i = 0; i < 8; ++i)
            fresh.state.recoveryOffer->project.name += "the meadow behind the old mill ";
        EXPECT_TRUE(recoveryButtonsShown(fresh));
    }

    // Saved: nothing left to recover.
    ASSERT_TRUE(editor::saveTo(editor.state, (folder.path() / "saved/project.json").string()));
    EXPECT_FALSE(fs::exists(slot));
    EXPECT_TRUE(editor.state.doc.unsavedSlot.empty());
    EXPECT_TRUE(fs::exists(folder.path() / "saved/maps/soil.png"));

    // With no folder for it at all, the status line says so and how to keep the work.
    const ScopedEnv noState("XDG_STATE_HOME", nullptr);
    const ScopedEnv noHome("HOME", nullptr);
    EXPECT_TRUE(editor::unsavedAutosaveRoot().empty());
    editor.state.doc.loaded.file.clear();
    editor.state.doc.dirty = true;
    editor.state.transient.message.clear();
    editor::autosaveNow(editor.state);
    const std::string said = editor.state.transient.message;
    EXPECT_EQ(said.rfind("not autosaved: ", 0), 0u) << said;
    EXPECT_NE(said.find("Save As"), std::string::npos) << said;
    EXPECT_TRUE(editor.state.transient.messageIsSaveError) << "shown in the warning colour";
}

// Two never-saved projects left by sessions that did not close cleanly: the newer is offered
// first, and once discarded the older is offered in the same session (before, one a start); the
// open document's own slot is never offered, nor anything to a replayed script.
TEST(EditorPanels, EveryLeftAutosaveIsOfferedInTurn) {
    const ScratchFolder folder("editor-autosaves-in-turn");
    const ScratchFolder stateHome("editor-autosaves-in-turn-state");
    const ScopedEnv state("XDG_STATE_HOME", stateHome.path().c_str());
    EditorDriver editor(folder.path());
    const fs::path root = stateHome.path() / "grass/unsaved";
    const auto leave = [&](const std::string& slot, const std::string& name, int ageS) {
        core::Project project = editor.state.doc.project();
        project.name = name;
        fs::create_directories(root / slot);
        const fs::path side = root / slot / "project.autosave.json";
        ASSERT_TRUE(core::saveProject(project, side).ok());
        fs::last_write_time(side, fs::file_time_type::clock::now() - std::chrono::seconds(ageS));
    };
    // Slots of processes that are gone (no process has these ids).
    leave("999991-1", "older", 600);
    leave("999992-1", "newer", 60);
    leave("999993-1", "mine", 1);
    editor.state.doc.unsavedSlot = root / "999993-1";  // the open document's own, newest
    editor.state.recoveryOffer = editor::findUnsavedAutosave(editor.state.doc.unsavedSlot);
    ASSERT_TRUE(editor.state.recoveryOffer);
    EXPECT_EQ(editor.state.recoveryOffer->project.name, "newer");
    editor.click("Discard");
    EXPECT_FALSE(fs::exists(root / "999992-1"));
    ASSERT_TRUE(editor.state.recoveryOffer) << "the older one is offered next";
    EXPECT_EQ(editor.state.recoveryOffer->project.name, "older");
    editor.frame();  // the window of the next offer, first shown
    editor.click("Discard");
    EXPECT_FALSE(fs::exists(root / "999991-1"));
    EXPECT_FALSE(editor.state.recoveryOffer) << "the document's own slot is not offered";
    EXPECT_TRUE(fs::exists(root / "999993-1"));
    // A replayed script is offered none.
    leave("999994-1", "another", 30);
    leave("999995-1", "last", 40);
    editor.state.offersUnsavedAutosaves = false;
    editor.state.recoveryOffer = editor::findUnsavedAutosave(editor.state.doc.unsavedSlot);
    ASSERT_TRUE(editor.state.recoveryOffer);
    editor.click("Discard");
    EXPECT_FALSE(editor.state.recoveryOffer);
    EXPECT_TRUE(fs::exists(root / "999995-1"));
}

// How long ago an autosave was written, as the recovery offer says it.
TEST(EditorPanels, TheRecoveryOfferSaysHowLongAgoInWholeUnits) {
    EXPECT_EQ(editor::timeAgo(0.0), "just now");
    EXPECT_EQ(editor::timeAgo(59.9), "just now");
    EXPECT_EQ(editor::timeAgo(-30.0), "just now") << "a clock set back";
    EXPECT_EQ(editor::timeAgo(std::nan("")), "just now");
    EXPECT_EQ(editor::timeAgo(60.0), "1 minute ago");
    EXPECT_EQ(editor::timeAgo(179.0), "2 minutes ago");
    EXPECT_EQ(editor::timeAgo(3599.0), "59 minutes ago");
    EXPECT_EQ(editor::timeAgo(3600.0), "1 hour ago");
    EXPECT_EQ(editor::timeAgo(47.9 * 3600.0), "47 hours ago");
    EXPECT_EQ(editor::timeAgo(3.5 * 86400.0), "3 days ago");
}

// A saved project whose folder refuses the autosave (read-only, full; here a folder stands where
// the side project goes, so it holds as root too) is autosaved into the user's unsaved folder
// and offered back naming the project it came from. Before, the status line said "autosave
// failed" and the work was kept nowhere until the user found a folder for Save As.
TEST(EditorPanels, AProjectWhoseFolderRefusesTheAutosaveIsAutosavedIntoTheUsersFolder) {
    const ScratchFolder folder("editor-refused-autosave");
    const ScratchFolder stateHome("editor-refused-state");
    const ScopedEnv state("XDG_STATE_HOME", stateHome.path().c_str());
    EditorDriver editor(folder.path());
    editor.state.doc.paintedMaps.insert({0, core::LayerMap::Soil});
    const fs::path blocked = editor::autosavePath(editor.state.doc.loaded);
    ASSERT_FALSE(blocked.empty());
    fs::create_directories(blocked);
    editor::autosaveNow(editor.state);
    const std::string said = editor.state.transient.message;
    const fs::path slot = editor.state.doc.unsavedSlot;
    ASSERT_FALSE(slot.empty()) << said;
    EXPECT_EQ(slot.parent_path(), stateHome.path() / "grass/unsaved");
    EXPECT_EQ(said.rfind("the project's folder refused the autosave: kept in ", 0), 0u) << said;
    EXPECT_NE(said.find((slot / "project.autosave.json").string()), std::string::npos) << said;
    EXPECT_NE(said.find("Save As"), std::string::npos) << said;
    EXPECT_TRUE(editor.state.transient.messageIsSaveError) << "shown in the warning colour";
    EXPECT_TRUE(fs::exists(slot / "maps/soil.autosave.png")) << "the painted map";
    EXPECT_EQ(editor::unsavedAutosaveOrigin(slot), editor.state.doc.loaded.file);

    // Offered back after a crash, naming the project it came from.
    const auto offered = editor::findUnsavedAutosave();
    ASSERT_TRUE(offered.has_value());
    EXPECT_EQ(offered->folder, slot);
    EXPECT_TRUE(core::buildScene(*offered).ok()) << "it grows from the slot's files";
    editor.state.recoveryOffer = *offered;
    // Wrapped: the path is a line of its own, after "An autosave of".
    const std::set<std::string> shown = editor.shownTexts();
    EXPECT_TRUE(shown.count("An autosave of"));
    EXPECT_TRUE(shown.count(editor.state.doc.loaded.file.string() + " was")) << "the offer names the project";
    EXPECT_TRUE(recoveryButtonsShown(editor));
    editor.state.recoveryOffer.reset();

    // Recovered, its Save As starts where the project was, which it saves onto without asking
    // (a never-saved project's starts in the working folder).
    {
        const ScratchFolder elsewhere("editor-refused-recovered");
        EditorDriver recovered(elsewhere.path());
        recovered.state.doc.loaded = *offered;
        editor::openBrowser(recovered.state, editor::BrowsePurpose::SaveProject);
        ASSERT_TRUE(recovered.state.transient.browser.has_value());
        editor::FileBrowser& browser = *recovered.state.transient.browser;
        EXPECT_EQ(browser.folder(), folder.path().parent_path());
        EXPECT_EQ(browser.typed(), folder.path().filename().string());
        EXPECT_EQ(browser.activateTyped(), std::optional<fs::path>(folder.path()));
        EXPECT_TRUE(browser.message().empty()) << browser.message();
    }

    // Once the folder takes the autosave again, the stand-in slot has nothing left to recover.
    fs::remove(blocked);
    editor::autosaveNow(editor.state);
    EXPECT_TRUE(fs::is_regular_file(blocked));
    EXPECT_FALSE(fs::exists(slot));
    EXPECT_TRUE(editor.state.doc.unsavedSlot.empty());
    EXPECT_FALSE(editor::unsavedAutosaveOrigin(slot).has_filename());

    // With neither place writable, the status line says both.
    fs::remove(blocked);
    fs::create_directories(blocked);
    const ScopedEnv noState("XDG_STATE_HOME", nullptr);
    const ScopedEnv noHome("HOME", nullptr);
    editor::autosaveNow(editor.state);
    EXPECT_EQ(editor.state.transient.message.rfind("autosave failed: ", 0), 0u)
        << editor.state.transient.message;
    EXPECT_TRUE(editor.state.transient.messageIsSaveError);
}

// File › Save screenshot, Save turntable and Export… write beside the project; where they cannot (the
// folder gone, read-only, or the autosave slot a recovered project lives in) they go to the
// working folder instead of failing ("screenshot not saved: … cannot write", found on a
// read-only copy of the meadow).
TEST(EditorPanels, PicturesAndExportsGoWhereTheyCanBeWritten) {
    const ScratchFolder folder("editor-pictures");
    EditorDriver editor(folder.path());
    EXPECT_EQ(editor::outputFolder(editor.state), folder.path());
    EXPECT_EQ(fs::path(editor::freshPicturePath(editor.state, "screenshot", ".png")),
              folder.path() / "screenshot-1.png");
    std::ofstream(folder.path() / "screenshot-1.png") << "taken";
    EXPECT_EQ(fs::path(editor::freshPicturePath(editor.state, "screenshot", ".png")),
              folder.path() / "screenshot-2.png");

    editor.state.doc.loaded.folder = folder.path() / "gone";
    EXPECT_EQ(editor::outputFolder(editor.state), fs::current_path());
    const ScratchFolder stateHome("editor-pictures-state");
    const ScopedEnv state("XDG_STATE_HOME", stateHome.path().c_str());
    editor.state.doc.loaded.folder = editor::unsavedAutosaveRoot() / "1-1";
    fs::create_directories(editor.state.doc.loaded.folder);
    EXPECT_EQ(editor::outputFolder(editor.state), fs::current_path()) << "not the hidden slot";
    editor.click("File");
    editor.click("Export…");
    EXPECT_EQ(fs::path(editor.state.transient.exportDir), fs::current_path() / "export")
        << "the export window's default folder follows the same rule";

    // A project opened by a relative path (`grass-editor meadow`): the default export folder is
    // its export folder, written out whole. Before, "meadow/export" was read as inside the
    // project's folder: meadow/meadow/export.
    editor.state.doc.loaded.folder = fs::relative(folder.path(), fs::current_path());
    ASSERT_TRUE(editor.state.doc.loaded.folder.is_relative());
    editor.state.transient.exportDir.clear();
    editor.state.transient.exportDialog = false;
    editor.click("File");
    editor.click("Export…");
    EXPECT_EQ(fs::path(editor.state.transient.exportDir), folder.path() / "export");
    EXPECT_EQ(fs::path(editor::freshPicturePath(editor.state, "screenshot", ".png")),
              folder.path() / "screenshot-2.png");
}

// Issue 26 item 4: every status message is logged; a click on the status line shows them whole.
TEST(EditorPanels, TheStatusMessageOpensTheWholeLog) {
    const ScratchFolder folder("editor-messages");
    EditorDriver editor(folder.path());
    const std::string longMessage =
        "cannot import /a/very/long/path/that/does/not/fit/in/the/status/bar/at/all/rock.glb: "
        "the file is not glTF";
    editor.state.transient.message = "first";
    editor.frame();
    editor.state.transient.message = longMessage;
    editor.frame();
    ASSERT_EQ(editor.state.transient.messageLog.size(), 2u);
    EXPECT_NE(editor.state.transient.messageLog[1].find(longMessage), std::string::npos);
    // The status line shows the message first, left of the figures (after them it lay past the
    // window's edge at 1280 px while the picture was reduced), cut to the room the figures
    // leave: they end inside the window (cut to half the line, a new project's message pushed
    // the grass time off it).
    const std::string figuresStart =
        std::to_string(editor.state.transient.status.blades) + " blades";
    // Some seconds on: a new message comes before the figures (below,
    // TheStatusBarMakesRoomForANewMessage).
    editor.input.timeS += 7.0;
    const ui::Output& withMessage = editor.frame();
    std::optional<ui::TextShape> status = textStarting(withMessage, "cannot import /a/very");
    std::optional<ui::TextShape> figures = textStarting(withMessage, figuresStart);
    ASSERT_TRUE(status && figures);
    EXPECT_LT(status->pos.x, figures->pos.x);
    EXPECT_NE(status->text.find("\u2026"), std::string::npos) << status->text;
    EXPECT_EQ(status->text.find("the file is not glTF"), std::string::npos) << status->text;
    EXPECT_LE(figures->pos.x + testFonts().textSize(figures->text, figures->sizePt).x,
              editor.input.screenRect.max.x);
    // Physics that cannot keep up is said before the figures, in the room they leave.
    editor.state.transient.status.physicsDroppedS = 0.5;
    const ui::Output& behindFrame = editor.frame();
    const std::optional<ui::TextShape> behind =
        textStarting(behindFrame, "physics behind: skipping 0.5 s per s");
    figures = textStarting(behindFrame, figuresStart);
    ASSERT_TRUE(behind && figures);
    EXPECT_LT(behind->pos.x, figures->pos.x);
    EXPECT_LE(behind->pos.x + testFonts().textSize(behind->text, behind->sizePt).x,
              editor.input.screenRect.max.x)
        << "the warning shows whole, whatever a narrow window cuts";
    editor.state.transient.status.physicsDroppedS = 0.0;
    // A narrow window leaves out whole figures, the least wanted first (the UI's time), rather
    // than cutting the line at its edge mid-word; the blade counts and the frame rate stay, and
    // the message takes what room is left, if any (else it waits in Help › Messages).
    // 1280 points playing a reduced picture with the physics behind, 900 without either note.
    for (const float windowWidth : {1280.0f, 900.0f}) {
        const bool notes = windowWidth > 1000.0f;
        editor.state.transient.status.reduced = notes ? "MSAA off, 1/16 blades, LOD, 1/2 res" : "";
        editor.state.transient.status.physicsDroppedS = notes ? 0.5 : 0.0;
        editor.input.screenRect = {{0.0f, 0.0f}, {windowWidth, 720.0f}};
        const ui::Output& narrow = editor.frame();
        figures = textStarting(narrow, figuresStart);
        ASSERT_TRUE(figures) << windowWidth;
        EXPECT_LE(figures->pos.x + testFonts().textSize(figures->text, figures->sizePt).x,
                  windowWidth)
            << figures->text;
        EXPECT_EQ(figures->text.find("UI "), std::string::npos) << figures->text;
        EXPECT_TRUE(figures->text.ends_with(" fps")) << figures->text;
        if (const auto message = textStarting(narrow, "cannot import")) {
            EXPECT_LT(message->pos.x, figures->pos.x);
        }
    }
    editor.state.transient.status.reduced.clear();
    editor.state.transient.status.physicsDroppedS = 0.0;
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 720.0f}};
    editor.clickStartingWith("cannot import /a/very");
    ASSERT_TRUE(editor.state.transient.messagesWindow);
    // Wrapped to the window, the whole text is there, line by line.
    std::string joined;
    for (const ui::ClippedShape& shape : editor.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && !t->text.ends_with("   "))
            joined += t->text + " ";  // the status line's message ends with three spaces
    EXPECT_NE(joined.find("the file is not glTF"), std::string::npos) << joined;
}

// The timeline strip's range and key count are said as the room left allows: at 800 points,
// the window's least width, the line ran past the window's edge and read "0.0".
TEST(EditorPanels, TheTimelineRangeIsSaidAsRoomAllows) {
    const ScratchFolder folder("editor-timeline-range");
    EditorDriver editor(folder.path());
    const auto endX = [](const ui::TextShape& text) {
        return text.pos.x + testFonts().textSize(text.text, text.sizePt).x;
    };
    bool shortened = false;
    for (const float width : {1280.0f, 1000.0f, 900.0f, 800.0f, 700.0f}) {
        editor.input.screenRect = {{0.0f, 0.0f}, {width, 720.0f}};
        const ui::Output& out = editor.frame();
        const std::optional<ui::TextShape> whole = textStarting(out, "   0.00 – ");
        const std::optional<ui::TextShape> keys = textStarting(out, "   0 keys");
        if (width == 1280.0f) {
            ASSERT_TRUE(whole) << "a wide window says the range";
        }
        for (const auto& range : {whole, keys}) {
            if (range) {
                EXPECT_LE(endX(*range), width) << width << ": " << range->text;
            }
        }
        shortened = shortened || (!whole && keys);
    }
    EXPECT_TRUE(shortened) << "a narrow window says the key count alone";
}

// A new message comes before the figures for its first seconds. At 1280 points, while a field
// played reduced with its physics behind (always, on llvmpipe), the "moving: …" and "physics
// behind" notes and the figures left no room, and Ctrl+S said nothing at all; a second Ctrl+S,
// with the same text, was not said again either.
TEST(EditorPanels, TheStatusBarMakesRoomForANewMessage) {
    const ScratchFolder folder("editor-fresh-message");
    EditorDriver editor(folder.path());
    editor::FrameStatus& status = editor.state.transient.status;
    status.blades = 58942;
    status.fps = 2.0;
    status.physicsDevice = "cpu";
    status.physicsMs = 11.2;
    status.reduced = "MSAA off, 1/16 blades, LOD, 1/2 res";
    status.physicsDroppedS = 0.9;
    const auto endX = [](const ui::TextShape& text) {
        return text.pos.x + testFonts().textSize(text.text, text.sizePt).x;
    };
    const std::string saved = "saved " + (folder.path() / "project.json").string();
    for (int save = 0; save < 2; ++save) {
        ASSERT_TRUE(editor::saveTo(editor.state, (folder.path() / "project.json").string()));
        const ui::Output& out = editor.frame();
        const std::optional<ui::TextShape> message = textStarting(out, "saved ");
        const std::optional<ui::TextShape> figures = textStarting(out, "58942 blades");
        const std::optional<ui::TextShape> behind = textStarting(out, "physics behind");
        ASSERT_TRUE(message) << "save " << save << ": the message has no room";
        EXPECT_EQ(message->text, saved + "   ") << "whole";
        ASSERT_TRUE(figures && behind) << [&] {
            std::string all;
            for (const ui::ClippedShape& shape : out.shapes)
                if (const auto* t = std::get_if<ui::TextShape>(&shape.shape))
                    all += "[" + t->text + "]";
            return all;
        }();
        EXPECT_LT(endX(*message), behind->pos.x);
        EXPECT_LT(endX(*behind), figures->pos.x);
        EXPECT_LE(endX(*figures), editor.input.screenRect.max.x) << figures->text;
        // The viewport's badge says "reduced while moving"; the bar says the notes short
        // meanwhile.
        EXPECT_TRUE(textStarting(out, "moving   ")) << "the note said short";
        // Some seconds later the figures and the whole note have their room back.
        editor.input.timeS += 7.0;
        const ui::Output& later = editor.frame();
        EXPECT_TRUE(textStarting(later, "moving: MSAA off, 1/16 blades"));
        EXPECT_TRUE(textStarting(later, "physics behind: skipping 0.9 s per s"));
        const std::optional<ui::TextShape> laterFigures = textStarting(later, "58942 blades");
        ASSERT_TRUE(laterFigures);
        EXPECT_TRUE(laterFigures->text.ends_with("2 fps")) << laterFigures->text;
        EXPECT_LE(endX(*laterFigures), editor.input.screenRect.max.x);
    }
    std::size_t savesLogged = 0;
    for (const std::string& line : editor.state.transient.messageLog)
        savesLogged += line.find(saved) != std::string::npos ? 1 : 0;
    EXPECT_EQ(savesLogged, 2u) << "each save said";
    // A narrow window says the notes short, then without "moving" (the viewport's badge says
    // it): the warning and the blade counts stay whole inside it. Before, at 900 points the
    // warning ran off the edge mid-word, the blade counts after it.
    for (const float windowWidth : {900.0f, 700.0f}) {
        editor.input.screenRect = {{0.0f, 0.0f}, {windowWidth, 720.0f}};
        const ui::Output& narrow = editor.frame();
        const std::optional<ui::TextShape> figures = textStarting(narrow, "58942 blades");
        const std::optional<ui::TextShape> behind = textStarting(narrow, "physics behind");
        ASSERT_TRUE(figures && behind) << windowWidth;
        EXPECT_LT(endX(*behind), figures->pos.x);
        EXPECT_LE(endX(*figures), windowWidth) << figures->text;
        if (const std::optional<ui::TextShape> moving = textStarting(narrow, "moving")) {
            EXPECT_LT(endX(*moving), behind->pos.x);
        }
    }
}

// Issue 26 item 4: Help › Keyboard shortcuts shows every key of the editor's table.
TEST(EditorPanels, HelpListsEveryKeyboardShortcut) {
    const ScratchFolder folder("editor-help");
    EditorDriver editor(folder.path());
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 1200.0f}};  // the table unscrolled
    editor.click("Help");
    editor.click("Keyboard shortcuts");
    const std::set<std::string> shown = editor.shownTexts();
    ASSERT_GE(editor::keyboardShortcuts().size(), 15u);
    for (const editor::Shortcut& shortcut : editor::keyboardShortcuts()) {
        EXPECT_TRUE(shown.count(std::string(shortcut.keys))) << shortcut.keys;
        EXPECT_TRUE(shown.count(std::string(shortcut.what))) << shortcut.what;
    }
    for (const char* key : {"Delete", "F", "Space", "Ctrl+Z", "Ctrl+S"})
        EXPECT_TRUE(shown.count(key)) << key;
}

// Help › About grass says the version, the OpenGL renderer, where the guide and the autosaves of
// never-saved projects are; Copy puts those lines on the clipboard for a bug report.
TEST(EditorPanels, HelpAboutSaysTheVersionAndRendererAndCopiesThem) {
    const ScratchFolder folder("editor-about");
    const ScratchFolder stateHome("editor-about-state");
    const ScopedEnv state("XDG_STATE_HOME", stateHome.path().c_str());
    EditorDriver editor(folder.path());
    editor.state.glRenderer = "Test Renderer | 4.5 (Core Profile)";
    editor.click("Help");
    editor.click("About grass");
    ASSERT_TRUE(editor.state.transient.aboutWindow);
    const std::set<std::string> shown = editor.shownTexts();
    std::string said;  // wrapped lines joined again
    for (const std::string& text : shown)
        said += text + " ";
    EXPECT_TRUE(shown.count("grass-editor " + std::string(core::versionText()))) << said;
    EXPECT_TRUE(shown.count("OpenGL: Test Renderer | 4.5 (Core Profile)")) << said;
    EXPECT_TRUE(shown.count("Guide: " + (sourceDir() / "docs/editing.md").string())) << said;
    EXPECT_NE(said.find((stateHome.path() / "grass/unsaved").string()), std::string::npos) << said;
    EXPECT_NE(core::versionText(), "unknown") << "CMake's project version reaches the build";
    editor.click("Copy");
    const auto& copied = editor.ctx.output().copiedText;
    ASSERT_TRUE(copied.has_value());
    EXPECT_EQ(copied->rfind("grass-editor " + std::string(core::versionText()) + "\n", 0), 0u)
        << *copied;
    EXPECT_NE(copied->find("OpenGL: Test Renderer"), std::string::npos) << *copied;
}

// Issue 26 item 4: a setting's widget says what it is, what it accepts and where it is saved.
TEST(EditorPanels, ASettingShowsItsTooltipWhenHovered) {
    const ScratchFolder folder("editor-tooltip");
    EditorDriver editor(folder.path());
    editor.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};  // no scrolling
    editor.click("Light");
    std::optional<ui::Vec2> label;
    for (const ui::ClippedShape& shape : editor.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == "intensity")
            label = t->pos;
    ASSERT_TRUE(label.has_value());
    editor.input.pointerPos = *label + ui::Vec2(-20.0f, 6.0f);
    editor.frame();
    std::string tooltip;
    for (const ui::ClippedShape& shape : editor.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text.find("multiplies") == 0)
            tooltip = t->text;
    EXPECT_EQ(tooltip, "multiplies color · allowed: >= 0 · project.json \"intensity\"");
}

std::vector<std::string> layerNames(const editor::EditorState& state) {
    std::vector<std::string> names;
    for (const core::GrassLayer& layer : state.doc.project().layers)
        names.push_back(layer.name);
    return names;
}

// A re-grow as the Editor does it after a panel edit: the scene grown from the project, the
// painted maps carried over.
void regrowLikeTheEditor(EditorDriver& d) {
    auto grown = core::buildScene(d.state.doc.loaded);
    ASSERT_TRUE(grown.ok()) << grown.error().str();
    ASSERT_TRUE(editor::carryPaintedMaps(d.state, d.scene, *grown).ok());
    d.scene = std::move(*grown);
    d.state.rebuildPending = false;
}

// Issue 27 item 2: layers as species, added, duplicated, reordered and removed in the panel, each
// one undo step; the maps painted on a layer follow it through a reorder and a removal's undo.
TEST(EditorPanels, LayersAreAddedDuplicatedMovedAndRemovedWithTheirPaintedMaps) {
    const ScratchFolder folder("editor-layers");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};  // no scrolling
    editor::resetHistory(d.state);
    // Paint the first layer's density map (as a finished stroke leaves it).
    const core::MapImage painted = core::makeConstantMap(64, 64, 0.25f);
    d.scene.layers[0].source.maps.density = painted;
    d.state.doc.paintedMaps.insert({0, core::LayerMap::Density});

    d.click("add layer");
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(layerNames(d.state), (std::vector<std::string>{"grass", "grass 2"}));
    EXPECT_TRUE(d.state.rebuildPending);
    regrowLikeTheEditor(d);

    d.click("duplicate");  // the first layer's header is open
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(layerNames(d.state), (std::vector<std::string>{"grass", "grass copy", "grass 2"}));
    regrowLikeTheEditor(d);
    EXPECT_EQ(d.scene.layers[1].source.maps.density.texels, painted.texels)
        << "the copy starts from its source's painted map";

    d.click("down");
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(layerNames(d.state), (std::vector<std::string>{"grass copy", "grass", "grass 2"}));
    EXPECT_EQ(d.state.view.paint.layer, 1u) << "the brush follows the layer it paints";
    regrowLikeTheEditor(d);
    ASSERT_FALSE(d.scene.layers[1].source.maps.density.texels.empty());
    EXPECT_EQ(d.scene.layers[1].source.maps.density.texels[0], 0.25f);
    EXPECT_TRUE(d.state.doc.paintedMaps.count({1, core::LayerMap::Density}));

    // Remove the copy (the first layer, whose header is open): its painted map waits.
    d.click("remove");
    editor::recordProjectEdit(d.state, false);
    regrowLikeTheEditor(d);
    EXPECT_EQ(layerNames(d.state), (std::vector<std::string>{"grass", "grass 2"}));
    EXPECT_TRUE(d.state.doc.waitingMaps.count({"grass copy", core::LayerMap::Density}))
        << "the removed layer's painted map waits for an undo";
    ASSERT_TRUE(editor::undo(d.state));
    regrowLikeTheEditor(d);
    EXPECT_EQ(layerNames(d.state), (std::vector<std::string>{"grass copy", "grass", "grass 2"}));
    ASSERT_FALSE(d.scene.layers[0].source.maps.density.texels.empty());
    EXPECT_EQ(d.scene.layers[0].source.maps.density.texels[0], 0.25f);
    EXPECT_TRUE(d.state.doc.waitingMaps.empty());

    // Undo every step: the layers come back in order, with the painted map on "grass".
    while (editor::undo(d.state))
        regrowLikeTheEditor(d);
    EXPECT_EQ(layerNames(d.state), (std::vector<std::string>{"grass"}));
    ASSERT_FALSE(d.scene.layers[0].source.maps.density.texels.empty());
    EXPECT_EQ(d.scene.layers[0].source.maps.density.texels[0], 0.25f);
}

// Issue 27 item 1 in the editor: a layer's rules are edited in its "placement rules" section
// and re-grow the field; the surface's names are offered as a checklist.
TEST(EditorPanels, PlacementRulesAreEditedInTheLayer) {
    const ScratchFolder folder("editor-rules");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};
    editor::resetHistory(d.state);
    d.click("placement rules");
    const std::set<std::string> shown = d.shownTexts();
    // Wrapped to the panel's width: its first line.
    EXPECT_TRUE(std::any_of(shown.begin(), shown.end(), [](const std::string& text) {
        return text.starts_with("this surface names no parts");
    }));
    EXPECT_TRUE(shown.count("clear colliders"));
    d.click("clear colliders");
    editor::recordProjectEdit(d.state, false);
    EXPECT_TRUE(d.state.doc.project().layers[0].rules.clearColliders);
    EXPECT_TRUE(d.state.rebuildPending);
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_FALSE(d.state.doc.project().layers[0].rules.clearColliders);
}

// A density the scene cannot hold is not taken from a drag either (a typed one is refused in its
// box): on a 60 km sphere (1.16e10 m²) the density slider's lowest step, 1 /m², asked for 1e10
// blades; the field could not grow, and the project kept the density, which it could then not
// grow from. And the slider's box reads such a mesh's density, below 1 /m², with its digits
// (it read "0").
TEST(EditorPanels, ADensityDragTheSceneCannotHoldIsNotTaken) {
    const ScratchFolder folder("editor-density-limit");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};
    d.scene.area = 1.16e10;
    core::Project sparse = d.state.doc.project();
    sparse.layers.front().scatter.density = 3.45e-6f;
    editor::apply(d.state, editor::EditProject{.after = sparse});
    // Presses on the slider's track left of the density box and drags right.
    const auto dragTrack = [&] {
        std::optional<ui::Vec2> label, box;
        const ui::Output& out = d.frame();
        for (const ui::ClippedShape& shape : out.shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape);
                t && t->text == "density /m²")
                label = t->pos;
        ASSERT_TRUE(label.has_value());
        for (const ui::ClippedShape& shape : out.shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape);
                t && t->pos.x < label->x && std::abs(t->pos.y - label->y) < 4.0f)
                box = t->pos;
        ASSERT_TRUE(box.has_value()) << "no density box";
        d.input.pointerPos = *box + ui::Vec2(-60.0f, 6.0f);
        d.frame();
        d.input.buttonDown[0] = true;
        d.frame();
        for (int i = 0; i < 4; ++i) {
            d.input.pointerPos.x += 5.0f;
            d.frame();
        }
        d.input.buttonDown[0] = false;
        d.frame();
    };
    EXPECT_TRUE(d.shownTexts().contains("0.00000345"));
    dragTrack();
    EXPECT_EQ(d.state.doc.project().layers.front().scatter.density, 3.45e-6f);
    const std::string& said = d.state.transient.message;
    EXPECT_TRUE(said.starts_with("density not changed: ")) << said;
    EXPECT_NE(said.find("a scene holds at most 2e+07"), std::string::npos) << said;
    EXPECT_EQ(d.state.transient.warningMessage, said) << "said in orange";
    // The other layers count: a second layer of the scene's whole budget leaves this one none.
    d.scene.area = 4.0;
    core::Project full = d.state.doc.project();
    full.layers.push_back(full.layers.front());
    full.layers.back().name = "full";
    full.layers.back().scatter.density = float(core::MAX_SCENE_BLADES / 4.0);
    editor::apply(d.state, editor::EditProject{.after = full});
    d.state.transient.message.clear();
    dragTrack();
    EXPECT_EQ(d.state.doc.project().layers.front().scatter.density, 3.45e-6f);
    EXPECT_TRUE(said.starts_with("density not changed: ")) << said;
    // On the project's own 2 m plane alone the same drag is taken.
    full.layers.pop_back();
    editor::apply(d.state, editor::EditProject{.after = full});
    d.state.transient.message.clear();
    dragTrack();
    EXPECT_GT(d.state.doc.project().layers.front().scatter.density, 1.0f);
    EXPECT_TRUE(said.empty()) << said;
}

// Every text of the side panel, with every section and sub-section open and the brush's settings
// showing, lies within the panel at its default width: a row wider than the panel cut its last
// words off ("density /m²" read "density /m", the budget's unit was lost).
TEST(EditorPanels, EveryTextOfTheSidePanelIsReadWholeAtItsDefaultWidth) {
    const ScratchFolder folder("editor-whole-labels");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 6000.0f}};  // no scrolling: every row shows
    const core::Project& project = d.state.doc.loaded.project;
    // Opens the header whose text starts with `prefix`: a click that hid texts closed an open
    // header, so a second click opens it again.
    const auto open = [&](std::string_view prefix) {
        const std::size_t before = d.shownTexts().size();
        d.clickStartingWith(prefix);
        if (d.shownTexts().size() < before)
            d.clickStartingWith(prefix);
    };
    // A wind source and a ball, so that their rows and the gizmo's show too.
    open("Wind");
    d.click("add wind");
    editor::recordProjectEdit(d.state, false);
    open("Colliders");
    d.click("add ball");
    editor::recordProjectEdit(d.state, false);
    ASSERT_FALSE(project.wind.empty());
    ASSERT_FALSE(project.colliders.empty());
    // The wind source keyed on a path: its position row is the key at the current time's.
    core::Project keyed = project;
    const glm::vec3 at = keyed.wind.back().source.position;
    keyed.wind.back().source.path = {{0.0f, at}, {2.0f, at + glm::vec3(1.0f, 0.0f, 0.0f)}};
    editor::apply(d.state, editor::EditProject{.after = keyed});
    for (const std::string_view tool : {"brush (b)", "gizmo (g)"}) {
        d.click(tool);
        for (const std::string_view header :
             {"Tools", "Layers", "grass", "growth curves", "placement rules", "bending", "Surface",
              "Wind", "Colliders", "Light", "Cameras", "Render", "Snow"})
            open(header);
        open(project.wind.back().name);
        open(project.colliders.back().name);
        std::size_t checked = 0;
        std::vector<std::string> cut;
        for (const ui::ClippedShape& shape : d.frame().shapes) {
            const auto* t = std::get_if<ui::TextShape>(&shape.shape);
            // The side panel's own clip (its inner margin to the panel's width); a text box's
            // text clipped by its box scrolls in it, and the menu bar spans the window.
            if (t == nullptr || shape.clip.min.x > 10.0f || shape.clip.max.x < 300.0f ||
                shape.clip.max.x > 330.0f)
                continue;
            ++checked;
            const float right = t->pos.x + d.ctx.fonts().textSize(t->text, t->sizePt).x;
            if (right > shape.clip.max.x + 0.5f)
                cut.push_back("\"" + t->text + "\" ends at " + std::to_string(right) +
                              ", the panel at " + std::to_string(shape.clip.max.x));
        }
        EXPECT_GT(checked, 100u) << tool << ": " << checked << " texts, every section open";
        for (const std::string& text : cut)
            ADD_FAILURE() << tool << ": " << text;
    }
}

// A save the project file cannot hold is refused before anything is written: a Save As of a
// field whose blades project.json refuses left the mesh and its files in a new folder with no
// project.json.
TEST(EditorPanels, ASaveRefusedForAValueLeavesNoFolderBehind) {
    const ScratchFolder folder("editor-save-refused"), elsewhere("editor-save-refused-to");
    EditorDriver d(folder.path());
    core::Project tall = d.state.doc.project();
    tall.layers.front().scatter.blade.heightMax = 2.0f * core::MAX_BLADE_HEIGHT_M;
    editor::apply(d.state, editor::EditProject{.after = tall});
    const fs::path to = elsewhere.path() / "copy";
    EXPECT_FALSE(editor::saveTo(d.state, (to / "project.json").string()));
    EXPECT_FALSE(fs::exists(to)) << "no folder made, no map copied";
    const std::string& said = d.state.transient.message;
    EXPECT_TRUE(said.starts_with("not saved: ")) << said;
    EXPECT_NE(said.find("/layers/0/blade/height/1"), std::string::npos) << said;
    EXPECT_EQ(said.find("not saved", 1), std::string::npos) << "said once: " << said;
    EXPECT_TRUE(d.state.doc.dirty);
}

// A click on the status bar's message opens the Messages window even when the press lowers the
// viewport's quality: the "moving" note that then comes took the message's room on a field at
// rest in a narrow bar, and the release found no message to end the click on (seen in the
// window: clicks on "cannot grow the field: …" did nothing until the field moved anyway).
TEST(EditorPanels, AClickOnTheMessageOpensTheMessagesWhateverThePressChanges) {
    const ScratchFolder folder("editor-message-click");
    EditorDriver d(folder.path());
    ui::Input& input = d.input;
    editor::Transient& t = d.state.transient;
    t.message = "cannot grow the field: the limit is 20 million blades per scene";
    t.status.blades = 40000;
    t.status.physicsDevice = "cpu";
    t.status.physicsMs = 5.0;
    t.status.atRest = true;
    t.status.playing = true;
    d.frame();
    input.timeS += 10.0;  // no longer a fresh message, which the bar makes room for
    const std::string note = "MSAA off, 1/2 blades";
    const auto messageAt = [&](float width, const std::string& reduced) {
        input.screenRect = {{0.0f, 0.0f}, {width, 720.0f}};
        t.status.reduced = reduced;
        return textStarting(d.frame(), "cannot grow");
    };
    // The narrowest bar that shows the message at rest: with the note it has no room.
    float width = 600.0f;
    while (width < 1600.0f && !messageAt(width, ""))
        width += 2.0f;
    const std::optional<ui::TextShape> message = messageAt(width, "");
    ASSERT_TRUE(message.has_value()) << "no width shows the message";
    ASSERT_FALSE(messageAt(width, note).has_value()) << width << " points: the note leaves room";
    messageAt(width, "");
    input.pointerPos = message->pos + ui::Vec2(3.0f, 6.0f);
    d.frame();
    input.buttonDown[0] = true;
    d.frame();
    t.status.reduced = note;  // the press lowers the quality
    d.frame();
    input.buttonDown[0] = false;
    d.frame();
    EXPECT_TRUE(t.messagesWindow) << "at " << width << " points";
    EXPECT_EQ(t.messagePressedWidth, 0.0f) << "released";
}

// The brush's radius in the panel is the one its ring shows: before the user chooses one, the
// scene's default (a twentieth of its diagonal), where the panel read the stored 1.00 m; and
// the range follows the scene (a 60 km sphere's default, 5 km, was beyond the slider's 100 m).
TEST(EditorPanels, TheBrushRadiusShownIsTheOneThatPaints) {
    const ScratchFolder folder("editor-brush-radius");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};
    d.click("brush (b)");
    const float diagonal = glm::length(d.scene.bounds.size());
    const double radius = 0.05 * double(diagonal);
    const std::string shown = ui::numberText(radius, ui::significantDecimals(radius, 2));
    ASSERT_NE(shown, "1.00");
    EXPECT_TRUE(d.shownTexts().contains(shown)) << shown;
    EXPECT_FLOAT_EQ(d.state.view.paint.brush.radiusM, editor::brushRadius(d.state));
    EXPECT_FALSE(d.state.view.paint.radiusChosen) << "shown, not chosen: another scene resizes it";
    // A 60 km scene: its default radius, 5.2 km, within the slider's range.
    d.scene.bounds = {glm::vec3(-30000.0f), glm::vec3(30000.0f)};
    EXPECT_TRUE(d.shownTexts().contains("5196.15"));
    EXPECT_GE(editor::brushRadiusRange(d.state).max, 5196.15f);
}

// An added wind bends the field's blades visibly, whatever their size: its strength follows the
// blades (core::physicsScaleFor) and its core its reach. At the default 1 m/s it held the
// meadow's blades 2 cm off their rest tips, and a 60 km sphere's 3 km blades not at all.
TEST(EditorPanels, AnAddedWindBendsBladesOfAnySize) {
    const ScratchFolder folder("editor-wind-scale");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};
    const std::vector<core::WindDesc>& wind = d.state.doc.loaded.project.wind;
    const auto addWind = [&] {
        d.click("Wind (" + std::to_string(wind.size()) + ")");
        d.click("add wind");
        editor::recordProjectEdit(d.state, false);
        ASSERT_FALSE(wind.empty());
    };
    addWind();
    ASSERT_EQ(d.state.doc.project().layers.front().scatter.blade, core::BladeRanges{});
    EXPECT_FLOAT_EQ(wind.back().source.strength, 20.0f) << "the meadow's breeze on default blades";
    EXPECT_FLOAT_EQ(wind.back().source.coreRadiusM, 0.1f * wind.back().source.radiusM);
    // Blades ten times as tall (a mesh's field in kilometres is a thousand times): ten times the
    // strength. Two layers: their mean.
    core::Project tall = d.state.doc.project();
    tall.layers.front().scatter.blade.heightMin = 2.5f;
    tall.layers.front().scatter.blade.heightMax = 5.5f;
    tall.layers.push_back(tall.layers.front());
    tall.layers.back().name = "short";
    tall.layers.back().scatter.blade = core::BladeRanges{};
    editor::apply(d.state, editor::EditProject{.after = tall});
    d.click("Wind (1)");  // closed again: addWind opens it
    addWind();
    EXPECT_FLOAT_EQ(wind.back().source.strength, 20.0f * 0.5f * (10.0f + 1.0f));
}

// Undoing back to what was saved leaves nothing unsaved: the title's * goes and quitting asks
// nothing (before, any edit kept the project unsaved until the next save, its undo too).
TEST(EditorPanels, UndoingBackToTheSavedProjectLeavesNothingUnsaved) {
    const ScratchFolder folder("editor-save-point");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};
    editor::resetHistory(d.state);
    ASSERT_TRUE(editor::saveTo(d.state, (folder.path() / "project.json").string()));
    EXPECT_FALSE(d.state.doc.dirty);
    d.click("Wind (0)");
    d.click("add wind");
    editor::recordProjectEdit(d.state, false);
    EXPECT_TRUE(d.state.doc.dirty);
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_FALSE(d.state.doc.dirty) << "back at what the file holds";
    ASSERT_TRUE(editor::redo(d.state));
    EXPECT_TRUE(d.state.doc.dirty);
    ASSERT_TRUE(editor::undo(d.state));
    // An edit after the undo drops the redo branch; undoing it comes back to the saved state.
    d.click("add wind");
    editor::recordProjectEdit(d.state, false);
    EXPECT_TRUE(d.state.doc.dirty);
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_FALSE(d.state.doc.dirty);
}

// Issue 27 item 4: the brush's map exported from the paint tool's row (export…, the typed name,
// Enter) as it is now, painted and not yet saved; a rename to another layer's name is refused.
TEST(EditorPanels, TheBrushMapIsExportedAndATakenNameRefused) {
    const ScratchFolder folder("editor-export-map");
    EditorDriver d(folder.path());
    d.input.screenRect = {{0.0f, 0.0f}, {1280.0f, 4000.0f}};
    editor::resetHistory(d.state);
    d.state.view.tool = editor::ViewportTool::Paint;
    d.scene.layers[0].source.maps.density = core::makeConstantMap(64, 64, 0.25f);
    d.click("export…");
    d.typePathAndEnter((folder / "out.exr").string());
    auto written = core::loadMapImage(folder / "out.exr");
    ASSERT_TRUE(written.ok()) << d.state.transient.message;
    EXPECT_EQ(written->width, 64);
    EXPECT_FLOAT_EQ(written->texels[0], 0.25f);
    EXPECT_NE(d.state.transient.message.find("exported the density map"), std::string::npos);

    // A second layer, then the first renamed to its name: refused, the old name kept.
    d.click("add layer");
    editor::recordProjectEdit(d.state, false);
    ASSERT_EQ(d.state.doc.project().layers.size(), 2u);
    std::optional<ui::Vec2> label;  // the first layer's "name" label, right of its box
    for (const ui::ClippedShape& shape : d.frame().shapes)
        if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == "name" && !label)
            label = t->pos;
    ASSERT_TRUE(label.has_value());
    d.clickAt(*label + ui::Vec2(-80.0f, 6.0f));
    d.input.keys.push_back({ui::Key::A, {false, true, false}});
    d.frame();
    d.input.text = "grass 2";
    d.frame();
    d.input.keys.push_back({ui::Key::Enter, {}});
    d.frame();
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(d.state.doc.project().layers[0].name, "grass");
    EXPECT_NE(d.state.transient.message.find("another layer is named"), std::string::npos)
        << d.state.transient.message;
    // A free name is taken when Enter ends the entry, as one undo step.
    d.clickAt(*label + ui::Vec2(-80.0f, 6.0f));
    d.input.keys.push_back({ui::Key::A, {false, true, false}});
    d.frame();
    d.input.text = "clover";
    d.frame();
    EXPECT_EQ(d.state.doc.project().layers[0].name, "grass") << "not before Enter";
    d.input.keys.push_back({ui::Key::Enter, {}});
    d.frame();
    editor::recordProjectEdit(d.state, false);
    EXPECT_EQ(d.state.doc.project().layers[0].name, "clover");
    ASSERT_TRUE(editor::undo(d.state));
    EXPECT_EQ(d.state.doc.project().layers[0].name, "grass");
}

}  // namespace
}  // namespace grass::test

namespace grass::test {
namespace {

// At rest the window draws only its panels, about ten times a second (app/view_redraw.h): the
// status bar says so instead of a frame rate that would read as a slow viewport.
// A re-grow after an edit runs on a worker while the old field stays on screen; the viewport's
// badge says so and, below it, what the build does now (which layer grows): before, one text for
// seconds of work.
TEST(EditorPanels, TheRegrowBadgeFollowsTheBuildsStages) {
    ScratchFolder folder("regrow_badge");
    EditorDriver driver(folder.path());
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    driver.state.regrowJob = std::make_unique<editor::DocumentJob>(
        editor::DocumentAction::Regrow, fs::path(), "",
        [released](editor::DocumentJob&) -> Result<editor::GrownDocument> {
            released.wait();
            return makeError("test", "not grown");
        });
    const auto overlayTexts = [&] {
        driver.ctx.beginFrame(driver.input);
        editor::drawViewportOverlay(driver.ctx, {{300.0f, 20.0f}, {1280.0f, 680.0f}}, 1.0f,
                                    driver.state, core::OrbitCamera{}, editor::ViewportPointer{});
        std::vector<std::string> texts;
        for (const ui::ClippedShape& shape : driver.ctx.endFrame().shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape))
                texts.push_back(t->text);
        return texts;
    };
    std::vector<std::string> texts = overlayTexts();
    ASSERT_EQ(texts.size(), 1u);  // no stage yet
    EXPECT_EQ(texts[0].rfind("growing the field after the edit … ", 0), 0u) << texts[0];
    driver.state.regrowJob->setStage("growing layer \"grass\" (2 of 3)");
    texts = overlayTexts();
    ASSERT_EQ(texts.size(), 2u);
    EXPECT_EQ(texts[1], "growing layer \"grass\" (2 of 3)");
    release.set_value();
    driver.state.regrowJob.reset();
    EXPECT_TRUE(overlayTexts().empty());
}

TEST(EditorPanels, TheStatusBarSaysAtRestInsteadOfThePanelsFrameRate) {
    editor::FrameStatus status;
    status.fps = 9.6;
    EXPECT_EQ(editor::frameRateText(status), "10 fps");
    status.atRest = true;
    EXPECT_EQ(editor::frameRateText(status), "at rest");
    status.playing = true;  // a field without wind plays: the clock moves, the picture does not
    EXPECT_EQ(editor::frameRateText(status), "nothing moves");
}

}  // namespace
}  // namespace grass::test
