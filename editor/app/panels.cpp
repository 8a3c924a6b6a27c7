#include "app/panels.h"

#include "app/autosave.h"
#include "app/edit_actions.h"

#include <cstdio>
#include <filesystem>

#include "ui/menu.h"
#include "ui/text_edit.h"
#include "ui/ui.h"
#include "ui/window.h"

namespace grass::editor {

namespace {

// Height of the status bar under the viewport, points.
constexpr float STATUS_BAR_HEIGHT = 26.0f;
constexpr float SIDE_PANEL_WIDTH = 330.0f;

// A folder, or a file that does not end in .json, means <path>/project.json: projects are
// folders (assets are relative to them), so that is what artists type.
std::filesystem::path projectFileFor(const std::string& path) {
    std::filesystem::path p(path);
    if (p.extension() == ".json")
        return p;
    return p / "project.json";
}

// <project folder>/<stem>-<n><extension> with the first n whose file (and turntable frames)
// do not exist yet, so repeated shots never overwrite each other.
std::string freshPath(const EditorState& s, const std::string& stem, const std::string& extension) {
    namespace fs = std::filesystem;
    const fs::path folder = s.loaded.folder.empty() ? fs::current_path() : s.loaded.folder;
    for (int n = 1;; ++n) {
        const std::string name = stem + "-" + std::to_string(n);
        if (!fs::exists(folder / (name + extension)) &&
            !fs::exists(folder / (name + "_0000" + extension)))
            return (folder / (name + extension)).string();
    }
}

void fileMenu(ui::Ui& bar, EditorState& s) {
    ui::menu(bar, "File", [&](ui::Ui& m) {
        if (ui::menuItem(m, "New"))
            askLeave(s, LeaveAction::New);
        if (ui::menuItem(m, "Open…")) {
            s.fileDialog = FileDialog::Open;
            s.pathText = s.loaded.folder.string();
        }
        if (ui::menuItem(m, "Save")) {
            if (s.loaded.file.empty()) {
                s.fileDialog = FileDialog::SaveAs;
                s.pathText.clear();
            } else {
                saveTo(s, s.loaded.file.string());
            }
        }
        if (ui::menuItem(m, "Save As…")) {
            s.fileDialog = FileDialog::SaveAs;
            s.pathText = s.loaded.file.string();
        }
        m.separator();
        if (ui::menuItem(m, "Export…")) {
            s.exportDialog = true;
            if (s.exportDir.empty())
                s.exportDir = (s.loaded.folder / "export").string();
        }
        if (ui::menuItem(m, "Save screenshot"))
            s.screenshotRequested = freshPath(s, "screenshot", ".png");
        if (ui::menuItem(m, "Save turntable (24 views)"))
            s.turntableRequested = freshPath(s, "turntable", ".png");
        m.separator();
        if (ui::menuItem(m, "Quit"))
            askQuit(s);
    });
}

void editMenu(ui::Ui& bar, EditorState& s) {
    ui::menu(bar, "Edit", [&](ui::Ui& m) {
        const core::Edit* next = s.history.nextUndo();
        if (ui::menuItem(m, next ? "Undo " + next->label + "   Ctrl+Z" : std::string("Undo")) &&
            next)
            undo(s);
        const core::Edit* again = s.history.nextRedo();
        if (ui::menuItem(
                m, again ? "Redo " + again->label + "   Ctrl+Shift+Z" : std::string("Redo")) &&
            again)
            redo(s);
    });
}

// The path entry window of Open… and Save As… (there is no native file dialog).
void fileDialogWindow(ui::Context& ctx, EditorState& s) {
    if (s.fileDialog == FileDialog::None)
        return;
    const bool opening = s.fileDialog == FileDialog::Open;
    bool open = true;
    const ui::Rect screen = ctx.screenRect();
    const ui::Rect defaultRect = ui::Rect::fromMinSize(
        {screen.centre().x - 230.0f, screen.centre().y - 60.0f}, {460.0f, 120.0f});
    ui::window(
        ctx, opening ? "Open project" : "Save project as", &open,
        [&](ui::Ui& ui) {
            ui.label(opening ? "Project folder or .json file:" : "Save to folder or .json file:");
            // The text edit consumes Enter, so look before it: Enter (not a commit by focus loss,
            // e.g. a click on Cancel) confirms the dialog.
            const bool enter = ctx.keyPressed(ui::Key::Enter);
            bool committed = false;
            ui::textEdit(ui, "##path", s.pathText, ui.availableWidth() - 8.0f, &committed);
            ui.horizontal([&](ui::Ui& row) {
                const bool go =
                    row.button(opening ? "Open" : "Save").clicked() || (committed && enter);
                if (go && !s.pathText.empty()) {
                    if (opening)
                        askLeave(s, LeaveAction::Open, s.pathText);
                    else
                        saveTo(s, projectFileFor(s.pathText).string());
                    s.fileDialog = FileDialog::None;
                }
                if (row.button("Cancel").clicked())
                    s.fileDialog = FileDialog::None;
            });
        },
        defaultRect);
    if (!open)
        s.fileDialog = FileDialog::None;
}

// Carries out the confirmed (or harmless) leave action for main.cpp.
void leave(EditorState& s) {
    s.quitDialog = false;
    switch (s.leaveAction) {
        case LeaveAction::Quit:
            s.quitRequested = true;
            break;
        case LeaveAction::New:
            s.newRequested = true;
            break;
        case LeaveAction::Open:
            s.openRequested = s.leaveOpenPath;
            break;
    }
}

void quitDialogWindow(ui::Context& ctx, EditorState& s) {
    if (!s.quitDialog)
        return;
    const ui::Rect screen = ctx.screenRect();
    ui::window(
        ctx, "Unsaved changes", &s.quitDialog,
        [&](ui::Ui& ui) {
            ui.label("The project has unsaved changes.");
            const bool quitting = s.leaveAction == LeaveAction::Quit;
            ui.horizontal([&](ui::Ui& row) {
                if (row.button(quitting ? "Save and quit" : "Save first").clicked()) {
                    if (s.loaded.file.empty()) {
                        s.fileDialog = FileDialog::SaveAs;  // no file yet: ask where first
                        s.quitDialog = false;
                    } else if (saveTo(s, s.loaded.file.string())) {
                        askLeave(s, s.leaveAction, s.leaveOpenPath);
                    }
                }
                // The project stays dirty: if opening the other one fails, the edits are
                // still there and still count as unsaved.
                if (row.button(quitting ? "Quit without saving" : "Discard changes").clicked())
                    leave(s);
                if (row.button("Cancel").clicked())
                    s.quitDialog = false;
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 200.0f, screen.centre().y - 50.0f},
                              {400.0f, 90.0f}));
}

void statusBar(ui::Context& ctx, ui::Rect rect, const EditorState& s) {
    const ui::Style& style = ctx.style();
    ui::Painter bg = ctx.painter(ui::Layer::Panels, rect);
    bg.rect(rect, 0.0f, style.panelFill);
    bg.line({rect.min.x, rect.min.y + 0.5f}, {rect.max.x, rect.min.y + 0.5f},
            {1.0f, style.separator});
    ctx.registerArea(rect);
    const render::FrameTimings& t = s.status.timings;
    const bool stems = s.loaded.project.render.technique == core::GrassTechnique::Growth;
    // The snow map's time shows only while snow lies (its pass runs only then).
    char snow[32] = "";
    if (t.snowMs > 0.0)
        std::snprintf(snow, sizeof snow, " · snow %.2f", t.snowMs);
    char text[320];
    std::snprintf(text, sizeof text,
                  "%zu blades · %zu drawn   cull %.2f · opaque %.2f · grass %.2f · %s %.2f%s ms"
                  "   UI %.2f ms   %.0f fps",
                  s.status.blades, stems ? t.stemSetsDrawn : t.cull.drawn, t.cullMs, t.meshMs,
                  t.grassMs, stems ? "stem sets" : "billboards",
                  stems ? t.stemSetMs : t.billboardMs, snow, s.status.uiMs, s.status.fps);
    ui::Ui ui(ctx, {rect.min + ui::Vec2(8.0f, 2.0f), rect.max}, ui::Layer::Panels);
    ui.horizontal([&](ui::Ui& row) {
        row.label(text);
        // A failed save in warning orange, so that it reads as something to act on.
        if (!s.message.empty())
            row.coloredLabel("   " + s.message, s.messageIsSaveError
                                                    ? ui::Color32::rgb(255, 150, 60)
                                                    : style.textWeak);
    });
}

}  // namespace

render::RenderOptions viewRenderOptions(const EditorState& s) {
    render::RenderOptions options = render::renderOptionsFor(s.loaded.project, s.softwareRenderer);
    render::CullSettings& cull = options.cull;
    cull.orientation = cull.orientation && s.view.orientation;
    cull.frustum = cull.frustum && s.view.frustum;
    cull.distance = cull.distance && s.view.distance;
    cull.occlusion = cull.occlusion && s.view.occlusion;
    return options;
}

bool saveTo(EditorState& s, const std::string& file) {
    namespace fs = std::filesystem;
    const fs::path path(file);
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    fs::create_directories(folder, ec);
    // Asset paths are relative to the project's folder: saved elsewhere, the project must take
    // its files along (mesh, maps, textures), or it would name files that are not there.
    // Files already at the destination are kept; the copy happens before project.json is
    // written, so a failure leaves the old project as it was and no new one naming missing files.
    if (!s.loaded.folder.empty() && !fs::equivalent(s.loaded.folder, folder, ec)) {
        for (const std::string& asset : core::projectAssetPaths(s.loaded.project)) {
            const fs::path from = s.loaded.folder / asset, to = folder / asset;
            if (!fs::exists(from) || fs::exists(to))
                continue;
            fs::create_directories(to.parent_path(), ec);
            if (!fs::copy_file(from, to, ec)) {
                s.message = "not saved: " + to.string() + ": cannot copy " + from.string() + " (" +
                            ec.message() + ")";
                s.messageIsSaveError = true;
                return false;
            }
        }
    }
    if (auto maps = savePaintedMaps(s, folder); !maps) {
        s.message = "not saved: " + maps.error().str();
        s.messageIsSaveError = true;
        return false;
    }
    if (auto saved = core::saveProject(s.loaded.project, path); !saved) {
        s.message = "not saved: " + saved.error().str();
        s.messageIsSaveError = true;
        return false;
    }
    // Saved: the autosave side files (of where the project was) have nothing left to recover.
    removeAutosave(s.loaded);
    s.loaded.file = path;
    s.loaded.folder = folder;
    s.dirty = false;
    s.message = "saved " + path.string();
    s.messageIsSaveError = false;
    return true;
}

void askLeave(EditorState& s, LeaveAction action, const std::string& openPath) {
    s.leaveAction = action;
    s.leaveOpenPath = openPath;
    s.quitDialog = s.dirty;
    if (!s.dirty)
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
            const std::string title =
                s.loaded.project.name + (s.dirty ? " *" : "") +
                (s.loaded.file.empty() ? "  (not saved)" : "  — " + s.loaded.file.string());
            bar.coloredLabel(title, ctx.style().textWeak);
        });
    });
    ui::sidePanel(ctx, "side", ui::Side::Left, SIDE_PANEL_WIDTH, [&](ui::Ui& panel) {
        // Layers with open headers are taller than any screen: the whole panel scrolls.
        panel.scrollArea("scroll", panel.availableRect().height(), [&](ui::Ui& ui) {
            ui.horizontal([&](ui::Ui& row) {
                bool committed = false;
                std::string name = s.loaded.project.name;
                ui::textEdit(row, "project##name", name, 200.0f, &committed);
                if (name != s.loaded.project.name) {
                    s.loaded.project.name = name;
                    s.dirty = true;
                }
            });
            ui.separator();
            toolSection(ui, s);
            timelineSection(ui, s);
            layerSection(ui, s);
            windSection(ui, s);
            colliderSection(ui, s);
            renderSection(ui, s);
            snowSection(ui, s);
        });
    });
    ui::Rect central = ui::centralRect(ctx);
    const ui::Rect bar{{central.min.x, central.max.y - STATUS_BAR_HEIGHT}, central.max};
    statusBar(ctx, bar, s);
    central.max.y = bar.min.y;
    fileDialogWindow(ctx, s);
    quitDialogWindow(ctx, s);
    exportWindow(ctx, s);
    recoveryWindow(ctx, s);
    return central;
}

}  // namespace grass::editor
