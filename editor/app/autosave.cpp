#include "app/autosave.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include "app/mesh_import.h"
#include "maps/map_image.h"
#include "ui/text_wrap.h"
#include "ui/ui.h"
#include "ui/window.h"
#include "util/atomic_file.h"
#include "util/process_alive.h"

namespace grass::editor {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view AUTOSAVE_TAG = ".autosave";
// The side project in a never-saved project's slot.
constexpr std::string_view UNSAVED_SIDE_PROJECT = "project.autosave.json";
// In a slot that took a saved project's autosave (its own folder could not be written): the
// project file it came from, one line.
constexpr std::string_view UNSAVED_ORIGIN = "origin.txt";

// The side project `file` and the side files of the painted maps, named relative to `folder`.
Result<void> writeSideFiles(const EditorState& s, const fs::path& folder, const fs::path& file) {
    if (!s.scene)
        return {};
    core::Project project = s.doc.loaded.project;
    for (const auto& [index, map] : s.doc.paintedMaps) {
        if (index >= project.layers.size() || index >= s.scene->layers.size())
            continue;
        core::GrassLayer& layer = project.layers[index];
        std::string& field = core::layerMapFile(layer, map);
        const std::string side =
            autosaveMapName(field.empty() ? core::defaultMapFile(layer.name, core::layerMapName(map)) : field);
        auto target = core::resolveAssetPath(folder, side, "autosave");
        if (!target)
            return target.error();
        std::error_code ec;
        fs::create_directories(target->parent_path(), ec);
        if (auto saved = core::saveMapImage(
                core::layerMap(s.scene->layers[index].source.maps, map), *target);
            !saved)
            return saved.error();
        field = side;
    }
    return core::saveProject(project, file);
}

}  // namespace

fs::path autosavePath(const core::LoadedProject& loaded) {
    if (loaded.file.empty())
        return {};
    return loaded.folder / (loaded.file.stem().string() + std::string(AUTOSAVE_TAG) + ".json");
}

std::string autosaveMapName(const std::string& relative) {
    const fs::path path(relative);
    return (path.parent_path() / (path.stem().string() + std::string(AUTOSAVE_TAG) +
                                  path.extension().string()))
        .generic_string();
}

std::optional<std::string> mapNameOfAutosave(const std::string& relative) {
    const fs::path path(relative);
    const std::string stem = path.stem().string();
    if (stem.size() <= AUTOSAVE_TAG.size() ||
        stem.compare(stem.size() - AUTOSAVE_TAG.size(), AUTOSAVE_TAG.size(), AUTOSAVE_TAG) != 0)
        return std::nullopt;
    return (path.parent_path() / (stem.substr(0, stem.size() - AUTOSAVE_TAG.size()) +
                                  path.extension().string()))
        .generic_string();
}

Result<void> writeAutosave(const EditorState& s) {
    const fs::path file = autosavePath(s.doc.loaded);
    if (file.empty())
        return {};
    return writeSideFiles(s, s.doc.loaded.folder, file);
}

fs::path unsavedAutosaveRoot() {
    if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state == '/')
        return fs::path(state) / "grass" / "unsaved";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".local" / "state" / "grass" / "unsaved";
    return {};
}

Result<void> writeUnsavedAutosave(EditorState& s) {
    if (!s.scene)
        return {};
    // A slot holds the files of one folder: a project that took another folder (a mesh imported
    // from elsewhere) starts a fresh slot, so no stale file of the same name is kept.
    if (!s.doc.unsavedSlot.empty() && s.doc.unsavedSlotFrom != s.doc.loaded.folder &&
        s.doc.unsavedSlot != s.doc.loaded.folder)
        removeUnsavedSlot(s.doc.unsavedSlot);
    if (s.doc.unsavedSlot.empty()) {
        const fs::path root = unsavedAutosaveRoot();
        if (root.empty())
            return makeError("autosave", "there is no folder for it (neither XDG_STATE_HOME nor HOME is set)");
        static int slots = 0;
        s.doc.unsavedSlot = root / (std::to_string(::getpid()) + "-" + std::to_string(++slots));
        s.doc.unsavedSlotFrom = s.doc.loaded.folder;
    }
    const fs::path& slot = s.doc.unsavedSlot;
    std::error_code ec;
    fs::create_directories(slot, ec);
    if (ec)
        return makeError(slot.string(), "cannot create the autosave folder: " + ec.message());
    // The files the project names, copied once as Save As copies them (a recovered project's
    // are in its slot already).
    if (s.doc.loaded.folder != slot)
        for (const std::string& asset : core::projectAssetPaths(s.doc.loaded.project))
            if (auto copied = copyAssetFiles(s.doc.loaded.folder / asset, slot / asset); !copied)
                return copied.error();
    return writeSideFiles(s, slot, slot / UNSAVED_SIDE_PROJECT);
}

