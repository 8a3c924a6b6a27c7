// Single-line text edit and the typed number entry built on it (text_edit.h).
#include "ui/text_edit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "ui/number_text.h"

namespace grass::ui {

namespace {

constexpr double CARET_PERIOD_S = 1.0;
constexpr double CARET_SHOWN_S = 0.6;

bool isContinuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0u) == 0x80u;
}

// Pulls a byte offset back onto the start of a code point: the text may have been changed by the
// app since the cursor was stored.
std::size_t snap(std::string_view text, std::size_t pos) {
    pos = std::min(pos, text.size());
    while (pos > 0 && pos < text.size() && isContinuation(text[pos])) {
        --pos;
    }
    return pos;
}

struct TextEditState {
    std::size_t cursor = 0;
    // The other end of the selection; == cursor when nothing is selected.
    std::size_t anchor = 0;
    // How far the text is shifted left so the cursor stays in the box, points.
    float scroll = 0.0f;
    bool editing = false;
    // The text when focus arrived, for Escape.
    std::string original;
    // Restarts the caret blink on every edit or move so the caret is visible while typing.
    double lastActivityS = 0.0;
};

float offsetX(const FontAtlas& fonts, std::string_view text, std::size_t pos, float sizePt) {
    return fonts.textSize(text.substr(0, pos), sizePt).x;
}

// The code point boundary nearest to x (relative to the text start); glyph advances are what the
// tessellator uses to lay text out, so the cursor lands where the glyphs are drawn.
std::size_t hitTest(const FontAtlas& fonts, std::string_view text, float x, float sizePt) {
    float pen = 0.0f;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t next = pos;
        const float advance = fonts.glyph(decodeUtf8(text, next), sizePt).advance;
        if (x < pen + 0.5f * advance) {
            return pos;
        }
        pen += advance;
        pos = next;
    }
    return text.size();
}

