// Replacing the open document (File → New, Open, the recovered autosave): the new project's
// field is grown whole first, and only then does anything change. A failure (a broken mesh, a
// missing map) leaves the previous document, its live field, its history and the window title
// as they were, and says why in the status bar: before, the panel and title switched to the new
// project while the viewport kept the old scene, and a Ctrl+S then saved the mix.
#pragma once

#include <string_view>

#include "app/live_scene.h"
#include "app/panels.h"

namespace grass::editor {

// Grows `next` into a live field and, on success, makes it the document: state.doc.loaded, the
// scene and tools pointers, a fresh history. `what` names the action in the message on failure
// ("cannot open"). True when replaced.
bool replaceDocument(EditorState& state, Live& live, core::LoadedProject next, bool withPhysics,
                     std::string_view what, PhysicsDevice device = PhysicsDevice::Auto);
// The same with the field already grown (on a worker, document_job.h): brought up on the GPU
// here, then made the document.
bool replaceDocument(EditorState& state, Live& live, GrownField next, std::string_view what,
                     PhysicsDevice device = PhysicsDevice::Auto);

}  // namespace grass::editor
