// The editor's keys when no widget has the keyboard (window.h lists them): 1-4 switch a cull
// test of the view, T and L the project's technique and lighting, the tools' keys
// (viewport_tools.h), Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y undo and redo, Ctrl+S saves (with the UI,
// where Save As can ask for a path). Document changes are commands (commands.h).
#pragma once

#include <string>

#include "app/editor_state.h"
#include "app/window.h"

namespace grass::editor {

// Applies this frame's keys; returns what a render key changed, for the console (or empty).
// None while a document job runs (EditorState::loading()).
std::string applyEditorKeys(EditorState& state, const InputState& input, bool withUi);

}  // namespace grass::editor