// The editing logic; `edited` reports a text change (public callers turn it into changed()).
Response textEditImpl(Ui& ui, std::string_view idLabel, std::string& text, float width,
                      bool* committed, bool* edited) {
    Context& ctx = ui.context();
    const Style& s = ui.style();
    const FontAtlas& fonts = ctx.fonts();
    const float size = s.textSizePt;
    const std::string_view label = shownLabel(idLabel);
    const Vec2 labelSize = fonts.textSize(label, size);
    const float height =
        std::max(s.interactHeight, fonts.lineHeight(size) + 2.0f * s.buttonPadding.y);
    const Rect total =
        ui.allocate({width + (label.empty() ? 0.0f : s.itemSpacing.x + labelSize.x), height});
    const Rect box = Rect::fromMinSize(total.min, {width, height});
    const Id id = ui.makeId(idLabel);
    const Response r = ui.interact(box, id, Sense{true, true, true});
    TextEditState& st = ctx.state<TextEditState>(id);
    *committed = false;
    *edited = false;
    st.cursor = snap(text, st.cursor);
    st.anchor = snap(text, st.anchor);
    const double now = ctx.input().timeS;
    const float textLeft = box.min.x + s.buttonPadding.x;

    if (r.hasFocus() && !st.editing) {
        st.editing = true;
        st.original = text;
        // Focus by keyboard (Tab) or by a program (number entry) selects everything, ready to
        // be typed over; a click places the cursor below instead.
        st.anchor = 0;
        st.cursor = text.size();
        st.lastActivityS = now;
    } else if (!r.hasFocus() && st.editing) {
        st.editing = false;
        *committed = true;
    }
    if (r.hovered() || r.dragged()) {
        ctx.output().cursor = CursorIcon::Text;
    }

    if (r.hasFocus()) {
        const float pointerX = r.pointerPos().x - textLeft + st.scroll;
        if (r.hovered() && ctx.buttonPressed()) {
            st.cursor = hitTest(fonts, text, pointerX, size);
            if (!ctx.input().modifiers.shift) {
                st.anchor = st.cursor;
            }
            st.lastActivityS = now;
        } else if (r.dragged()) {
            st.cursor = hitTest(fonts, text, pointerX, size);
        }
        if (r.doubleClicked()) {
            st.anchor = 0;
            st.cursor = text.size();
        }

        const auto hasSelection = [&] { return st.cursor != st.anchor; };
        const auto eraseSelection = [&] {
            const std::size_t a = std::min(st.cursor, st.anchor);
            text.erase(a, std::max(st.cursor, st.anchor) - a);
            st.cursor = st.anchor = a;
            *edited = true;
        };
        const auto insert = [&](std::string_view typed) {
            if (typed.empty()) {
                return;
            }
            if (hasSelection()) {
                eraseSelection();
            }
            text.insert(st.cursor, typed);
            st.cursor += typed.size();
            st.anchor = st.cursor;
            st.lastActivityS = now;  // the caret stays shown while typing
            *edited = true;
        };
        // The frame's typed text and keys in the order they came (KeyEvent::textBefore): the
        // text typed before each key goes in before the key acts.
        const std::string& typed = ctx.input().text;
        std::size_t typedIn = 0;
        const auto insertTypedUpTo = [&](std::size_t end) {
            end = std::min(end, typed.size());
            if (end > typedIn) {
                insert(std::string_view(typed).substr(typedIn, end - typedIn));
                typedIn = end;
            }
        };

        // A copy: consumeKey below edits the input's key list.
        const std::vector<KeyEvent> keys = ctx.input().keys;
        for (const KeyEvent& e : keys) {
            insertTypedUpTo(e.textBefore);
            const bool shift = e.modifiers.shift;
            const bool ctrl = e.modifiers.ctrl && !e.modifiers.alt;
            bool used = true;
            const auto moveTo = [&](std::size_t pos) {
                st.cursor = pos;
                if (!shift) {
                    st.anchor = pos;
                }
            };
            switch (e.key) {
                case Key::Left:
                    // Without Shift a selection collapses to its start rather than moving on.
                    moveTo(hasSelection() && !shift ? std::min(st.cursor, st.anchor)
                                                    : prevCodePoint(text, st.cursor));
                    break;
                case Key::Right:
                    moveTo(hasSelection() && !shift ? std::max(st.cursor, st.anchor)
                                                    : nextCodePoint(text, st.cursor));
                    break;
                case Key::Home:
                    moveTo(0);
                    break;
                case Key::End:
                    moveTo(text.size());
                    break;
                case Key::Backspace:
                    if (!hasSelection()) {
                        st.anchor = prevCodePoint(text, st.cursor);
                    }
                    eraseSelection();
                    break;
                case Key::Delete:
                    if (!hasSelection()) {
                        st.anchor = nextCodePoint(text, st.cursor);
                    }
                    eraseSelection();
                    break;
                case Key::Enter:
                    st.editing = false;
                    *committed = true;
                    ctx.clearFocus();
                    break;
                case Key::Escape:
                    if (text != st.original) {
                        text = st.original;
                        *edited = true;
                    }
                    st.editing = false;
                    st.cursor = st.anchor = snap(text, st.cursor);
                    ctx.clearFocus();
                    break;
                case Key::A:
                    used = ctrl;
                    if (ctrl) {
                        st.anchor = 0;
                        st.cursor = text.size();
                    }
                    break;
                case Key::C:
                case Key::X:
                    used = ctrl;
                    if (ctrl && hasSelection()) {
                        const std::size_t a = std::min(st.cursor, st.anchor);
                        ctx.output().copiedText =
                            text.substr(a, std::max(st.cursor, st.anchor) - a);
                        if (e.key == Key::X) {
                            eraseSelection();
                        }
                    }
                    break;
                case Key::V: {
                    used = ctrl;
                    if (ctrl) {
                        // Single line: line breaks of the pasted text are dropped.
                        std::string paste = ctx.input().clipboardText;
                        std::erase_if(paste, [](char c) { return c == '\n' || c == '\r'; });
                        insert(paste);
                    }
                    break;
                }
                default:
                    used = false;
                    break;
            }
            if (used) {
                ctx.consumeKey(e.key, e.modifiers);
                st.lastActivityS = now;
            }
            if (!st.editing) {
                break;
            }
        }
        if (st.editing) {
            insertTypedUpTo(typed.size());
        }
    }

    // Scrolls just enough to keep the cursor inside the box, and never past the text's end.
    const float inner = std::max(0.0f, width - 2.0f * s.buttonPadding.x);
    const float textWidth = fonts.textSize(text, size).x;
    const float caretX = offsetX(fonts, text, st.cursor, size);
    if (r.hasFocus()) {
        st.scroll = std::clamp(st.scroll, caretX - inner, caretX);
    }
    st.scroll = std::clamp(st.scroll, 0.0f, std::max(0.0f, textWidth + 1.0f - inner));

    Painter& p = ui.painter();
    const WidgetVisuals& v = ui.visuals(r);
    const Stroke frame = r.hasFocus() ? Stroke{1.0f, s.accent} : v.bgStroke;
    p.rect(box, s.rounding, s.extremeBg, frame);
    p.pushClip({{textLeft - 1.0f, box.min.y}, {box.max.x - s.buttonPadding.x + 1.0f, box.max.y}});
    const float x0 = textLeft - st.scroll;
    const float lineH = fonts.lineHeight(size);
    const float top = box.centre().y - 0.5f * lineH;
    if (r.hasFocus() && st.cursor != st.anchor) {
        const float a = offsetX(fonts, text, std::min(st.cursor, st.anchor), size);
        const float b = offsetX(fonts, text, std::max(st.cursor, st.anchor), size);
        p.rect({{x0 + a, top}, {x0 + b, top + lineH}}, 0.0f, s.selectionFill);
    }
    p.text({x0, top}, text, size, v.text);
    // Blinks with a 1 s period, solid for the first 0.6 s after any activity; the next frame is
    // asked for at the next change, since an editor at rest draws only when something changes.
    if (r.hasFocus()) {
        const double phase = std::fmod(now - st.lastActivityS, CARET_PERIOD_S);
        const bool shown = phase < CARET_SHOWN_S;
        if (shown)
            p.line({x0 + caretX, top}, {x0 + caretX, top + lineH}, {1.0f, s.textStrong});
        ctx.requestRepaintAfter((shown ? CARET_SHOWN_S : CARET_PERIOD_S) - phase);
    }
    p.popClip();
    p.text({box.max.x + s.itemSpacing.x, box.centre().y}, label, size, s.text, {0.0f, 0.5f});
    return r;
}

