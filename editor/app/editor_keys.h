// The editor's keys when no widget has the keyboard (window.h lists them): 1-4 switch a cull
// test of the view, T and L the project's technique and lighting, the tools' keys
// (viewport_tools.h), Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y undo and redo, Ctrl+S saves (with the UI,
// where Save As can ask for a path). Document changes are commands (commands.h).
#pragma once

#include <string>

#include "app/editor_state.h"
#include "app/window.h"

namespace grass::editor {

// How much of a frame's key presses and typed text was applied already: those that came before
// one of its clicks are applied before that click (Editor::runInput), so that at a frame a
// second a Delete, an undo or a tool key quicker than a frame acts where it came.
struct KeysTaken {
    std::size_t keys = 0;   // of InputState::keys
    std::size_t typed = 0;  // bytes of InputState::typed
};

// Applies the keys that keep their order with the frame's clicks, from `taken` up to `until`
// (the tools' keys, Space, Delete, Ctrl+Z/Y/S/N/O), and moves `taken` there; returns what
// changed, for the console (or empty). None while a document job runs.
std::string applyKeysUpTo(EditorState& state, const InputState& input, bool withUi,
                          KeysTaken& taken, KeysTaken until);

// Applies this frame's keys not yet taken; returns what a key changed, for the console (or
// empty). None while a document job runs (EditorState::loading()).
std::string applyEditorKeys(EditorState& state, const InputState& input, bool withUi,
                            KeysTaken taken = {});

}  // namespace grass::editor
