// The message log (issue 26 item 4): every status message the editor shows (saved, opened,
// refused, imported, autosaved…) is kept, newest last, and the status bar's message opens a
// window that shows each one whole, wrapped to the window: the status line is cut off at the
// window's edge, and a path or an error is exactly what must be read in full.
#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "app/panels.h"
#include "ui/text_wrap.h"
#include "ui/window.h"

namespace grass::editor {

void logMessage(EditorState& s, double timeS) {
    Transient& t = s.transient;
    if (t.message.empty() || t.message == t.loggedMessage)
        return;
    t.loggedMessage = t.message;
    t.messageLoggedAtS = timeS;
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%.1f s  ", timeS);
    t.messageLog.push_back(stamp + t.message);
    if (t.messageLog.size() > MAX_LOGGED_MESSAGES)
        t.messageLog.erase(t.messageLog.begin());
}

void messagesWindow(ui::Context& ctx, EditorState& s) {
    if (!s.transient.messagesWindow)
        return;
    const ui::Rect screen = ctx.screenRect();
    ui::window(
        ctx, "Messages", &s.transient.messagesWindow,
        [&](ui::Ui& ui) {
            const std::vector<std::string>& log = s.transient.messageLog;
            ui.horizontal([&](ui::Ui& row) {
                if (row.button("Copy all").onHoverText("Copy every message to the clipboard").clicked()) {
                    std::string all;
                    for (const std::string& message : log)
                        all += message + "\n";
                    ctx.output().copiedText = all;
                }
                if (row.button("Clear").onHoverText("Forget the messages shown here").clicked())
                    s.transient.messageLog.clear();
            });
            ui.separator();
            const float width = ui.availableWidth() - 2.0f * ui.style().itemSpacing.x - 12.0f;
            ui.scrollArea("log", std::max(60.0f, ui.availableRect().height()), [&](ui::Ui& list) {
                if (log.empty())
                    list.coloredLabel("(no messages yet)", list.style().textWeak);
                for (std::size_t i = 0; i < log.size(); ++i) {
                    list.withId(i, [&](ui::Ui& item) {
                        for (const std::string& line :
                             ui::wrapText(ctx.fonts(), item.style().textSizePt, log[i], width))
                            item.label(line);
                    });
                    list.separator();
                }
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 300.0f, screen.max.y - 330.0f}, {600.0f, 280.0f}));
}

}  // namespace grass::editor