std::string formatNumber(float value, int decimals) {
    return numberText(double(value), decimals);
}

// Enough digits to see a 1% step of the range (0..500 integers, 0..1 two decimals), the rule the
// slider's own value text follows.
int rangeDecimals(float min, float max) {
    const float range = std::abs(max - min);
    if (!(range > 0.0f) || !std::isfinite(range)) {
        return 3;
    }
    return std::clamp(int(std::ceil(-std::log10(range / 100.0f))), 0, 6);
}

struct EntryState {
    bool editing = false;
    bool hadFocus = false;
    double openedAtS = -1.0;  // the input time of the click that opened the box
    std::string buffer;
    std::string refused;  // why the typed text was not taken (empty: nothing refused)
};

// The typed number, or why it is none: the whole text (spaces around allowed) must be one
// finite number.
std::optional<double> parseTyped(const std::string& text) {
    char* end = nullptr;
    const double typed = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || !std::isfinite(typed))
        return std::nullopt;
    while (*end == ' ' || *end == '\t')
        ++end;
    if (*end != '\0')
        return std::nullopt;
    return typed;
}

// The box a drag value turns into for typing, shared by the float and integer entries. A
// click that does not drag opens it with the value selected, as egui's DragValue and Blender's
// number fields do (a double-click's second click keeps the selection; Ctrl+click too). Before,
// only a double-click or Ctrl+click opened it, and the single click a user tries first did
// nothing, the typing after it lost. Enter takes the typed value
// when `take` accepts it (returns an empty reason) and otherwise keeps the box open, outlined,
// with the reason under it, focused again for the correction. Clicking elsewhere leaves a
// refused entry showing (never a silent revert); Escape in the box cancels.
Response numberEntry(Ui& ui, std::string_view label, const std::function<Response()>& dragBox,
                     const std::function<std::string()>& current,
                     const std::function<std::string(double)>& take) {
    Context& ctx = ui.context();
    const Style& s = ui.style();
    EntryState& st = ctx.state<EntryState>(ui.makeId(label).with("entry"));
    // The text box gets its own id, but shows the same label.
    const std::string editId = std::string(label) + "##entry";
    if (!st.editing) {
        Response r = dragBox();
        if (r.clicked()) {  // a double-click's first click included
            st.editing = true;
            st.hadFocus = false;
            st.openedAtS = ctx.input().timeS;
            st.refused.clear();
            st.buffer = current();
            const Id textId = ui.makeId(editId);
            ctx.requestFocus(textId);
            // Context drops focus held by a widget it did not see this frame; this zero-size
            // interaction keeps the requested focus alive until the box appears next frame.
            ui.interact(Rect{}, textId, Sense::hover());
        }
        return r;
    }
    const float width =
        std::max(s.dragValueMinWidth,
                 ctx.fonts().textSize(st.buffer, s.textSizePt).x + 2.0f * s.buttonPadding.x);
    // The text edit consumes Enter: look before it, so a refusal by Enter keeps the focus.
    const bool enter = ctx.keyPressed(Key::Enter);
    bool committed = false;
    bool edited = false;
    const bool pressedSoonAfterOpening =
        ctx.buttonPressed() && ctx.input().timeS - st.openedAtS <= double(s.doubleClickTimeS);
    Response r = textEditImpl(ui, editId, st.buffer, width, &committed, &edited);
    // The second click of a double-click lands in the box the first opened, perhaps in the
    // same frame (then the context still sees the drag box there and would drop the focus): it
    // keeps the box focused with the value selected, to be typed over, instead of placing the
    // caret.
    if (pressedSoonAfterOpening && ctx.input().hasPointer &&
        r.rect().contains(ctx.input().pointerPos)) {
        ctx.requestFocus(r.id());
        TextEditState& text = ctx.state<TextEditState>(r.id());
        text.anchor = 0;
        text.cursor = st.buffer.size();
    }
    if (committed) {
        const std::optional<double> typed = parseTyped(st.buffer);
        st.refused = !typed ? "\"" + st.buffer + "\" is not a number" : take(*typed);
        if (st.refused.empty()) {
            st.editing = false;
            r.markChanged();
        } else if (enter) {
            ctx.requestFocus(r.id());
        }
    } else if (st.hadFocus && !r.hasFocus()) {
        // Escape: back to dragging, value untouched.
        st.editing = false;
        st.refused.clear();
    }
    st.hadFocus = r.hasFocus();
    if (st.editing && !st.refused.empty()) {
        const Rect box = Rect::fromMinSize(r.rect().min, {width, r.rect().height()});
        Painter over = ctx.painter(Layer::Foreground, ctx.screenRect());
        over.rect(box, s.rounding, Color32::transparent(), {1.5f, s.refused});
        const Vec2 size = ctx.fonts().textSize(st.refused, s.textSizePt);
        const Rect bubble = Rect::fromMinSize({box.min.x, box.max.y + 2.0f},
                                              size + 2.0f * s.buttonPadding);
        over.rect(bubble, s.rounding, s.popupFill, {1.0f, s.refused});
        over.text(bubble.min + s.buttonPadding, st.refused, s.textSizePt, s.refused);
    }
    return r;
}

