// The history's and the painted maps' life cycle (issue 8): a fresh history for a new document,
// painted maps surviving a re-grow of the scene and reaching the disk on save. Undo, redo and
// how edits become history steps are commands (app/commands.h).
#pragma once

#include <filesystem>

#include "app/commands.h"
#include "app/panels.h"
#include "util/result.h"

namespace grass::editor {

// Starts the history afresh (a project was opened or created), and the watch of the project's
// files (project_file_watch.h): the field was just grown from them as they are.
void resetHistory(EditorState& state);

// The painted maps of `from` carried into `to` (a scene re-grown after a panel edit), which is
// then re-grown where they differ from what it loaded. Each layer of `to` takes the maps of the
// layer it was (core::matchLayers: by name, so they follow a reorder); a removed layer's maps
// wait in Document::waitingMaps for an undo to bring it back.
Result<void> carryPaintedMaps(EditorState& state, core::Scene& from, core::Scene& to);

// The paint tool's map of the paint tool's layer becomes the picture in `file` (resampled to the
// map's size), one undo step like a stroke; saved as painted maps are. The status bar says what
// happened (or why not: no such layer, an unreadable picture).
bool importMapImage(EditorState& state, const std::filesystem::path& file);

// Writes the paint tool's map of the paint tool's layer, as it is now (painted or not yet saved;
// a map never painted is 1 everywhere at the layer's map resolution), to `file`: PNG (16-bit),
// TIFF or EXR by extension, atomically. The status bar says where, or why not.
bool exportMapImage(EditorState& state, const std::filesystem::path& file);

// Writes every painted map into `folder` (the layer's own file, else maps/<layer>-<map>.png) and
// names it in the project; atomic per file. Called by saveTo before project.json is written. A
// file another map of the project also reads (a duplicated layer's) is left as it is: the
// painted map goes to the layer's own default file instead.
Result<void> savePaintedMaps(EditorState& state, const std::filesystem::path& folder);
// Whether more than one map of the project reads `file` (then a painted one is saved elsewhere).
bool mapFileShared(const core::Project& project, const std::string& file);

}  // namespace grass::editor
