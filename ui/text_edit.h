// Single-line text editing and typed number entry, as free widgets over ui::Ui.
//
// textEdit edits a UTF-8 std::string in place: a click focuses it and places the cursor (byte
// offsets always on code point boundaries), typing inserts Input::text, arrows/Home/End move
// (Shift extends the selection), Backspace/Delete remove the selection or one code point,
// Ctrl+A/C/X/V select all, copy, cut and paste (through Output::copiedText and
// Input::clipboardText), a double click selects all. Enter or losing focus commits; Escape
// restores the text the widget had when it got focus. Text wider than the box scrolls
// horizontally to keep the cursor visible. Sizes in points.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <string_view>

#include "ui/ui.h"

namespace grass::ui {

// `idLabel` gives the id; the part before "##" (all of it if there is none) is drawn as a label
// right of the box, so "##name" is an unlabelled box. `width` is the box's width. The Response
// reports changed() on every frame the text changed, hasFocus() while editing; `committed`,
// when given, is set to whether the edit was committed this frame (Enter or focus loss, not
// Escape).
Response textEdit(Ui& ui, std::string_view idLabel, std::string& text, float width,
                  bool* committed = nullptr);

// A tooltip of a typeable number, with how to type it: "<tooltip>; click (without dragging) to
// type a value" (one wording for every such box).
std::string withTypingHint(std::string_view tooltip);

// Why a typed number is refused ("must be in (0, 5000] m"); empty: it is taken.
using NumberCheck = std::function<std::string(double)>;

// A drag value (Ui::dragValue) that a click without a drag (or a double-click, or Ctrl+click)
// turns into a text box for typing the number. Enter takes it when it is a number that `check`
// accepts (without a check: one in [min, max]; an integer must be whole); otherwise the box stays
// open, outlined, with the reason under it: a refused value is never clamped or reverted silently.
// Clicking elsewhere leaves it showing; Escape in the box cancels, the value untouched.
Response dragValueWithEntry(Ui& ui, std::string_view label, float& value, float speed,
                            float min = -std::numeric_limits<float>::infinity(),
                            float max = std::numeric_limits<float>::infinity(), int decimals = 3,
                            const NumberCheck& check = {});
Response dragValueWithEntry(Ui& ui, std::string_view label, int& value, float speed, int min,
                            int max, const NumberCheck& check = {});

// A slider track followed by a dragValueWithEntry box and the label, as egui's slider: drag the
// track, drag the box, or click the box to type a value.
Response sliderWithEntry(Ui& ui, std::string_view label, float& value, float min, float max,
                         const SliderOptions& options = {}, const NumberCheck& check = {});

// Cursor editing helpers on UTF-8 byte offsets, exposed for tests.
std::size_t nextCodePoint(std::string_view text, std::size_t pos);
std::size_t prevCodePoint(std::string_view text, std::size_t pos);

}  // namespace grass::ui
