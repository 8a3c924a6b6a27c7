// While a New, Open, import or recovery grows its field on a worker (document_job.h): the panels
// wait under a veil, and a box over the viewport says what is being read or grown and for how
// long, with a Cancel that gives the window back at once with the document as it was. The
// viewport stays the user's: the old field goes on playing and the camera moves.
#include <array>
#include <cstdio>
#include <string>
#include <utility>

#include "app/panels.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

const ui::Vec2 BOX_SIZE{380.0f, 88.0f};

}  // namespace

void loadingWindow(ui::Context& ctx, ui::Rect viewport, EditorState& s) {
    if (!s.documentJob)
        return;
    const ui::Style& style = ctx.style();
    const ui::Rect screen = ctx.screenRect();
    // Nothing may edit the document meanwhile: no text entry keeps the keyboard, no menu stays
    // open, and every panel around the viewport takes the pointer without passing it on.
    ctx.clearFocus();
    ctx.closePopup();
    const std::array<ui::Rect, 4> veils{
        ui::Rect{screen.min, {screen.max.x, viewport.min.y}},
        ui::Rect{{screen.min.x, viewport.max.y}, screen.max},
        ui::Rect{{screen.min.x, viewport.min.y}, {viewport.min.x, viewport.max.y}},
        ui::Rect{{viewport.max.x, viewport.min.y}, {screen.max.x, viewport.max.y}},
    };
    ui::Painter painter = ctx.painter(ui::Layer::Foreground, screen);
    const ui::Id id = ctx.currentId().with("loading");
    for (std::size_t i = 0; i < veils.size(); ++i) {
        const ui::Rect& veil = veils[i];
        if (veil.width() <= 0.0f || veil.height() <= 0.0f)
            continue;
        painter.rect(veil, 0.0f, ui::Color32{12, 12, 12, 150});
        ctx.interact(veil, screen, ui::Layer::Foreground, id.with(i), ui::Sense::clickAndDrag());
        ctx.registerArea(veil);
    }
    const ui::Rect box = ui::Rect::fromMinSize(viewport.centre() - BOX_SIZE * 0.5f, BOX_SIZE);
    painter.rect(box, style.rounding, style.popupFill, style.popupStroke);
    ctx.interact(box, screen, ui::Layer::Foreground, id.with("box"), ui::Sense::hover());
    ctx.registerArea(box);
    ui::Ui ui(ctx, box.expand(-10.0f), ui::Layer::Foreground);
    ui.coloredLabel(s.documentJob->title(), style.textStrong);
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, " … %.0f s", s.documentJob->elapsedS());
    ui.coloredLabel(s.documentJob->stage() + elapsed, style.text);
    if (ui.button("Cancel")
            .onHoverText("Stop waiting and go on with the project as it is")
            .clicked()) {
        cancelDocumentJob(s);
    }
}

void cancelDocumentJob(EditorState& s) {
    if (!s.documentJob)
        return;
    // The worker stops at its next stage (a read or a growth is not stopped halfway); what it
    // made is dropped.
    s.transient.message = "cancelled: " + s.documentJob->title();
    s.documentJob->cancel();
    s.cancelledJobs.push_back(std::move(s.documentJob));
}

}  // namespace grass::editor
