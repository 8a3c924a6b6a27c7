#include "app/edit_actions.h"

#include <system_error>

#include "edit/layer_list.h"
#include "maps/map_image.h"

namespace grass::editor {

namespace fs = std::filesystem;

void resetHistory(EditorState& s) {
    s.doc.history.clear();
    s.doc.committed = s.doc.loaded.project;
    s.doc.paintedMaps.clear();
    s.doc.waitingMaps.clear();
    // Stamps of another document's files (or of this one's before it was opened again, maybe
    // changed since) would make the first look take the files just read for changes.
    s.fileWatch = {};
    s.view.gizmoDrag.reset();
    s.view.toolDragActive = false;
    s.view.place.selected.reset();
}

Result<void> carryPaintedMaps(EditorState& s, core::Scene& from, core::Scene& to) {
    std::vector<std::string> before, after;
    for (const core::LayerField& layer : from.layers)
        before.push_back(layer.name);
    for (const core::LayerField& layer : to.layers)
        after.push_back(layer.name);
    const auto match = core::matchLayers(before, after);
    std::set<std::size_t> kept;
    for (const auto& was : match)
        if (was)
            kept.insert(*was);
    auto& waiting = s.doc.waitingMaps;
    for (const auto& [layer, map] : s.doc.paintedMaps)
        if (layer < from.layers.size() && !kept.contains(layer))
            waiting[{before[layer], map}] = core::layerMap(from.layers[layer].source.maps, map);
    std::set<std::pair<std::size_t, core::LayerMap>> painted;
    for (std::size_t j = 0; j < to.layers.size(); ++j)
        for (const core::LayerMap map : core::ALL_LAYER_MAPS) {
            core::MapImage& target = core::layerMap(to.layers[j].source.maps, map);
            if (match[j] && s.doc.paintedMaps.contains({*match[j], map})) {
                target = core::layerMap(from.layers[*match[j]].source.maps, map);
                painted.insert({j, map});
            } else if (const auto found = waiting.find({after[j], map}); found != waiting.end()) {
                target = std::move(found->second);
                waiting.erase(found);
                painted.insert({j, map});
            }
        }
    s.doc.paintedMaps = painted;
    std::set<std::size_t> layers;
    for (const auto& entry : painted)
        layers.insert(entry.first);
    for (const std::size_t layer : layers) {
        // A re-grow over the whole mesh equals growing from these maps (layer_growth tests).
        const float margin = glm::length(to.bounds.size());
        auto report = core::regrowLayerRegion(to.layers[layer], to.bounds, margin,
                                              s.doc.loaded.project.lighting);
        if (!report)
            return report.error();
    }
    return {};
}

bool importMapImage(EditorState& s, const fs::path& file) {
    const std::size_t layer = s.view.paint.layer;
    const core::LayerMap which = s.view.paint.map;
    const std::string mapName(core::layerMapName(which));
    if (!s.tools || !s.scene || layer >= s.scene->layers.size() ||
        layer >= s.doc.project().layers.size()) {
        s.transient.message = "cannot import " + file.string() + ": the brush's layer does not exist";
        return false;
    }
    if (s.view.toolDragActive || s.busy()) {
        s.transient.message = "cannot import " + file.string() + " while a stroke or an export runs";
        return false;
    }
    const core::MapImage& current = core::layerMap(s.scene->layers[layer].source.maps, which);
    const glm::ivec2 size = current.texels.empty() ? s.doc.project().layers[layer].mapResolution
                                                   : glm::ivec2(current.width, current.height);
    auto image = core::loadMapImageAt(file, size.x, size.y);
    if (!image) {
        s.transient.message = "cannot import: " + image.error().str();
        return false;
    }
    auto replaced = s.tools->painter.replaceMap(layer, which, *image);
    if (!replaced) {
        s.transient.message = "cannot import " + file.string() + ": " + replaced.error().str();
        return false;
    }
    auto& [edit, report] = *replaced;
    if (!edit) {
        s.transient.message = file.filename().string() + " equals the " + mapName + " map already";
        return true;
    }
    if (s.regrown)
        s.regrown(layer, report);
    const std::string label = "import " + mapName + " map";
    apply(s, RecordStroke{std::move(*edit), label});
    s.transient.message = "imported " + file.string() + " as the " + mapName + " map of layer \"" +
                          s.doc.project().layers[layer].name + "\"";
    // How the picture was read (resampled, colour to luminance): the user should know.
    for (const std::string& warning : image->warnings)
        s.transient.message += "; " + warning;
    return true;
}

bool exportMapImage(EditorState& s, const fs::path& file) {
    const std::size_t layer = s.view.paint.layer;
    const core::LayerMap which = s.view.paint.map;
    if (!s.scene || layer >= s.scene->layers.size() || layer >= s.doc.project().layers.size()) {
        s.transient.message = "cannot export " + file.string() + ": the brush's layer does not exist";
        return false;
    }
    const core::MapImage& current = core::layerMap(s.scene->layers[layer].source.maps, which);
    const glm::ivec2 size = s.doc.project().layers[layer].mapResolution;
    const core::MapImage map =
        current.texels.empty() ? core::makeConstantMap(size.x, size.y, 1.0f) : current;
    if (auto saved = core::saveMapImage(map, file); !saved) {
        s.transient.message = "cannot export: " + saved.error().str();
        return false;
    }
    s.transient.message = "exported the " + std::string(core::layerMapName(which)) +
                          " map of layer \"" + s.doc.project().layers[layer].name + "\" to " +
                          file.string();
    return true;
}

bool mapFileShared(const core::Project& project, const std::string& file) {
    std::size_t readers = 0;
    for (const core::GrassLayer& layer : project.layers)
        for (const core::LayerMap map : core::ALL_LAYER_MAPS)
            readers += core::layerMapFile(layer, map) == file ? 1 : 0;
    return readers > 1;
}

Result<void> savePaintedMaps(EditorState& s, const fs::path& folder) {
    if (!s.scene)
        return {};
    for (const auto& [index, map] : s.doc.paintedMaps) {
        if (index >= s.doc.loaded.project.layers.size() || index >= s.scene->layers.size())
            continue;
        core::GrassLayer& layer = s.doc.loaded.project.layers[index];
        std::string& field = core::layerMapFile(layer, map);
        const std::string relative =
            field.empty() || mapFileShared(s.doc.loaded.project, field)
                ? core::defaultMapFile(layer.name, core::layerMapName(map))
                : field;
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
    // A generated atlas goes with the maps painted on it (scene/paint_uvs.h).
    if (auto kept = core::keepGeneratedUvs(s.doc.loaded.project, folder, s.scene->paintUvs); !kept)
        return kept.error();
    // The map names written into the project are part of the save, not an edit to undo.
    s.doc.committed = s.doc.loaded.project;
    s.doc.paintedMaps.clear();
    return {};
}

}  // namespace grass::editor
