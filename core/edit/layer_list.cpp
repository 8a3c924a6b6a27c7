#include "edit/layer_list.h"

#include <algorithm>

#include "util/free_name.h"

namespace grass::core {

namespace {

bool hasName(const std::vector<GrassLayer>& layers, const std::string& name) {
    return std::any_of(layers.begin(), layers.end(),
                       [&](const GrassLayer& layer) { return layer.name == name; });
}

}  // namespace

std::string freeLayerName(const std::vector<GrassLayer>& layers, const std::string& base) {
    return freeName(layers, base);
}

bool addLayer(Project& project) {
    if (project.layers.size() >= MAX_LAYERS)
        return false;
    GrassLayer layer;
    layer.name = freeLayerName(project.layers, layer.name);
    project.layers.push_back(std::move(layer));
    return true;
}

bool duplicateLayer(Project& project, std::size_t index) {
    if (index >= project.layers.size() || project.layers.size() >= MAX_LAYERS)
        return false;
    GrassLayer copy = project.layers[index];
    copy.name = freeLayerName(project.layers, copy.name + " copy");
    project.layers.insert(project.layers.begin() + std::ptrdiff_t(index + 1), std::move(copy));
    return true;
}

bool removeLayer(Project& project, std::size_t index) {
    if (index >= project.layers.size() || project.layers.size() <= 1)
        return false;
    project.layers.erase(project.layers.begin() + std::ptrdiff_t(index));
    return true;
}

bool moveLayer(Project& project, std::size_t index, bool up) {
    if (index >= project.layers.size() || (up && index == 0) ||
        (!up && index + 1 >= project.layers.size()))
        return false;
    const std::size_t other = up ? index - 1 : index + 1;
    std::swap(project.layers[index], project.layers[other]);
    return true;
}

bool renameLayer(Project& project, std::size_t index, const std::string& name) {
    if (index >= project.layers.size() || name.empty())
        return false;
    if (project.layers[index].name == name)
        return true;
    if (hasName(project.layers, name))
        return false;
    project.layers[index].name = name;
    return true;
}

std::vector<std::optional<std::size_t>> matchLayers(const std::vector<std::string>& before,
                                                    const std::vector<std::string>& after) {
    std::vector<std::optional<std::size_t>> match(after.size());
    for (std::size_t j = 0; j < after.size(); ++j) {
        if (const auto same = std::find(before.begin(), before.end(), after[j]);
            same != before.end()) {
            match[j] = std::size_t(same - before.begin());
        } else if (j < before.size() &&
                   std::find(after.begin(), after.end(), before[j]) == after.end()) {
            match[j] = j;  // renamed in place
        }
    }
    return match;
}

}  // namespace grass::core
