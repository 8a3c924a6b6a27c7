// Undo, redo and the painted maps' life cycle (issue 8): what the Edit menu, Ctrl+Z and
// Ctrl+Shift+Z do, how panel edits become history steps, and how painted maps survive a re-grow
// of the scene and reach the disk on save.
#pragma once

#include <filesystem>

#include "app/panels.h"
#include "util/result.h"

namespace grass::editor {

// Records the project's change since the last step as one step, once no widget (`widgetActive`)
// and no tool drag is active; does nothing while one is, or when nothing changed.
void recordProjectEdit(EditorState& state, bool widgetActive);

// Reverts / re-applies the newest step: a project step replaces the project (the scene re-grows),
// a paint step writes its texels back and re-grows the patches they reach. False when there is
// nothing to undo / redo (or a tool drag is under way).
bool undo(EditorState& state);
bool redo(EditorState& state);

// Starts the history afresh (a project was opened or created).
void resetHistory(EditorState& state);

// The painted maps of `from` carried into `to` (a scene re-grown from the same project after a
// panel edit), which is then re-grown where they differ from what it loaded.
Result<void> carryPaintedMaps(const EditorState& state, core::Scene& from, core::Scene& to);

// Writes every painted map into `folder` (the layer's own file, else maps/<layer>-<map>.png) and
// names it in the project; atomic per file. Called by saveTo before project.json is written.
Result<void> savePaintedMaps(EditorState& state, const std::filesystem::path& folder);

}  // namespace grass::editor