std::optional<core::LoadedProject> findUnsavedAutosave(const fs::path& except) {
    const fs::path root = unsavedAutosaveRoot();
    std::error_code ec;
    if (root.empty() || !fs::is_directory(root, ec))
        return std::nullopt;
    std::optional<core::LoadedProject> newest;
    fs::file_time_type newestTime{};
    for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path slot = it->path();
        if (!except.empty() && slot == except)
            continue;
        const fs::path side = slot / UNSAVED_SIDE_PROJECT;
        // A slot whose editor still runs is that editor's own.
        std::error_code sideError;
        if (processRunsElsewhere(std::strtol(slot.filename().c_str(), nullptr, 10)) ||
            !fs::is_regular_file(side, sideError))
            continue;
        std::error_code timeError;
        const fs::file_time_type time = fs::last_write_time(side, timeError);
        if (timeError || (newest && time <= newestTime))
            continue;
        auto loaded = core::loadProject(side);
        if (!loaded)
            continue;  // half-written or damaged: nothing to offer
        loaded->file.clear();  // never saved: Save asks where
        loaded->folder = slot;
        newest = std::move(*loaded);
        newestTime = time;
    }
    return newest;
}

bool isUnsavedSlot(const fs::path& folder) {
    const fs::path root = unsavedAutosaveRoot();
    return !folder.empty() && !root.empty() && folder.parent_path() == root;
}

void removeUnsavedSlot(fs::path& slot) {
    std::error_code ec;
    if (isUnsavedSlot(slot))
        fs::remove_all(slot, ec);
    slot.clear();
}

Result<void> writeUnsavedOrigin(const fs::path& slot, const fs::path& projectFile) {
    return writeFileAtomic(slot / UNSAVED_ORIGIN, projectFile.string() + "\n");
}

fs::path unsavedAutosaveOrigin(const fs::path& slot) {
    std::ifstream in(slot / UNSAVED_ORIGIN);
    std::string line;
    std::getline(in, line);
    return line;
}

void autosaveNow(EditorState& state) {
    // A project never saved (File > New, New from mesh) has no folder of its own to autosave
    // next to: it goes to the user's unsaved folder, and when even that fails the status line
    // says so, rather than nothing at all.
    if (state.doc.loaded.file.empty()) {
        if (!state.doc.dirty)
            return;
        if (auto written = writeUnsavedAutosave(state); !written) {
            if (!state.transient.messageIsSaveError) {
                state.transient.message = "not autosaved: " + written.error().str() +
                                          " (this project has never been saved: File > Save "
                                          "As... gives it a folder)";
                state.transient.messageIsSaveError = true;
            }
        } else if (!state.transient.messageIsSaveError) {
            state.transient.message =
                "autosaved to " + (state.doc.unsavedSlot / UNSAVED_SIDE_PROJECT).string() +
                " (a new project: File > Save As... gives it a folder)";
        }
        return;
    }
    auto written = writeAutosave(state);
    if (written) {
        // The folder takes it (again): a slot that stood in for it has nothing left to recover.
        removeUnsavedSlot(state.doc.unsavedSlot);
        if (!state.transient.messageIsSaveError)
            state.transient.message = "autosaved to " + autosavePath(state.doc.loaded).string();
        return;
    }
    // A project whose folder cannot be written (read-only, full, gone) is autosaved where a
    // never-saved one is, and offered back the same way: the work is kept, and the status line
    // says where and how to save it for good.
    auto kept = writeUnsavedAutosave(state);
    if (kept)
        kept = writeUnsavedOrigin(state.doc.unsavedSlot, state.doc.loaded.file);
    if (!kept) {
        state.transient.message = "autosave failed: " + written.error().str() +
                                  "; not kept elsewhere either: " + kept.error().str();
        state.transient.messageIsSaveError = true;
        return;
    }
    // Where the work is comes first: the status line shows the beginning of a long message.
    state.transient.message = "the project's folder refused the autosave: kept in " +
                              (state.doc.unsavedSlot / UNSAVED_SIDE_PROJECT).string() + " (" +
                              written.error().str() +
                              "; File > Save As... saves the project elsewhere)";
    state.transient.messageIsSaveError = true;
}

void removeAutosave(const core::LoadedProject& loaded) {
    const fs::path file = autosavePath(loaded);
    if (file.empty())
        return;
    std::error_code ec;
    if (auto side = core::loadProject(file)) {
        for (core::GrassLayer& layer : side->project.layers)
            for (const core::LayerMap map : core::ALL_LAYER_MAPS)
                if (const std::string& field = core::layerMapFile(layer, map);
                    mapNameOfAutosave(field))
                    if (auto path = core::resolveAssetPath(loaded.folder, field, "autosave"))
                        fs::remove(*path, ec);
    }
    fs::remove(file, ec);
}

std::optional<core::LoadedProject> findAutosave(const core::LoadedProject& loaded) {
    const fs::path file = autosavePath(loaded);
    std::error_code ec;
    if (file.empty() || !fs::exists(file, ec))
        return std::nullopt;
    auto side = core::loadProject(file);
    if (!side)
        return std::nullopt;  // half-written or damaged: nothing to offer
    // Saved as the real project's file, relative to the same folder; that file as read now is
    // what a Save of the recovered work replaces.
    side->file = loaded.file;
    side->folder = loaded.folder;
    side->fileDigest = loaded.fileDigest;
    return std::move(*side);
}

