#include "app/autosave.h"

#include <system_error>

#include "maps/map_image.h"
#include "ui/ui.h"
#include "ui/window.h"

namespace grass::editor {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view AUTOSAVE_TAG = ".autosave";

std::string& mapField(core::GrassLayer& layer, core::LayerMap map) {
    return map == core::LayerMap::Density ? layer.densityMap
           : map == core::LayerMap::Soil  ? layer.soilMap
                                          : layer.lightMap;
}

std::string_view mapKey(core::LayerMap map) {
    return map == core::LayerMap::Density ? "density"
           : map == core::LayerMap::Soil  ? "soil"
                                          : "light";
}

constexpr core::LayerMap ALL_MAPS[] = {core::LayerMap::Density, core::LayerMap::Soil,
                                       core::LayerMap::Light};

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
    const fs::path file = autosavePath(s.loaded);
    if (file.empty() || !s.scene)
        return {};
    core::Project project = s.loaded.project;
    for (const auto& [index, map] : s.paintedMaps) {
        if (index >= project.layers.size() || index >= s.scene->layers.size())
            continue;
        core::GrassLayer& layer = project.layers[index];
        std::string& field = mapField(layer, map);
        const std::string side =
            autosaveMapName(field.empty() ? core::defaultMapFile(layer.name, mapKey(map)) : field);
        auto target = core::resolveAssetPath(s.loaded.folder, side, "autosave");
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
    if (auto written = writeAutosave(state); !written)
        state.message = "autosave failed: " + written.error().str();
    else if (!state.loaded.file.empty() && !state.messageIsSaveError)
        state.message = "autosaved to " + autosavePath(state.loaded).string();
}

void removeAutosave(const core::LoadedProject& loaded) {
    const fs::path file = autosavePath(loaded);
    if (file.empty())
        return;
    std::error_code ec;
    if (auto side = core::loadProject(file)) {
        for (core::GrassLayer& layer : side->project.layers)
            for (const core::LayerMap map : ALL_MAPS)
                if (const std::string& field = mapField(layer, map);
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
    for (std::size_t i = 0; i < s.loaded.project.layers.size(); ++i)
        for (const core::LayerMap map : ALL_MAPS) {
            std::string& field = mapField(s.loaded.project.layers[i], map);
            if (const auto real = mapNameOfAutosave(field)) {
                // A map new in the lost session had no name: the default one is what Save picks.
                field = *real == core::defaultMapFile(s.loaded.project.layers[i].name, mapKey(map)) &&
                                !fs::exists(s.loaded.folder / *real)
                            ? std::string()
                            : *real;
                s.paintedMaps.insert({i, map});
            }
        }
    s.committed = s.loaded.project;
    s.dirty = true;
    s.message = "recovered the autosaved work: save to keep it";
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
                if (row.button("Recover").clicked())
                    s.recoverRequested = true;
                if (row.button("Discard").clicked()) {
                    removeAutosave(s.loaded);
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
