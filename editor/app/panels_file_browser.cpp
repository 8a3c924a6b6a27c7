// The file browser window (file_browser.h is its model): the folder's path with Up and the
// places (home, the project, the working folder, recent project folders), the folder's entries
// through the purpose's filter (a click selects, a double-click enters a folder or chooses a
// file), the typed name or path (Enter chooses), and why a choice was refused.
#include <filesystem>
#include <system_error>

#include "app/autosave.h"
#include "app/edit_actions.h"
#include "app/mesh_import.h"
#include "app/panels.h"
#include "mesh/gltf_source.h"
#include "ui/text_edit.h"
#include "ui/text_wrap.h"
#include "ui/window.h"
#include "util/byte_size.h"

namespace grass::editor {

namespace fs = std::filesystem;

namespace {

// Places to jump to, each once, those that exist.
std::vector<BrowserPlace> browserPlaces(const EditorState& s) {
    std::vector<BrowserPlace> places;
    const auto add = [&](std::string label, const fs::path& folder) {
        std::error_code ec;
        if (folder.empty() || !fs::is_directory(folder, ec))
            return;
        for (const BrowserPlace& place : places)
            if (place.folder == folder)
                return;
        places.push_back({std::move(label), folder});
    };
    if (const char* home = std::getenv("HOME"))
        add("Home", home);
    add("Project", s.doc.loaded.folder);
    add("Meshes", s.transient.meshFolder);
    std::error_code ec;
    add("Working folder", fs::current_path(ec));
    for (const fs::path& folder : s.transient.recent.folders())
        add(folder.filename().string(), folder);
    return places;
}

// What a chosen path does, by the browser's purpose.
void choose(EditorState& s, BrowsePurpose purpose, const fs::path& path) {
    switch (purpose) {
        case BrowsePurpose::OpenProject:
            askLeave(s, LeaveAction::Open, path.string());
            break;
        case BrowsePurpose::SaveProject:
            saveTo(s, projectFileFor(path).string());
            break;
        case BrowsePurpose::NewFromMesh:
            s.transient.meshFolder = path.parent_path();
            askLeave(s, LeaveAction::NewFromMesh, path.string());
            break;
        case BrowsePurpose::ImportMesh:
            s.transient.meshFolder = path.parent_path();
            s.importMeshRequested = path.string();
            break;
        case BrowsePurpose::ImportMap:
            s.transient.meshFolder = path.parent_path();
            s.importMapRequested = path.string();
            break;
        case BrowsePurpose::ExportMap:
            s.transient.meshFolder = path.parent_path();
            exportMapImage(s, path);
            break;
        case BrowsePurpose::AddCollider:
            s.transient.meshFolder = path.parent_path();
            s.addColliderRequested = path.string();
            break;
    }
}

std::string entryText(const BrowserEntry& entry) {
    if (entry.isFolder)
        return entry.name + (entry.isProject ? "/    (project)" : "/");
    return entry.name + "    " + byteSizeText(static_cast<double>(entry.bytes));
}

}  // namespace

void routeDroppedFiles(EditorState& s, const std::vector<std::string>& paths) {
    // While a field grows the document waits, and so do files dropped on it: said, not queued
    // behind a load the user may cancel.
    if (s.documentJob && !paths.empty()) {
        s.transient.message = "not taken: " + paths.front() + " (" + s.documentJob->title() +
                              " … drop it again once it is open)";
        return;
    }
    for (const std::string& dropped : paths) {
        const fs::path path(dropped);
        std::error_code ec;
        if (browseAccepts(BrowsePurpose::ImportMesh, path)) {
            s.importMeshRequested = dropped;
            s.transient.meshFolder = path.parent_path();
        } else if (browseAccepts(BrowsePurpose::ImportMap, path)) {
            s.importMapRequested = dropped;
        } else if (browseAccepts(BrowsePurpose::OpenProject, path) ||
                   fs::is_regular_file(path / "project.json", ec)) {
            askLeave(s, LeaveAction::Open, dropped);
        } else {
            s.transient.message = "cannot use " + dropped +
                                  ": drop a .gltf/.glb mesh, a map picture (" +
                                  browseFilterText(BrowsePurpose::ImportMap) +
                                  ") or a project folder" + core::gltf::otherMeshFormat(path);
        }
    }
}

void rememberRecent(EditorState& s, const fs::path& projectFile) {
    s.transient.recent.add(projectFile);
    // A list that cannot be kept costs nothing but the list: the save or open itself succeeded.
    (void)saveRecentFiles(s.transient.recent, s.transient.recentFile);
}

void openBrowser(EditorState& s, BrowsePurpose purpose) {
    const fs::path projectFolder = s.doc.loaded.folder;
    fs::path start = projectFolder;
    std::string typed;
    fs::path ownProject = s.doc.loaded.file;  // saved onto without the question of another's
    switch (purpose) {
        case BrowsePurpose::OpenProject:
            // The project's siblings: projects are folders side by side.
            start = projectFolder.has_parent_path() ? projectFolder.parent_path() : projectFolder;
            break;
        case BrowsePurpose::SaveProject:
            if (!s.doc.loaded.file.empty()) {
                start = projectFolder.parent_path();
                typed = projectFolder.filename().string();
            } else if (isUnsavedSlot(projectFolder)) {
                // A recovered never-saved project lives in its autosave slot: not a place to
                // save it to. One that stood in for a project whose folder refused it goes back
                // there, as that project's own Save As would.
                if (const fs::path origin = unsavedAutosaveOrigin(projectFolder); !origin.empty()) {
                    start = origin.parent_path().parent_path();
                    typed = origin.parent_path().filename().string();
                    ownProject = origin;
                } else {
                    std::error_code ec;
                    start = fs::current_path(ec);
                }
            }
            break;
        case BrowsePurpose::ExportMap:
            // "<layer>-<map>.png" in the project's maps folder, as a save would name it.
            if (s.view.paint.layer < s.doc.project().layers.size())
                typed = fs::path(core::defaultMapFile(s.doc.project().layers[s.view.paint.layer].name,
                                                      core::layerMapName(s.view.paint.map)))
                            .filename()
                            .string();
            if (fs::is_directory(projectFolder / "maps"))
                start = projectFolder / "maps";
            break;
        default:
            if (!s.transient.meshFolder.empty())
                start = s.transient.meshFolder;
            break;
    }
    s.transient.browser.emplace(purpose, start, std::move(typed));
    if (!ownProject.empty())
        s.transient.browser->setOwnProject(ownProject);
}

void fileBrowserWindow(ui::Context& ctx, EditorState& s) {
    if (!s.transient.browser)
        return;
    FileBrowser& browser = *s.transient.browser;
    const BrowsePurpose purpose = browser.purpose();
    bool open = true;
    std::optional<fs::path> chosen;
    const ui::Rect screen = ctx.screenRect();
    const ui::Rect defaultRect = ui::Rect::fromMinSize(
        {screen.centre().x - 320.0f, screen.centre().y - 220.0f}, {640.0f, 440.0f});
    ui::window(
        ctx, "File browser", &open,
        [&](ui::Ui& ui) {
            ui.coloredLabel(browseTitle(purpose), ui.style().textStrong);
            ui.horizontal([&](ui::Ui& row) {
                if (row.button("Up").onHoverText("The folder above this one").clicked())
                    browser.up();
                row.label(browser.folder().string());
            });
            ui.horizontal([&](ui::Ui& row) {
                const std::vector<BrowserPlace> places = browserPlaces(s);
                for (std::size_t i = 0; i < places.size(); ++i)
                    row.withId(i, [&](ui::Ui& item) {
                        if (item.button(places[i].label).onHoverText(places[i].folder.string()).clicked())
                            browser.enter(places[i].folder);
                    });
            });
            ui.separator();
            const FolderListing& listing = browser.listing();
            // The list takes what the rows below it leave of the window.
            // A refusal or question below wraps to the window: its lines beyond the first are
            // taken from the list too, so the message is never cut off at the bottom.
            const std::size_t messageLines =
                browser.message().empty()
                    ? 1
                    : ui::wrapText(ctx.fonts(), ui.style().textSizePt, browser.message(),
                                   ui.availableWidth())
                          .size();
            const float messageExtra =
                float(std::max<std::size_t>(messageLines, 1) - 1) *
                (ctx.fonts().lineHeight(ui.style().textSizePt) + ui.style().itemSpacing.y);
            const float listHeight =
                std::max(80.0f, ui.availableRect().height() - 96.0f - messageExtra);
            ui.scrollArea("entries", listHeight, [&](ui::Ui& list) {
                if (!listing.error.empty())
                    list.wrappedColoredLabel(listing.error, ui::Color32::rgb(255, 150, 60));
                else if (listing.entries.empty())
                    list.coloredLabel("(no folders or " + browseFilterText(purpose) + " here)",
                                      list.style().textWeak);
                for (std::size_t i = 0; i < listing.entries.size(); ++i) {
                    ui::Response r;
                    list.withId(i, [&](ui::Ui& item) {
                        r = item.selectable(browser.selected() == i, entryText(listing.entries[i]))
                                .onHoverText("Click to select, double-click to open");
                    });
                    if (r.doubleClicked()) {
                        chosen = browser.activate(i);
                        break;  // the listing may have changed
                    }
                    if (r.clicked())
                        browser.select(i);
                }
                if (listing.hidden > 0)
                    list.coloredLabel(std::to_string(listing.hidden) + " more not listed: type the name",
                                      list.style().textWeak);
            });
            ui.separator();
            // The text edit consumes Enter, so look before it: Enter (not a commit by focus loss,
            // e.g. a click on Cancel) chooses.
            const bool enter = ctx.keyPressed(ui::Key::Enter);
            bool committed = false;
            ui.horizontal([&](ui::Ui& row) {
                row.label(purpose == BrowsePurpose::SaveProject ? "Project folder:" : "Name or path:");
                // Asked before the field runs: a focus it does not see this frame is dropped.
                if (browser.takeFocusRequest())
                    ctx.requestFocus(row.makeId("##path"));
                // Typing while nothing has the keyboard (after a click in the list, say) types a
                // new name into the field. It went to the viewport's shortcuts behind the window
                // before: "maps/ctc24.tga" chose the gizmo (g), switched the frustum cull (2) and
                // the technique (t), and the name was lost.
                if (ctx.focusedId().value == 0 && !ctx.input().text.empty()) {
                    browser.typed().clear();
                    ctx.requestFocus(row.makeId("##path"));
                }
                ui::textEdit(row, "##path", browser.typed(), row.availableWidth() - 8.0f,
                             &committed)
                    .onHoverText("A name in this folder, a relative or absolute path, or ~/...; Enter");
            });
            ui.horizontal([&](ui::Ui& row) {
                const bool go = row.button(browseButton(purpose))
                                        .onHoverText("Use the typed path or the selected file (Enter)")
                                        .clicked() ||
                                    (committed && enter);
                if (go && !chosen)
                    chosen = browser.activateTyped();
                if (row.button("Cancel").onHoverText("Close the browser (nothing changes)").clicked())
                    open = false;
            });
            // Its own line, wrapped: the list of image extensions is wider than the buttons' row.
            ui.wrappedColoredLabel("Shows " + browseFilterText(purpose), ui.style().textWeak);
            if (!browser.message().empty())
                ui.wrappedColoredLabel(browser.message(), ui::Color32::rgb(255, 150, 60));
        },
        defaultRect);
    if (chosen) {
        s.transient.browser.reset();
        choose(s, purpose, *chosen);
    } else if (!open) {
        s.transient.browser.reset();
    }
}

}  // namespace grass::editor
