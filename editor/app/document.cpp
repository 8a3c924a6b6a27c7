#include "app/document.h"

#include <string>

#include "app/edit_actions.h"

namespace grass::editor {

bool replaceDocument(EditorState& state, Live& live, core::LoadedProject next, bool withPhysics,
                     std::string_view what, PhysicsDevice device, core::GltfImport* alreadyRead) {
    auto built = buildLive(next, withPhysics, {}, device, alreadyRead);
    if (!built) {
        state.transient.message = std::string(what) + ": " + built.error().str();
        return false;
    }
    const std::size_t steps = live.physics ? live.physics->steps : 0;
    live = std::move(*built);
    ++state.mapsChanged;  // the map overlay goes to the new renderer
    if (live.physics)
        live.physics->steps = steps;  // the field starts from rest, the clock goes on
    state.doc.loaded = std::move(next);
    state.scene = live.scene.get();
    state.tools = live.tools.get();
    resetHistory(state);
    return true;
}

}  // namespace grass::editor
