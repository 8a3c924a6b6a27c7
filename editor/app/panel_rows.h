// What the side panel's sections share: a widget whose change re-grows the scene once the edit
// ends (panels.h says which edits apply next frame and which re-grow).
#pragma once

#include <span>
#include <string_view>

#include "app/editor_state.h"
#include "app/setting_widget.h"
#include "ui/ui.h"

namespace grass::editor {

// A value the scene is grown from changed: re-grow once the edit ends.
inline void regrow(EditorState& s, const ui::Response& r) {
    if (r.changed())
        s.transient.draft.regrow = true;
}

// The row of `key` in `table` for `value`; a change re-grows the scene.
template <class S>
void regrowRow(ui::Ui& ui, EditorState& s, std::span<const core::settings::Setting<S>> table,
               std::string_view key, S& value) {
    regrow(s, settingWidget(ui, table, key, value));
}

}  // namespace grass::editor
