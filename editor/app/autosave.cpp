#include "app/autosave.h"

#include <system_error>

#include "maps/map_image.h"
#include "ui/ui.h"
#include "ui/window.h"

namespace grass::editor {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view AUTOSAVE_TAG = ".autosave";

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
    if (file.empty() || !s.scene)
        return {};
    core::Project project = s.doc.loaded.project;
    for (const auto& [index, map] : s.doc.paintedMaps) {
        if (index >= project.layers.size() || index >= s.scene->layers.size())
            continue;
        core::GrassLayer& layer = project.layers[index];
        std::string& field = core::layerMapFile(layer, map);
        const std::string side =
            autosaveMapName(field.empty() ? core::defaultMapFile(layer.name, core::layerMapName(map)) : field);
        auto target = core::resolveAssetPath(s.doc.loaded.folder, side, "autosave");
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

void autosaveNow(EditorState& state) {
    // A project never saved (File > New, New from mesh) has no folder of its own to autosave
    // next to: say so while there is work to lose, rather than nothing at all.
    if (state.doc.loaded.file.empty()) {
        if (state.doc.dirty && !state.transient.messageIsSaveError) {
            state.transient.message =
                "not autosaved: this project has never been saved (File > Save As... gives it a "
                "folder, and autosaves then keep your work)";
            state.transient.messageIsSaveError = true;
        }
        return;
    }
    if (auto written = writeAutosave(state); !written)
        state.transient.message = "autosave failed: " + written.error().str();
    else if (!state.doc.loaded.file.empty() && !state.transient.messageIsSaveError)
        state.transient.message = "autosaved to " + autosavePath(state.doc.loaded).string();
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
    // Saved as the real project's file, relative to the same folder.
    side->file = loaded.file;
    side->folder = loaded.folder;
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

void recoveryWindow(ui::Context& ctx, EditorState& s) {
    if (!s.recoveryOffer)
        return;
    const ui::Rect screen = ctx.screenRect();
    bool open = true;
    ui::window(
        ctx, "Recover unsaved work?", &open,
        [&](ui::Ui& ui) {
            ui.label("The editor did not close cleanly last time.");
            ui.label("An autosave of this project has changes that were not saved.");
            ui.horizontal([&](ui::Ui& row) {
                if (row.button("Recover").onHoverText("Open the autosaved work (it stays unsaved until you save)").clicked())
                    s.recoverRequested = true;
                if (row.button("Discard").onHoverText("Delete the autosave and keep the project as saved").clicked()) {
                    removeAutosave(s.doc.loaded);
                    s.recoveryOffer.reset();
                }
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 220.0f, screen.centre().y - 60.0f},
                              {440.0f, 110.0f}));
    if (!open)
        s.recoveryOffer.reset();  // decided later: the side files stay until a save
}

}  // namespace grass::editor