std::string boundsText(double min, double max, int decimals) {
    const auto end = [&](double v) { return formatNumber(float(v), decimals); };
    if (std::isfinite(min) && std::isfinite(max))
        return "must be in [" + end(min) + ", " + end(max) + "]";
    if (std::isfinite(min))
        return "must be at least " + end(min);
    return "must be at most " + end(max);
}

}  // namespace

std::string withTypingHint(std::string_view tooltip) {
    return std::string(tooltip) + "; click (without dragging) to type a value";
}

std::size_t nextCodePoint(std::string_view text, std::size_t pos) {
    if (pos >= text.size()) {
        return text.size();
    }
    std::size_t next = pos;
    decodeUtf8(text, next);
    return next;
}

std::size_t prevCodePoint(std::string_view text, std::size_t pos) {
    pos = std::min(pos, text.size());
    if (pos == 0) {
        return 0;
    }
    --pos;
    while (pos > 0 && isContinuation(text[pos])) {
        --pos;
    }
    return pos;
}

Response textEdit(Ui& ui, std::string_view idLabel, std::string& text, float width,
                  bool* committed) {
    bool commit = false;
    bool edited = false;
    Response r = textEditImpl(ui, idLabel, text, width, &commit, &edited);
    if (committed != nullptr) {
        *committed = commit;
    }
    return edited ? r.markChanged() : r;
}

