// The project's file, or a map painted here, changed on disk since it was opened or saved here
// (another program wrote it: a text editor, a second editor window, a checkout, an image
// editor): a Save asks before replacing it, as a text editor does, instead of losing that work
// without a word. Replace it, save elsewhere, take the file's project instead (undoable), or keep
// both as they are.
#include <string>

#include "app/panels.h"
#include "app/project_file_watch.h"
#include "ui/text_wrap.h"
#include "ui/ui.h"
#include "ui/window.h"

namespace grass::editor {

void changedOnDiskWindow(ui::Context& ctx, EditorState& s) {
    if (!s.transient.changedOnDisk)
        return;
    const ui::Rect screen = ctx.screenRect();
    const std::string said =
        s.transient.changedOnDiskSaid + ". Saving replaces those changes with the project shown.";
    // Tall enough for the text as it wraps (a long path takes lines of its own) and the buttons.
    constexpr float WIDTH = 460.0f;
    const ui::Style& style = ctx.style();
    const float height =
        70.0f +
        ui::linesHeight(ctx.fonts(), style.textSizePt, style.itemSpacing.y,
                        ui::wrapText(ctx.fonts(), style.textSizePt, said, WIDTH - 24.0f).size());
    ui::window(
        ctx, "Changed on disk", &s.transient.changedOnDisk,
        [&](ui::Ui& ui) {
            ui.wrappedLabel(said);
            ui.horizontal([&](ui::Ui& row) {
                if (row.button("Replace it")
                        .onHoverText("Save the project shown over the changed file")
                        .clicked() &&
                    saveTo(s, s.doc.loaded.file.string(), true) && s.transient.quitDialog)
                    // Asked by "Save and quit" (or before New, Open): saved now, go on.
                    askLeave(s, s.transient.leaveAction, s.transient.leaveOpenPath);
                if (row.button("Save As…")
                        .onHoverText("Save the project shown elsewhere; the changed file stays")
                        .clicked()) {
                    s.transient.changedOnDisk = false;
                    openBrowser(s, BrowsePurpose::SaveProject);
                }
                // The other program's project wins; the changes made here stay in the undo
                // history. Not for maps alone: they are grown from as they are once saved.
                if (s.transient.changedOnDiskProjectFile &&
                    row.button("Take the file's")
                        .onHoverText("Take the project as the file holds it; Ctrl+Z brings back "
                                     "the changes made here")
                        .clicked()) {
                    s.transient.changedOnDisk = false;
                    s.transient.quitDialog = false;  // a pending quit or open waits for the user
                    takeProjectFileFromDisk(s);
                }
                if (row.button("Cancel")
                        .onHoverText(
                            "Save nothing: the file and the project shown stay as they are")
                        .clicked())
                    s.transient.changedOnDisk = false;
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 0.5f * WIDTH, screen.centre().y - 0.5f * height},
                              {WIDTH, height}));
}

}  // namespace grass::editor
