#include "app/document.h"

#include <string>

#include "app/edit_actions.h"

namespace grass::editor {

bool replaceDocument(EditorState& state, Live& live, core::LoadedProject next, bool withPhysics,
                     std::string_view what, PhysicsDevice device) {
    auto grown = growField(std::move(next), withPhysics);
    if (!grown) {
        state.transient.message = std::string(what) + ": " + grown.error().str();
        return false;
    }
    return replaceDocument(state, live, std::move(*grown), what, device);
}

bool replaceDocument(EditorState& state, Live& live, GrownField next, std::string_view what,
                     PhysicsDevice device) {
    auto built = bringUpLive(std::move(next), {}, device);
    if (!built) {
        state.transient.message = std::string(what) + ": " + built.error().str();
        return false;
    }
    const std::size_t steps = live.physics ? live.physics->steps : 0;
    live = std::move(*built);
    ++state.mapsChanged;  // the map overlay goes to the new renderer
    if (live.physics)
        live.physics->steps = steps;  // the field starts from rest, the clock goes on
    state.doc.loaded = live.builtFrom;
    state.scene = live.scene.get();
    state.tools = live.tools.get();
    resetHistory(state);
    return true;
}

}  // namespace grass::editor
