#include "app/editor_keys.h"

#include <algorithm>

#include "app/commands.h"
#include "app/panels.h"
#include "app/viewport_tools.h"

namespace grass::editor {

namespace {

// Keys that change how the field is drawn (window.h); returns what changed, for the console.
// 1-4 switch a cull test of the view; T and L change the project's technique and lighting (a
// command like the Render panel's combo boxes: saved, undoable, marking it unsaved).
std::string applyRenderKeys(const InputState& input, EditorState& state) {
    ViewOverrides& view = state.view.overrides;
    bool* tests[] = {&view.orientation, &view.frustum, &view.distance, &view.occlusion};
    const char* names[] = {"orientation", "frustum", "distance", "occlusion"};
    if (input.toggledCullTest >= 1 && input.toggledCullTest <= 4) {
        bool& test = *tests[input.toggledCullTest - 1];
        test = !test;
        return std::string(names[input.toggledCullTest - 1]) + " culling " + (test ? "on" : "off");
    }
    core::Project project = state.doc.project();
    std::string changed;
    if (input.nextTechnique) {
        project.render.technique =
            static_cast<core::GrassTechnique>((static_cast<int>(project.render.technique) + 1) % 4);
        changed = "technique " + std::string(core::grassTechniqueName(project.render.technique));
    } else if (input.toggleLighting) {
        core::LightingModel& model = project.lighting.model;
        model = model == core::LightingModel::Grass ? core::LightingModel::Simple
                                                    : core::LightingModel::Grass;
        changed = model == core::LightingModel::Grass ? "grass lighting" : "simple lighting";
    } else {
        return {};
    }
    apply(state, EditProject{.after = std::move(project), .label = changed});
    return changed;
}

}  // namespace

std::string applyKeysUpTo(EditorState& state, const InputState& input, bool withUi,
                          KeysTaken& taken, KeysTaken until) {
    // While a New, Open or import grows its field the document stays as it is: the keys that
    // edit, save or replace it wait with the panels (the camera still moves).
    if (state.loading())
        return {};
    until.keys = std::min(until.keys, input.keys.size());
    until.typed = std::min(until.typed, input.typed.size());
    const std::string_view typed =
        taken.typed < until.typed
            ? std::string_view(input.typed).substr(taken.typed, until.typed - taken.typed)
            : std::string_view();
    std::string changed;
    applyToolKeys(state, typed);
    // Space plays and pauses the timeline, as in Blender and most players.
    if (typed.find(' ') != std::string_view::npos) {
        state.view.timeJump = state.view.timeline.toggle();
        changed = state.view.timeline.playing() ? "playing" : "paused";
    }
    for (std::size_t k = taken.keys; k < until.keys; ++k) {
        const ui::KeyEvent& key = input.keys[k];
        // Delete removes the selected wind source or collider (the keyboard is the viewport's
        // here: a focused text field keeps its Delete).
        if (key.key == ui::Key::Delete && !key.modifiers.ctrl)
            if (const auto removed = deleteSelection(state))
                changed = "deleted " + *removed;
        if (!key.modifiers.ctrl)
            continue;
        if (key.key == ui::Key::Z)
            key.modifiers.shift ? redo(state) : undo(state);
        else if (key.key == ui::Key::Y)
            redo(state);
        else if (key.key == ui::Key::S && withUi && key.modifiers.shift)
            openBrowser(state, BrowsePurpose::SaveProject);
        else if (key.key == ui::Key::S && withUi)
            saveOrAsk(state);
        else if (key.key == ui::Key::N && withUi)
            askLeave(state, LeaveAction::New);
        else if (key.key == ui::Key::O && withUi)
            openBrowser(state, BrowsePurpose::OpenProject);
    }
    taken.keys = std::max(taken.keys, until.keys);
    taken.typed = std::max(taken.typed, until.typed);
    return changed;
}

std::string applyEditorKeys(EditorState& state, const InputState& input, bool withUi,
                            KeysTaken taken) {
    if (state.loading())
        return {};
    const std::string rendered = applyRenderKeys(input, state);
    const std::string changed =
        applyKeysUpTo(state, input, withUi, taken, {input.keys.size(), input.typed.size()});
    return changed.empty() ? rendered : changed;
}

}  // namespace grass::editor
