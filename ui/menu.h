// Menus: a menu bar row, menu buttons that open a popup list below them, and menu items.
// One menu is open at a time (the context's popup); while one is open, hovering another menu
// button of the same bar switches to it; Escape or a press outside closes it; clicking an item
// closes it. Sizes in points.
#pragma once

#include <string_view>

#include "ui/ui.h"

namespace grass::ui {

// A full-width horizontal row with the panel background in which `fn` calls menu(). Returns the
// bar's rect.
Rect menuBar(Ui& ui, const UiFn& fn);

// A flat button showing `label`; a click toggles its popup, which `fn` fills with menuItem()s
// (or any widgets). Returns whether the menu is open (fn ran) this frame.
bool menu(Ui& ui, std::string_view label, const UiFn& fn);

// A full-width row: label left, `shortcutText` (shown, not handled) right. True once, on the
// frame it is clicked; the click also closes the menu. A disabled row is greyed, and a click on
// it does nothing (Edit › Undo with nothing to undo).
// "Text##key" shows Text (the whole label is the id).
bool menuItem(Ui& ui, std::string_view label, std::string_view shortcutText = {},
              bool enabled = true);

}  // namespace grass::ui
