// Every change to the document (editor_state.h) is a Command, and apply() is the only code that
// changes it: it replaces the project, records the undo step, marks the document unsaved and asks
// for the re-grow the change needs. The panels (their working copy, buildPanels), the keys (T, L,
// Ctrl+Z), the gizmo, the brush and replayed scripts (which drive those same panels, keys and
// tools) all end in a command here.
#pragma once

#include <string>
#include <variant>

#include "app/editor_state.h"

namespace grass::editor {

// What a project change costs the live field.
enum class EditEffect {
    Live,    // read by the renderer every frame (colours, shapes, render settings): nothing to do
    Regrow,  // the scene is grown from it (scatter, growth, wind, colliders, physics)
    Grown,   // a field was grown for it already (an imported mesh): undoing it grows again
};

// The project becomes `after`. While `ongoing` (a drag or a text entry under way) the picture
// follows but no undo step is made; the first command after it that is not ongoing makes the
// whole change since the last step one step (a drag is one step, not one per frame).
struct EditProject {
    core::Project after;
    EditEffect effect = EditEffect::Live;
    bool ongoing = false;
    std::string label = {};  // empty: named after the part of the project that changed
};

// A finished brush stroke: its texels were painted and re-grown dab by dab while it ran (the
// brush must be seen as it moves); this records it as one undo step of the document.
struct RecordStroke {
    core::PaintEdit edit;
    std::string label = {};  // empty: "paint <map>"
};

struct Undo {};
struct Redo {};

using Command = std::variant<EditProject, RecordStroke, Undo, Redo>;

// Applies `command` to the state's document. False when it changed nothing: nothing to undo or
// redo, or undo during a tool drag or an export.
bool apply(EditorState& state, Command command);

// The settling command of a frame: the project as it is, ongoing while a widget
// (`widgetActive`) or a tool drag is active — so an edit that has just ended becomes its step.
void recordProjectEdit(EditorState& state, bool widgetActive);
bool undo(EditorState& state);
bool redo(EditorState& state);

}  // namespace grass::editor
