#include "app/edit_actions.h"

#include <system_error>

#include "maps/map_image.h"
#include "quality/quality_presets.h"

namespace grass::editor {

namespace {

namespace fs = std::filesystem;

std::string_view mapKey(core::LayerMap map) {
    switch (map) {
    case core::LayerMap::Density: return "density";
    case core::LayerMap::Soil: return "soil";
    case core::LayerMap::Light: return "light";
    }
    return "density";
}

std::string& mapField(core::GrassLayer& layer, core::LayerMap map) {
    return map == core::LayerMap::Density ? layer.densityMap
           : map == core::LayerMap::Soil  ? layer.soilMap
                                          : layer.lightMap;
}

// A short name for a project step: the part of the project that changed.
std::string projectEditLabel(const core::Project& before, const core::Project& after) {
    if (const auto preset = core::matchingPreset(after); preset && preset != core::matchingPreset(before))
        return "quality " + std::string(core::qualityPresetName(*preset));
    if (before.wind != after.wind)
        return "wind";
    if (before.colliders != after.colliders)
        return "colliders";
    if (before.layers != after.layers)
        return "layers";
    if (before.render != after.render || before.lighting != after.lighting)
        return "render settings";
    if (before.snow != after.snow)
        return "snow";
    if (before.name != after.name)
        return "project name";
    return "project";
}

bool applyProject(EditorState& s, const core::Project& project) {
    s.loaded.project = project;
    s.committed = project;
    s.dirty = s.rebuildPending = true;
    return true;
}

bool applyPaint(EditorState& s, const core::PaintEdit& edit, bool undoing) {
    if (!s.tools)
        return false;
    auto report = s.tools->painter.apply(edit, undoing);
    if (!report) {
        s.message = "cannot " + std::string(undoing ? "undo" : "redo") + ": " +
                    report.error().message;
        return false;
    }
    s.regrown.emplace_back(edit.layer, *report);
    s.paintedMaps.insert({edit.layer, edit.map});
    s.dirty = true;
    return true;
}

bool step(EditorState& s, bool undoing) {
    if (s.toolDragActive || s.busy())
        return false;
    const core::Edit* edit = undoing ? s.history.undo() : s.history.redo();
    if (!edit)
        return false;
    s.message = std::string(undoing ? "undid " : "redid ") + edit->label;
    if (const auto* project = std::get_if<core::ProjectEdit>(&edit->change))
        return applyProject(s, undoing ? project->before : project->after);
    return applyPaint(s, std::get<core::PaintEdit>(edit->change), undoing);
}

}  // namespace

void recordProjectEdit(EditorState& s, bool widgetActive) {
    if (widgetActive || s.toolDragActive || s.loaded.project == s.committed)
        return;
    core::ProjectEdit edit{s.committed, s.loaded.project};
    std::string label = projectEditLabel(edit.before, edit.after);
    s.committed = s.loaded.project;
    s.history.push(core::Edit{std::move(label), std::move(edit)});
    // Every change of the project, from any source (panel, key, gizmo, script), passes here.
    s.dirty = true;
}

bool undo(EditorState& s) {
    return step(s, true);
}

bool redo(EditorState& s) {
    return step(s, false);
}

void resetHistory(EditorState& s) {
    s.history.clear();
    s.committed = s.loaded.project;
    s.paintedMaps.clear();
    s.gizmoDrag.reset();
    s.toolDragActive = false;
    s.place.selected.reset();
}

Result<void> carryPaintedMaps(const EditorState& s, core::Scene& from, core::Scene& to) {
    std::set<std::size_t> layers;
    for (const auto& [layer, map] : s.paintedMaps) {
        if (layer >= from.layers.size() || layer >= to.layers.size())
            continue;
        core::layerMap(to.layers[layer].source.maps, map) =
            core::layerMap(from.layers[layer].source.maps, map);
        layers.insert(layer);
    }
    for (const std::size_t layer : layers) {
        // A re-grow over the whole mesh equals growing from these maps (layer_growth tests).
        const float margin = glm::length(to.bounds.size());
        auto report = core::regrowLayerRegion(to.layers[layer], to.bounds, margin,
                                              s.loaded.project.lighting);
        if (!report)
            return report.error();
    }
    return {};
}

Result<void> savePaintedMaps(EditorState& s, const fs::path& folder) {
    if (!s.scene)
        return {};
    for (const auto& [index, map] : s.paintedMaps) {
        if (index >= s.loaded.project.layers.size() || index >= s.scene->layers.size())
            continue;
        core::GrassLayer& layer = s.loaded.project.layers[index];
        std::string& field = mapField(layer, map);
        const std::string relative =
            field.empty() ? core::defaultMapFile(layer.name, mapKey(map)) : field;
        auto target = core::resolveAssetPath(folder, relative, "layers/" + layer.name);
        if (!target)
            return target.error();
        std::error_code ec;
        fs::create_directories(target->parent_path(), ec);
        if (auto saved = core::saveMapImage(core::layerMap(s.scene->layers[index].source.maps, map),
                                            *target);
            !saved)
            return saved.error();
        field = relative;
    }
    // The map names written into the project are part of the save, not an edit to undo.
    s.committed = s.loaded.project;
    s.paintedMaps.clear();
    return {};
}

}  // namespace grass::editor
