// The project's layers as species (issue 27 item 2): added, duplicated, removed, renamed and
// reordered as project edits, each name kept unique (the format refuses twins), and the rule by
// which a re-grown scene finds, for each of its layers, the layer it was before an edit (so the
// maps painted since the last save follow their layer through a reorder or a removal).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "project/project.h"

namespace grass::core {

// `base`, or "base 2", "base 3", ... : the first name no layer of `layers` has.
std::string freeLayerName(const std::vector<GrassLayer>& layers, const std::string& base);

// A new layer with the default settings, named "grass" or the first free "grass N", appended.
// False when the project holds MAX_LAYERS already.
bool addLayer(Project& project);
// A copy of layer `index` (settings, rules and map files) named "<name> copy", placed after it.
bool duplicateLayer(Project& project, std::size_t index);
// Removes layer `index`; a project keeps at least one layer (the format's files always have).
bool removeLayer(Project& project, std::size_t index);
// Moves layer `index` one place up (towards 0) or down. False at the ends.
bool moveLayer(Project& project, std::size_t index, bool up);
// Renames layer `index` to `name` when no other layer has it and it is not empty; false else.
bool renameLayer(Project& project, std::size_t index, const std::string& name);

// For each layer of `after`, the index in `before` of the layer it was: the layer of the same
// name, else the layer at the same index when no layer of `after` carries that one's name (a
// rename), else none (a new layer).
std::vector<std::optional<std::size_t>> matchLayers(const std::vector<std::string>& before,
                                                    const std::vector<std::string>& after);

}  // namespace grass::core