Response dragValueWithEntry(Ui& ui, std::string_view label, float& value, float speed, float min,
                            float max, int decimals, const NumberCheck& check) {
    return numberEntry(
        ui, label, [&] { return ui.dragValue(label, value, speed, min, max, decimals); },
        [&] { return formatNumber(value, decimals); },
        [&](double typed) -> std::string {
            if (check) {
                if (std::string reason = check(typed); !reason.empty())
                    return reason;
            } else if (typed < double(min) || typed > double(max)) {
                return boundsText(min, max, decimals);
            }
            value = float(typed);
            return {};
        });
}

Response dragValueWithEntry(Ui& ui, std::string_view label, int& value, float speed, int min,
                            int max, const NumberCheck& check) {
    return numberEntry(
        ui, label, [&] { return ui.dragValue(label, value, speed, min, max); },
        [&] { return std::to_string(value); },
        [&](double typed) -> std::string {
            if (typed != std::floor(typed))
                return "must be a whole number";
            if (check) {
                if (std::string reason = check(typed); !reason.empty())
                    return reason;
            } else if (typed < double(min) || typed > double(max)) {
                return boundsText(min, max, 0);
            }
            value = int(typed);
            return {};
        });
}

namespace {

// The track of a slider with a box: Style::sliderWidth where the row has room for it, the box
// and the label, narrower (down to MIN_TRACK_WIDTH) where it has not, so that the label is read
// whole at a side panel's default width ("density /m²" lost its unit there). The box is
// measured at the widest of the range's ends and the value, so the track keeps its width while
// the value changes.
float sliderTrackWidth(const Ui& row, std::string_view label, float value, float min, float max,
                       int decimals, int valueDecimals) {
    constexpr float MIN_TRACK_WIDTH = 48.0f;
    const Style& s = row.style();
    const FontAtlas& fonts = row.context().fonts();
    float text = fonts.textSize(formatNumber(value, valueDecimals), s.textSizePt).x;
    for (const float end : {min, max})
        text = std::max(text, fonts.textSize(formatNumber(end, decimals), s.textSizePt).x);
    const float box = std::max(s.dragValueMinWidth, text + 2.0f * s.buttonPadding.x);
    const std::string_view shown = shownLabel(label);
    const float labelWidth =
        shown.empty() ? 0.0f : s.itemSpacing.x + fonts.textSize(shown, s.textSizePt).x;
    const float room = row.availableWidth() - s.itemSpacing.x - box - labelWidth;
    return std::clamp(room, std::min(MIN_TRACK_WIDTH, s.sliderWidth), s.sliderWidth);
}

}  // namespace

Response sliderWithEntry(Ui& ui, std::string_view label, float& value, float min, float max,
                         const SliderOptions& options, const NumberCheck& check) {
    Response result;
    ui.horizontal([&](Ui& row) {
        row.pushId(label);
        const int decimals = options.decimals >= 0 ? options.decimals : rangeDecimals(min, max);
        // A logarithmic track spans orders of magnitude: the box keeps the value's significant
        // digits (the slider's own value text follows the same rule).
        const bool logarithmic = options.logarithmic && min > 0.0f && max > min;
        const int boxDecimals = logarithmic ? significantDecimals(value, decimals) : decimals;
        SliderOptions trackOnly = options;
        trackOnly.showValue = false;
        trackOnly.trackWidth = sliderTrackWidth(row, label, value, min, max, decimals, boxDecimals);
        // The track and the box are both unlabelled: separate salts keep their ids apart.
        row.pushId("track");
        result = row.slider("", value, min, max, trackOnly);
        row.popId();
        // The box drags at the track's rate: the full range over the track width.
        const float speed = (max - min) / std::max(trackOnly.trackWidth, 1.0f);
        const Response box = dragValueWithEntry(row, "", value, speed, std::min(min, max),
                                                std::max(min, max), boxDecimals, check);
        row.popId();
        if (!label.empty()) {
            row.label(label);
        }
        result.unite(box);
    });
    return result;
}

}  // namespace grass::ui
