#include "app/panels.h"

#include "app/autosave.h"
#include "app/edit_actions.h"
#include "app/mesh_import.h"
#include "app/project_file_watch.h"
#include "app/status_figures.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "ui/menu.h"
#include "ui/text_edit.h"
#include "ui/text_wrap.h"
#include "ui/ui.h"
#include "ui/window.h"
#include "util/content_digest.h"

namespace grass::editor {

namespace {

// Height of the status bar under the viewport, points.
constexpr float STATUS_BAR_HEIGHT = 26.0f;
// How long a new status message comes before the figures (statusBar).
constexpr double FRESH_MESSAGE_S = 6.0;
constexpr float SIDE_PANEL_WIDTH = 330.0f;

// File › Open Recent: the projects opened or saved last, newest first; a project whose file
// is gone is left out (opening it would only fail).
void recentItems(ui::Ui& m, EditorState& s) {
    namespace fs = std::filesystem;
    std::vector<fs::path> shown;
    for (const fs::path& file : s.transient.recent.projects) {
        std::error_code ec;
        if (fs::is_regular_file(file, ec))
            shown.push_back(file);
    }
    if (shown.empty())
        return;
    m.coloredLabel("Open Recent", m.style().textWeak);
    for (const fs::path& file : shown) {
        const fs::path folder = file.parent_path();
        const std::string name = shownFileName(file);
        // The label is the item's id too: the full path keeps two "meadow"s apart.
        if (ui::menuItem(m, "   " + name + "##" + file.string(), folder.parent_path().string()))
            askLeave(s, LeaveAction::Open, file.string());
    }
}

void fileMenu(ui::Ui& bar, EditorState& s) {
    ui::menu(bar, "File", [&](ui::Ui& m) {
        if (ui::menuItem(m, "New", "Ctrl+N"))
            askLeave(s, LeaveAction::New);
        if (ui::menuItem(m, "New from mesh…"))
            openBrowser(s, BrowsePurpose::NewFromMesh);
        if (ui::menuItem(m, "Open…", "Ctrl+O"))
            openBrowser(s, BrowsePurpose::OpenProject);
        recentItems(m, s);
        m.separator();
        if (ui::menuItem(m, "Save", "Ctrl+S"))
            saveOrAsk(s);
        if (ui::menuItem(m, "Save As…", "Ctrl+Shift+S"))
            openBrowser(s, BrowsePurpose::SaveProject);
        m.separator();
        if (ui::menuItem(m, "Import mesh…"))
            openBrowser(s, BrowsePurpose::ImportMesh);
        if (ui::menuItem(m, "Import map image…"))
            openBrowser(s, BrowsePurpose::ImportMap);
        m.separator();
        if (ui::menuItem(m, "Export…")) {
            s.transient.exportDialog = true;
            if (s.transient.exportDir.empty())
                s.transient.exportDir = (outputFolder(s) / "export").string();
        }
        if (ui::menuItem(m, "Save screenshot"))
            s.screenshotRequested = freshPicturePath(s, "screenshot", ".png");
        if (ui::menuItem(m, "Save turntable (24 views)"))
            s.turntableRequested = freshPicturePath(s, "turntable", ".png");
        m.separator();
        if (ui::menuItem(m, "Quit"))
            askQuit(s);
    });
}

void editMenu(ui::Ui& bar, EditorState& s) {
    ui::menu(bar, "Edit", [&](ui::Ui& m) {
        // Greyed with nothing to undo or redo; the shortcuts in the column the File menu uses.
        const core::Edit* next = s.doc.history.nextUndo();
        if (ui::menuItem(m, next ? "Undo " + next->label : std::string("Undo"), "Ctrl+Z",
                         next != nullptr))
            undo(s);
        const core::Edit* again = s.doc.history.nextRedo();
        if (ui::menuItem(m, again ? "Redo " + again->label : std::string("Redo"), "Ctrl+Shift+Z",
                         again != nullptr))
            redo(s);
    });
}

// Carries out the confirmed (or harmless) leave action for the Editor.
void leave(EditorState& s) {
    s.transient.quitDialog = false;
    switch (s.transient.leaveAction) {
        case LeaveAction::Quit:
            s.quitRequested = true;
            break;
        case LeaveAction::New:
            s.newRequested = true;
            break;
        case LeaveAction::Open:
            s.openRequested = s.transient.leaveOpenPath;
            break;
        case LeaveAction::NewFromMesh:
            s.newFromMeshRequested = s.transient.leaveOpenPath;
            break;
    }
}

void quitDialogWindow(ui::Context& ctx, EditorState& s) {
    if (!s.transient.quitDialog)
        return;
    const ui::Rect screen = ctx.screenRect();
    ui::window(
        ctx, "Unsaved changes", &s.transient.quitDialog,
        [&](ui::Ui& ui) {
            ui.label("The project has unsaved changes.");
            const bool quitting = s.transient.leaveAction == LeaveAction::Quit;
            ui.horizontal([&](ui::Ui& row) {
                if (row.button(quitting ? "Save and quit" : "Save first")
                        .onHoverText("Save the project (Ctrl+S), then go on")
                        .clicked()) {
                    if (s.doc.loaded.file.empty()) {
                        openBrowser(s, BrowsePurpose::SaveProject);  // no file yet: ask where first
                        s.transient.quitDialog = false;
                    } else if (saveTo(s, s.doc.loaded.file.string())) {
                        askLeave(s, s.transient.leaveAction, s.transient.leaveOpenPath);
                    }
                }
                // The project stays dirty: if opening the other one fails, the edits are
                // still there and still count as unsaved.
                if (row.button(quitting ? "Quit without saving" : "Discard changes")
                        .onHoverText("Drop the unsaved changes and go on")
                        .clicked())
                    leave(s);
                if (row.button("Cancel").onHoverText("Stay with the project as it is").clicked())
                    s.transient.quitDialog = false;
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 200.0f, screen.centre().y - 50.0f},
                              {400.0f, 90.0f}));
}

void statusBar(ui::Context& ctx, ui::Rect rect, EditorState& s) {
    const ui::Style& style = ctx.style();
    paintBar(ctx, rect);
    const render::FrameTimings& t = s.transient.status.timings;
    const bool stems = s.doc.loaded.project.render.technique == core::GrassTechnique::Growth;
    // The snow map's time shows only while snow lies (its pass runs only then).
    char snow[32] = "";
    if (t.snowMs > 0.0)
        std::snprintf(snow, sizeof snow, " · snow %.2f", t.snowMs);
    // The billboards' or stem sets' time only when the technique draws them: the line must fit
    // beside the "moving:" note of a reduced picture.
    const core::GrassTechnique technique = s.doc.loaded.project.render.technique;
    char far[48] = "";
    if (stems || technique == core::GrassTechnique::Billboards ||
        technique == core::GrassTechnique::Hybrid)
        std::snprintf(far, sizeof far, " · %s %.2f", stems ? "stem sets" : "billboards",
                      stems ? t.stemSetMs : t.billboardMs);
    // Where the live physics runs, and on the CPU the time of the frame's steps: early in the
    // line, so it shows while playing, when it matters.
    char physics[64] = "";
    if (!s.transient.status.physicsDevice.empty()) {
        if (s.transient.status.physicsMs > 0.0)
            std::snprintf(physics, sizeof physics, "physics %s %.1f ms",
                          s.transient.status.physicsDevice.c_str(), s.transient.status.physicsMs);
        else
            std::snprintf(physics, sizeof physics, "physics %s",
                          s.transient.status.physicsDevice.c_str());
    }
    char blades[64], passes[192], uiTime[32];
    std::snprintf(blades, sizeof blades, "%zu blades · %zu drawn", s.transient.status.blades,
                  stems ? t.stemSetsDrawn : t.cull.drawn);
    std::snprintf(passes, sizeof passes, "cull %.2f · opaque %.2f · grass %.2f%s%s ms", t.cullMs,
                  t.meshMs, t.grassMs, far, snow);
    std::snprintf(uiTime, sizeof uiTime, "UI %.2f ms", s.transient.status.uiMs);
    // Left out first where the window is narrow: the UI's time, then the passes', the physics
    // device, the frame rate; the blade counts stay.
    const std::vector<StatusFigure> figures{{blades, 5},
                                            {physics, 2},
                                            {passes, 1},
                                            {uiTime, 0},
                                            {frameRateText(s.transient.status), 3}};
    ui::Ui ui(ctx, {rect.min + ui::Vec2(8.0f, 2.0f), rect.max}, ui::Layer::Panels);
    ui.horizontal([&](ui::Ui& row) {
        // The message first ("saved", "imported", a failed save in warning orange, so that it
        // reads as something to act on): after the figures it lay past the window's edge at
        // 1280 px whenever the picture was reduced, which is always while playing. Cut to the
        // room the figures leave, so they stay whole (cut to half the bar, a new project's
        // message pushed the grass time off a 1280 px window); a failed save keeps half the bar
        // whatever the figures; a message with no room left is not shown (Help › Messages has
        // it). A click shows every message whole.
        // For its first seconds a message comes before the figures too: at 1280 px a playing
        // field's "moving: …" and "physics behind" notes left it no room, so Ctrl+S said nothing
        // at all. Then the notes are said short and the figures make way, least wanted first;
        // the message takes up to half the bar.
        const auto width = [&](std::string_view line) {
            return ctx.fonts().textSize(line, style.textSizePt).x;
        };
        const bool freshMessage =
            !s.transient.message.empty() &&
            ctx.input().timeS - s.transient.messageLoggedAtS < FRESH_MESSAGE_S;
        const float messageWanted =
            s.transient.messageIsSaveError
                ? 0.5f * rect.width()
                : (freshMessage ? std::min(width(s.transient.message + "   "), 0.5f * rect.width())
                                : 0.0f);
        std::string movingNote = s.transient.status.reduced.empty()
                                     ? ""
                                     : "moving: " + s.transient.status.reduced + "   ";
        // The machine cannot step the physics as fast as time passes: said in orange, before the
        // figures (after them it was the first thing a narrow window cut).
        char behindNote[96] = "";
        if (const double dropped = s.transient.status.physicsDroppedS; dropped > 0.0)
            std::snprintf(behindNote, sizeof behindNote, "physics behind: skipping %.1f s per s   ",
                          dropped);
        // Less the bar's inset, the message's trailing spaces and the row's spacing after each
        // item.
        const int items = 2 + (movingNote.empty() ? 0 : 1) + (behindNote[0] != '\0' ? 1 : 0);
        const float margin = 8.0f + width("   ") + float(items) * style.itemSpacing.x;
        // The notes are said short where they, the blade counts and the message wanted leave
        // no room (a new message, or a narrow window: at 900 points "physics behind" ran off the
        // window's edge with the blade counts after it); with no room even then the "moving"
        // note goes, which the viewport's badge says too.
        const auto notesDoNotFit = [&](float message) {
            return width(movingNote + behindNote + figures.front().text) >
                   rect.width() - margin - message;
        };
        if (!movingNote.empty() && notesDoNotFit(messageWanted))
            movingNote = "moving   ";
        if (behindNote[0] != '\0' && notesDoNotFit(messageWanted))
            std::snprintf(behindNote, sizeof behindNote, "physics behind   ");
        if (notesDoNotFit(0.0f))
            movingNote.clear();
        // The blade counts stay whole whatever the message.
        const float messageFirst = std::clamp(
            rect.width() - margin - width(movingNote + behindNote + figures.front().text), 0.0f,
            messageWanted);
        const float figureRoom = rect.width() - margin - messageFirst;
        const std::string text =
            fitStatusFigures(figures, figureRoom - width(movingNote + behindNote), width);
        const float figuresWidth = width(movingNote + behindNote + text);
        float room = std::max(messageFirst, rect.width() - margin - figuresWidth);
        constexpr float LEAST_MESSAGE_WIDTH = 80.0f;
        // While the message is pressed it keeps the width it was pressed at: the press itself
        // lowers the viewport's quality, whose "moving" note then took the message's room (a
        // field at rest, a narrow bar), and the release found no message to end the click on.
        const ui::Id messageId = row.makeId("message");
        const bool messagePressed =
            ctx.activeId() == messageId && s.transient.messagePressedWidth > 0.0f;
        if (messagePressed)
            room = std::max(room, s.transient.messagePressedWidth);
        if (!s.transient.message.empty() && (room >= LEAST_MESSAGE_WIDTH || messagePressed)) {
            const std::string shownText =
                ui::elideText(ctx.fonts(), style.textSizePt, s.transient.message, room);
            const bool warning =
                s.transient.messageIsSaveError || s.transient.message == s.transient.warningMessage;
            const ui::Response shown = row.coloredLabel(
                shownText + "   ", warning ? ui::Color32::rgb(255, 150, 60) : style.textWeak);
            ui::Response click = row.interact(shown.rect(), messageId, ui::Sense::clickOnly());
            s.transient.messagePressedWidth =
                ctx.activeId() == messageId && ctx.input().buttonDown[0] ? room : 0.0f;
            if (click.onHoverText("Click to see every message in full").clicked())
                s.transient.messagesWindow = true;
        }
        // The viewport draws less while the user interacts (adaptive quality): say what.
        if (!movingNote.empty())
            row.coloredLabel(movingNote, ui::Color32::rgb(120, 190, 255));
        if (behindNote[0] != '\0')
            row.coloredLabel(behindNote, ui::Color32::rgb(255, 150, 60));
        row.label(text);
    });
}

}  // namespace

std::filesystem::path outputFolder(const EditorState& s) {
    namespace fs = std::filesystem;
    std::vector<fs::path> candidates;
    // A recovered never-saved project's folder is its autosave slot, hidden and removed on save.
    if (!s.doc.loaded.folder.empty() && !isUnsavedSlot(s.doc.loaded.folder))
        candidates.push_back(s.doc.loaded.folder);
    std::error_code ec;
    if (fs::path working = fs::current_path(ec); !ec)
        candidates.push_back(working);
    if (const char* home = std::getenv("HOME"); home && *home == '/')
        candidates.push_back(home);
    // Absolute: a project opened as `grass-editor meadow` has the relative folder "meadow", and
    // the export window, which reads a relative folder as inside the project's, turned its
    // default "meadow/export" into meadow/meadow/export.
    for (const fs::path& folder : candidates)
        if (fs::is_directory(folder, ec) && ::access(folder.c_str(), W_OK) == 0)
            return fs::absolute(folder, ec).lexically_normal();
    return candidates.empty() ? fs::path(".") : candidates.front();  // its error says why
}

std::string freshPicturePath(const EditorState& s, const std::string& stem, const std::string& extension) {
    namespace fs = std::filesystem;
    const fs::path folder = outputFolder(s);
    for (int n = 1;; ++n) {
        const std::string name = stem + "-" + std::to_string(n);
        if (!fs::exists(folder / (name + extension)) &&
            !fs::exists(folder / (name + "_0000" + extension)))
            return (folder / (name + extension)).string();
    }
}

std::string frameRateText(const FrameStatus& status) {
    if (status.atRest)
        return status.playing ? "nothing moves" : "at rest";
    char text[32];
    std::snprintf(text, sizeof text, "%.0f fps", status.fps);
    return text;
}

render::RenderOptions viewRenderOptions(const EditorState& s) {
    render::RenderOptions options = render::renderOptionsFor(s.doc.loaded.project, s.view.softwareRenderer);
    render::CullSettings& cull = options.cull;
    cull.orientation = cull.orientation && s.view.overrides.orientation;
    cull.frustum = cull.frustum && s.view.overrides.frustum;
    cull.distance = cull.distance && s.view.overrides.distance;
    cull.occlusion = cull.occlusion && s.view.overrides.occlusion;
    // While the user interacts, the adaptive quality's rung (MSAA and resolution are the
    // viewport's target, chosen by the Editor from the same rung).
    const core::Reduction& r = s.view.quality.reduction();
    cull.keepEvery = r.keepEvery;
    // Fewer blades, each wider: √N keeps much of the coverage without turning blades to ribbons.
    options.widthScale = std::sqrt(float(r.keepEvery));
    // 0 would mean "full detail everywhere": the fewest segments are a lodDistance near 0.
    if (r.lodDistanceScale < 1.0f && cull.lodDistanceM > 0.0f)
        cull.lodDistanceM = std::max(cull.lodDistanceM * r.lodDistanceScale, 1e-3f);
    return options;
}

bool saveTo(EditorState& s, const std::string& file, bool replaceChangedFile) {
    namespace fs = std::filesystem;
    const fs::path path(file);
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    // Another program (a text editor, a second editor window, a checkout, an image editor)
    // changed the project's file, or a map painted here, since it was read or written here:
    // replacing it silently would lose that work. A file gone from disk has nothing to lose.
    if (!replaceChangedFile) {
        std::vector<std::string> changed;
        if (s.doc.loaded.fileDigest && !s.doc.loaded.file.empty() &&
            fs::equivalent(path, s.doc.loaded.file, ec)) {
            if (const std::optional<std::uint64_t> now = fileDigest(path);
                now && *now != *s.doc.loaded.fileDigest)
                changed.push_back(path.string());
        }
        const bool projectFileChanged = !changed.empty();
        // Saved elsewhere, the painted maps go to new files.
        if (!s.doc.loaded.folder.empty() && fs::equivalent(folder, s.doc.loaded.folder, ec))
            for (const fs::path& map : paintedMapsChangedOnDisk(s))
                changed.push_back(map.string());
        if (!changed.empty()) {
            std::string& said = s.transient.changedOnDiskSaid;
            said = changed.front();
            for (std::size_t i = 1; i < changed.size(); ++i)
                said += (i + 1 == changed.size() ? " and " : ", ") + changed[i];
            said += std::string(changed.size() > 1 ? " were" : " was") +
                    " changed by another program since it was opened or saved here";
            s.transient.message = "not saved: " + said;
            s.transient.changedOnDiskProjectFile = projectFileChanged;
            s.transient.loggedMessage.clear();
            s.transient.changedOnDisk = true;
            return false;
        }
    }
    // A refused save says what failed and the way out (a read-only folder, a full disk).
    const auto refuse = [&](const Error& error) {
        s.transient.message =
            "not saved: " + error.str() + " (File > Save As... saves the project elsewhere)";
        s.transient.messageIsSaveError = true;
        return false;
    };
    // A project the file would not hold is refused before its folder is made and its files
    // copied there (a Save As of a field the format refused left the mesh and its UV atlas in
    // a new folder without a project.json).
    if (auto saves = core::checkProjectSaves(s.doc.loaded.project, path); !saves)
        return refuse(saves.error());
    fs::create_directories(folder, ec);
    // Asset paths are relative to the project's folder: saved elsewhere, the project must take
    // its files along (mesh, maps, textures), or it would name files that are not there.
    // Files already at the destination are kept; the copy happens before project.json is
    // written, so a failure leaves the old project as it was and no new one naming missing files.
    if (!s.doc.loaded.folder.empty() && !fs::equivalent(s.doc.loaded.folder, folder, ec)) {
        // A .gltf brings the buffers and images it names along (mesh_import.h).
        for (const std::string& asset : core::projectAssetPaths(s.doc.loaded.project)) {
            if (auto copied = copyAssetFiles(s.doc.loaded.folder / asset, folder / asset); !copied)
                return refuse(copied.error());
        }
    }
    if (auto maps = savePaintedMaps(s, folder); !maps)
        return refuse(maps.error());
    if (auto saved = core::saveProject(s.doc.loaded.project, path); !saved)
        return refuse(saved.error());
    // Saved: the autosave side files (of where the project was, or of a never-saved project in
    // the user's unsaved folder) have nothing left to recover.
    removeAutosave(s.doc.loaded);
    removeUnsavedSlot(s.doc.unsavedSlot);
    s.doc.loaded.file = path;
    s.doc.loaded.folder = folder;
    s.doc.loaded.fileDigest = fileDigest(path);  // what a later Save expects to find
    s.assetsWrittenHere = true;                  // the painted maps: no change by another program
    s.transient.changedOnDisk = false;
    s.doc.dirty = false;
    s.doc.history.markSaved();
    rememberRecent(s, path);
    s.transient.message = "saved " + path.string();
    s.transient.loggedMessage.clear();  // a second save says so again
    s.transient.messageIsSaveError = false;
    return true;
}

void paintBar(ui::Context& ctx, ui::Rect rect) {
    const ui::Style& style = ctx.style();
    ui::Painter bg = ctx.painter(ui::Layer::Panels, rect);
    bg.rect(rect, 0.0f, style.panelFill);
    bg.line({rect.min.x, rect.min.y + 0.5f}, {rect.max.x, rect.min.y + 0.5f},
            {1.0f, style.separator});
    ctx.registerArea(rect);
}

void saveOrAsk(EditorState& s) {
    if (s.doc.loaded.file.empty())
        openBrowser(s, BrowsePurpose::SaveProject);
    else
        saveTo(s, s.doc.loaded.file.string());
}

void askLeave(EditorState& s, LeaveAction action, const std::string& openPath) {
    s.transient.leaveAction = action;
    s.transient.leaveOpenPath = openPath;
    s.transient.quitDialog = s.doc.dirty;
    if (!s.doc.dirty)
        leave(s);
}

void askQuit(EditorState& s) {
    askLeave(s, LeaveAction::Quit);
}

ui::Rect buildPanels(ui::Context& ctx, EditorState& s) {
    ui::topBar(ctx, "menu", [&](ui::Ui& top) {
        ui::menuBar(top, [&](ui::Ui& bar) {
            fileMenu(bar, s);
            editMenu(bar, s);
            helpMenu(bar, s);
            const std::string title =
                s.doc.loaded.project.name + (s.doc.dirty ? " *" : "") +
                (s.doc.loaded.file.empty() ? "  (not saved)" : "  — " + s.doc.loaded.file.string());
            bar.coloredLabel(title, ctx.style().textWeak);
        });
    });
    // The side panel's widgets edit a working copy of the project; what they changed becomes one
    // command (the menus above and the windows below act on the document itself).
    s.transient.draft = {s.doc.project(), false};
    ui::sidePanel(ctx, "side", ui::Side::Left, SIDE_PANEL_WIDTH, [&](ui::Ui& panel) {
        // Layers with open headers are taller than any screen: the whole panel scrolls.
        panel.scrollArea("scroll", panel.availableRect().height(), [&](ui::Ui& ui) {
            ui.horizontal([&](ui::Ui& row) {
                bool committed = false;
                ui::textEdit(row, "project##name", s.transient.draft.project.name, 200.0f,
                             &committed)
                    .onHoverText("The project's name (project.json \"name\")");
            });
            ui.separator();
            toolSection(ui, s);
            layerSection(ui, s);
            surfaceSection(ui, s);
            windSection(ui, s);
            colliderSection(ui, s);
            lightSection(ui, s);
            cameraSection(ui, s);
            renderSection(ui, s);
            snowSection(ui, s);
        });
    });
    if (PanelDraft& draft = s.transient.draft; draft.project != s.doc.project())
        apply(s, EditProject{.after = std::move(draft.project),
                             .effect = draft.regrow ? EditEffect::Regrow : EditEffect::Live,
                             .ongoing = ctx.activeId().value != 0});
    ui::Rect central = ui::centralRect(ctx);
    const ui::Rect bar{{central.min.x, central.max.y - STATUS_BAR_HEIGHT}, central.max};
    logMessage(s, ctx.input().timeS);
    statusBar(ctx, bar, s);
    const ui::Rect strip{{central.min.x, bar.min.y - TIMELINE_STRIP_HEIGHT}, {central.max.x, bar.min.y}};
    timelineStrip(ctx, strip, s);
    central.max.y = strip.min.y;
    loadingWindow(ctx, central, s);
    fileBrowserWindow(ctx, s);
    quitDialogWindow(ctx, s);
    changedOnDiskWindow(ctx, s);
    exportWindow(ctx, s);
    shortcutsWindow(ctx, s);
    messagesWindow(ctx, s);
    aboutWindow(ctx, s);
    recoveryWindow(ctx, s);
    return central;
}

}  // namespace grass::editor
