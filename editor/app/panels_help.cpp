// Help › Keyboard shortcuts (issue 26 item 4): every key of the editor in one window, from the
// one table the window and the test read (keyboardShortcuts, panels.h).
#include <algorithm>
#include <array>

#include "app/panels.h"
#include "ui/menu.h"
#include "ui/ui.h"
#include "ui/window.h"

namespace grass::editor {

namespace {

constexpr std::array SHORTCUTS{
    Shortcut{"c", "camera tool: a left-drag in the view orbits"},
    Shortcut{"b", "brush tool: a left-drag paints the chosen map"},
    Shortcut{"g", "gizmo tool: a click selects a wind source or collider"},
    Shortcut{"w / e / r", "gizmo: move / rotate / scale"},
    Shortcut{"[ / ]", "brush: smaller / larger"},
    Shortcut{"Ctrl (while painting)", "brush: subtract instead of add"},
    Shortcut{"Ctrl (while dragging the gizmo)", "gizmo: snap"},
    Shortcut{"middle-drag, Shift+drag", "pan the view"},
    Shortcut{"wheel", "zoom"},
    Shortcut{"right-drag", "orbit in the brush and gizmo tools"},
    Shortcut{"F", "frame the selected object, else the whole scene"},
    Shortcut{"Delete", "remove the selected wind source or collider"},
    Shortcut{"Space", "play / pause the timeline"},
    Shortcut{"1 2 3 4", "view only: orientation, frustum, distance, occlusion culling on/off"},
    Shortcut{"T", "next grass technique (blades, billboards, hybrid, growth)"},
    Shortcut{"L", "grass lighting / simple lighting"},
    Shortcut{"Ctrl+Z", "undo"},
    Shortcut{"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    Shortcut{"Ctrl+S", "save (asks for a place the first time)"},
    Shortcut{"Ctrl+Shift+S", "save as: the file browser"},
    Shortcut{"Ctrl+N", "new project (asks first when there are unsaved changes)"},
    Shortcut{"Ctrl+O", "open a project: the file browser"},
    Shortcut{"drop a .gltf / .glb", "import it as the project's surface (one undo step)"},
    Shortcut{"drop a .png / .exr / ...", "import it as the brush's map of the brush's layer"},
    Shortcut{"drop a project folder", "open it"},
    Shortcut{"double-click (browser)", "enter a folder, choose a file"},
    Shortcut{"Enter", "in a path or number field: confirm"},
    Shortcut{"Escape", "close a menu, a popup or a text field"},
};

}  // namespace

std::span<const Shortcut> keyboardShortcuts() {
    return SHORTCUTS;
}

void helpMenu(ui::Ui& bar, EditorState& s) {
    ui::menu(bar, "Help", [&](ui::Ui& m) {
        if (ui::menuItem(m, "Keyboard shortcuts"))
            s.transient.shortcutsWindow = true;
        if (ui::menuItem(m, "Messages"))
            s.transient.messagesWindow = true;
    });
}

void shortcutsWindow(ui::Context& ctx, EditorState& s) {
    if (!s.transient.shortcutsWindow)
        return;
    bool open = true;
    const ui::Rect screen = ctx.screenRect();
    // The whole table on a screen of 1000 points or more; a smaller one scrolls it.
    const float height = std::max(200.0f, std::min(920.0f, screen.height() - 70.0f));
    const float width = std::max(300.0f, std::min(740.0f, screen.width() - 20.0f));
    const ui::Rect defaultRect = ui::Rect::fromMinSize(
        {screen.centre().x - 0.5f * width, screen.min.y + 40.0f}, {width, height});
    ui::window(
        ctx, "Keyboard shortcuts", &open,
        [&](ui::Ui& ui) {
            ui.scrollArea("shortcuts scroll", ui.availableRect().height(), [&](ui::Ui& body) {
                body.coloredLabel("Keys act while no text field has the keyboard.",
                                  body.style().textWeak);
                body.grid("shortcuts", 2, [&](ui::Ui& grid) {
                    for (const Shortcut& shortcut : SHORTCUTS) {
                        grid.label(shortcut.keys);
                        grid.label(shortcut.what);
                    }
                });
            });
        },
        defaultRect);
    if (!open)
        s.transient.shortcutsWindow = false;
}

}  // namespace grass::editor