void markRecoveredMaps(EditorState& s) {
    for (std::size_t i = 0; i < s.doc.loaded.project.layers.size(); ++i)
        for (const core::LayerMap map : core::ALL_LAYER_MAPS) {
            std::string& field = core::layerMapFile(s.doc.loaded.project.layers[i], map);
            if (const auto real = mapNameOfAutosave(field)) {
                // A map new in the lost session had no name: the default one is what Save picks.
                field = *real == core::defaultMapFile(s.doc.loaded.project.layers[i].name, core::layerMapName(map)) &&
                                !fs::exists(s.doc.loaded.folder / *real)
                            ? std::string()
                            : *real;
                s.doc.paintedMaps.insert({i, map});
            }
        }
    s.doc.committed = s.doc.loaded.project;
    s.doc.dirty = true;
    s.transient.message = "recovered the autosaved work: save to keep it";
}

std::string timeAgo(double seconds) {
    const auto count = [](double amount, const char* unit) {
        const long whole = std::max(1L, std::lround(std::floor(amount)));
        return std::to_string(whole) + " " + unit + (whole == 1 ? "" : "s") + " ago";
    };
    if (!(seconds >= 60.0))  // a clock set back says "just now" too
        return "just now";
    if (seconds < 3600.0)
        return count(seconds / 60.0, "minute");
    if (seconds < 48.0 * 3600.0)
        return count(seconds / 3600.0, "hour");
    return count(seconds / 86400.0, "day");
}

namespace {

// " 5 minutes ago": when the side project `file` was written; empty when it cannot be read.
std::string writtenAgo(const fs::path& file) {
    std::error_code ec;
    const fs::file_time_type written = fs::last_write_time(file, ec);
    if (ec)
        return {};
    return " " +
           timeAgo(
               std::chrono::duration<double>(fs::file_time_type::clock::now() - written).count());
}

}  // namespace

void recoveryWindow(ui::Context& ctx, EditorState& s) {
    if (!s.recoveryOffer)
        return;
    const ui::Rect screen = ctx.screenRect();
    // A never-saved project's autosave is offered whatever project the editor opened, and so is
    // a saved project's that its folder refused (it names that project).
    const bool unsaved = s.recoveryOffer->file.empty();
    const fs::path origin = unsaved ? unsavedAutosaveOrigin(s.recoveryOffer->folder) : fs::path();
    // Which work and when: the project open now may be another one (a never-saved project's
    // autosave is offered whatever the editor opened), and an old autosave is told from a
    // minute-old one.
    const std::string ago = writtenAgo(unsaved ? s.recoveryOffer->folder / UNSAVED_SIDE_PROJECT
                                               : autosavePath(*s.recoveryOffer));
    const std::string said =
        !origin.empty() ? "An autosave of " + origin.string() + " was kept in your unsaved folder" +
                              ago + " (the project's folder could not be written)."
        : unsaved
            ? "A new project that was never saved, \"" + s.recoveryOffer->project.name +
                  "\", was autosaved" + ago + "."
            : "An autosave of this project, written" + ago + ", has changes that were not saved.";
    // Tall enough for the text as it wraps (a long path takes lines), so the buttons below it
    // are never cut off: the title, the first line, the wrapped ones, the buttons' row.
    constexpr float WIDTH = 440.0f;
    const ui::Style& style = ctx.style();
    const std::size_t wrapped =
        ui::wrapText(ctx.fonts(), style.textSizePt, said, WIDTH - 24.0f).size();
    const float height =
        70.0f + ui::linesHeight(ctx.fonts(), style.textSizePt, style.itemSpacing.y, 1 + wrapped);
    bool open = true;
    ui::window(
        ctx, "Recover unsaved work?", &open,
        [&](ui::Ui& ui) {
            ui.label("The editor did not close cleanly last time.");
            ui.wrappedLabel(said);
            ui.horizontal([&](ui::Ui& row) {
                if (row.button("Recover").onHoverText("Open the autosaved work (it stays unsaved until you save)").clicked())
                    s.recoverRequested = true;
                if (row.button("Discard").onHoverText("Delete the autosave and keep the project as saved").clicked()) {
                    if (unsaved) {
                        fs::path slot = s.recoveryOffer->folder;
                        removeUnsavedSlot(slot);
                    } else {
                        removeAutosave(s.doc.loaded);
                    }
                    // An older never-saved autosave is offered next, so every one left by a
                    // session that did not close cleanly is asked about (before, one a start).
                    s.recoveryOffer = s.offersUnsavedAutosaves
                                          ? findUnsavedAutosave(s.doc.unsavedSlot)
                                          : std::nullopt;
                }
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 0.5f * WIDTH, screen.centre().y - 60.0f},
                              {WIDTH, height}));
    if (!open)
        s.recoveryOffer.reset();  // decided later: the side files stay until a save
}

}  // namespace grass::editor
