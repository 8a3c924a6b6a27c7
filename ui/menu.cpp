// Menu bar, menus and menu items (menu.h).
#include "ui/menu.h"

#include <algorithm>

namespace grass::ui {

namespace {

// Which menu of a bar was opened last; a bar is "active" while that popup is still open.
struct MenuBarState {
    Id openMenu;
};

// Menus of one bar share the id stack top pushed by menuBar (or their parent's id when used
// without a bar), so they find the same state.
MenuBarState& barState(Context& ctx) {
    return ctx.state<MenuBarState>(ctx.currentId().with("menu bar"));
}

}  // namespace

Rect menuBar(Ui& ui, const UiFn& fn) {
    Context& ctx = ui.context();
    const Style& s = ui.style();
    Painter& painter = ui.painter();
    const std::size_t background = painter.addPlaceholder();
    const Vec2 origin = ui.nextItemPos();
    Rect bar;
    ui.horizontal([&](Ui& row) {
        ctx.pushId(ui.makeId("menu bar"));
        fn(row);
        ctx.popId();
        bar = {origin,
               {ui.maxRect().max.x, std::max(row.minRect().max.y, origin.y + s.interactHeight)}};
    });
    painter.set(background, RectShape{bar, 0.0f, s.panelFill, {}});
    ctx.registerArea(bar);
    return bar;
}

bool menu(Ui& ui, std::string_view label, const UiFn& fn) {
    Context& ctx = ui.context();
    const Style& s = ui.style();
    const Id id = ui.makeId(label);
    const Id popupId = id.with("menu");
    MenuBarState& bar = barState(ctx);
    const std::string_view shown = shownLabel(label);
    const Vec2 textSize = ctx.fonts().textSize(shown, s.textSizePt);
    const Rect rect = ui.allocate(
        {textSize.x + 2.0f * s.buttonPadding.x, std::max(s.interactHeight, textSize.y)});
    const Response r = ui.interact(rect, id, Sense::clickOnly());
    const bool barActive = ctx.isPopupOpen(bar.openMenu);
    if (r.clicked()) {
        if (ctx.isPopupOpen(popupId)) {
            ctx.closePopup();
        } else {
            ctx.openPopup(popupId);
            bar.openMenu = popupId;
        }
    } else if (barActive && r.hovered() && !ctx.isPopupOpen(popupId)) {
        // Sliding along an open bar switches menus without another click, as desktop menus do.
        ctx.openPopup(popupId);
        bar.openMenu = popupId;
    }
    const bool open = ctx.isPopupOpen(popupId);
    Painter& p = ui.painter();
    if (open) {
        p.rect(rect, s.rounding, s.selectionFill);
    } else if (r.hovered()) {
        p.rect(rect, s.rounding, s.hovered.bgFill);
    }
    p.text(rect.centre(), shown, s.textSizePt, open ? s.textStrong : ui.visuals(r).text,
           {0.5f, 0.5f});
    // Items close the menu themselves, so other widgets in a menu (check boxes) keep it open.
    return ui.popupBelow(popupId, rect, fn, false);
}

bool menuItem(Ui& ui, std::string_view label, std::string_view shortcutText, bool enabled) {
    Context& ctx = ui.context();
    const Style& s = ui.style();
    const FontAtlas& fonts = ctx.fonts();
    // "Text##key" shows Text and is keyed by the whole (two recent projects of one name).
    const std::string_view shown = shownLabel(label);
    const float labelWidth = fonts.textSize(shown, s.textSizePt).x;
    const float shortcutWidth = fonts.textSize(shortcutText, s.textSizePt).x;
    // A gap of several spaces between label and shortcut keeps the columns readable.
    const float gap = shortcutText.empty() ? 0.0f : 3.0f * s.itemSpacing.x;
    const float minWidth = labelWidth + gap + shortcutWidth + 2.0f * s.buttonPadding.x;
    const Rect rect = ui.allocate({std::max(ui.availableWidth(), minWidth), s.interactHeight});
    const Response r = ui.interact(rect, ui.makeId(label), Sense::clickOnly());
    Painter& p = ui.painter();
    const bool hot = enabled && r.hovered();
    if (hot) {
        p.rect(rect, s.rounding, s.selectionFill);
    }
    const Color32 text = !enabled ? s.textWeak : hot ? s.textStrong : s.text;
    p.text({rect.min.x + s.buttonPadding.x, rect.centre().y}, shown, s.textSizePt, text,
           {0.0f, 0.5f});
    if (!shortcutText.empty()) {
        p.text({rect.max.x - s.buttonPadding.x, rect.centre().y}, shortcutText, s.textSizePt,
               s.textWeak, {1.0f, 0.5f});
    }
    if (enabled && r.clicked()) {
        ctx.closePopup();
        return true;
    }
    return false;
}

}  // namespace grass::ui
