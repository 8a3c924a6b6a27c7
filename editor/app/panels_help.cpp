// Help › Keyboard shortcuts (issue 26 item 4): every key of the editor in one window, from the
// one table the window and the test read (keyboardShortcuts, panels.h). Help › About grass: the
// version, the OpenGL renderer and where the guide and the autosaves are, to copy into a report.
#include <algorithm>
#include <array>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "app/autosave.h"
#include "app/panels.h"
#include "ui/menu.h"
#include "ui/ui.h"
#include "ui/window.h"
#include "util/version.h"

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
        m.separator();
        if (ui::menuItem(m, "About grass"))
            s.transient.aboutWindow = true;
    });
}

std::vector<std::string> aboutLines(const EditorState& s) {
    std::vector<std::string> lines{
        "grass-editor " + std::string(core::versionText()),
        "An authoring editor for real-time grass fields.",
        "OpenGL: " + (s.glRenderer.empty() ? std::string("not known yet") : s.glRenderer)};
    // The guide where this build's sources are (the shaders and default projects are read
    // there too); an installed copy without them says where the guide is kept.
    const std::filesystem::path guide = std::filesystem::path(GRASS_SOURCE_DIR) / "docs/editing.md";
    std::error_code ec;
    lines.push_back("Guide: " + (std::filesystem::is_regular_file(guide, ec)
                                     ? guide.string()
                                     : std::string("docs/editing.md in grass's sources")));
    const std::filesystem::path unsaved = unsavedAutosaveRoot();
    lines.push_back("Never-saved projects autosave into: " +
                    (unsaved.empty()
                         ? std::string("nowhere (neither XDG_STATE_HOME nor HOME is set)")
                         : unsaved.string()));
    return lines;
}

void aboutWindow(ui::Context& ctx, EditorState& s) {
    if (!s.transient.aboutWindow)
        return;
    const ui::Rect screen = ctx.screenRect();
    const float width = std::max(300.0f, std::min(560.0f, screen.width() - 20.0f));
    const std::vector<std::string> lines = aboutLines(s);
    ui::window(
        ctx, "About grass", &s.transient.aboutWindow,
        [&](ui::Ui& ui) {
            // First, as in Messages: long paths wrap onto more lines than a small window shows.
            if (ui.button("Copy").onHoverText("Copy these lines (for a bug report)").clicked()) {
                std::string all;
                for (const std::string& line : lines)
                    all += line + "\n";
                ctx.output().copiedText = all;
            }
            ui.separator();
            for (const std::string& line : lines)
                ui.wrappedLabel(line);
        },
        ui::Rect::fromMinSize({screen.centre().x - 0.5f * width, screen.min.y + 80.0f},
                              {width, 200.0f}));
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
