// ui::Ui: a cheap builder for one region of the screen (a panel, a popup, a row). It holds a
// layout cursor that places each item after the previous one (vertical, horizontal or grid),
// a painter clipped to the region, and a reference to the Context. Containers (horizontal,
// grid, scroll area, collapsing header) hand a child Ui to a closure; widgets return a
// Response. Points, y down.
//
// Widgets are members for discoverability, but nothing here is privileged: a widget is
// `allocate` (where), `interact` (what the pointer does), `painter()` (how it looks) and
// `context().state<T>(id)` (what it remembers), so new widgets can be free functions
// `Response myWidget(Ui&, ...)` in their own files.
#pragma once

#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <string_view>

#include "context.h"
#include "painter.h"
#include "response.h"
#include "style.h"
#include "types.h"

namespace grass::ui {

class Ui;
using UiFn = std::function<void(Ui&)>;

enum class Direction { Vertical, Horizontal };

struct SliderOptions {
    // Maps the track to log(value); needs 0 < min < max (otherwise linear).
    bool logarithmic = false;
    // Keeps dragged values within [min, max] (the track ends).
    bool clamp = true;
    // Digits after the decimal point in the value text; < 0 picks from the range.
    int decimals = -1;
    // Draws the value text after the track; sliderWithEntry (text_edit.h) shows its own box.
    bool showValue = true;
    // > 0: the track's width instead of Style::sliderWidth (sliderWithEntry narrows it to fit).
    float trackWidth = 0.0f;
};

class Ui {
public:
    // A root Ui filling `maxRect` (clip rect and layout bounds) on `layer`. Ids of its widgets
    // hash the context's current id: wrap separate panels in Context::pushId or withId.
    Ui(Context& ctx, Rect maxRect, Layer layer = Layer::Panels);

    Context& context() const { return *mCtx; }
    Painter& painter() { return mPainter; }
    const Style& style() const { return mCtx->style(); }
    Layer layer() const { return mLayer; }
    Direction direction() const { return mDir; }

    // Layout. maxRect: the region items may use; availableRect: what is left of it from the
    // cursor on; minRect: the bounding box of what was allocated so far.
    Rect maxRect() const { return mMaxRect; }
    Rect availableRect() const;
    float availableWidth() const { return availableRect().width(); }
    Rect minRect() const { return mMinRect; }
    // Where the next item's top-left goes (a grid cell's origin inside grids).
    Vec2 nextItemPos() const;
    // Places an item of `size` at the cursor and moves the cursor past it plus item spacing.
    // Items smaller than the interact height are centred in it in horizontal rows and grids.
    Rect allocate(Vec2 size);
    // Records an area already placed at nextItemPos() (a child's content), like allocate.
    void advance(Rect used);
    void addSpace(float points);

    // Interaction in this Ui's layer and clip rect (Context::interact).
    Response interact(Rect rect, Id id, Sense sense);

    // Ids: hashes of the context's id stack top and a salt; push an index in loops.
    Id makeId(std::string_view salt) const { return mCtx->currentId().with(salt); }
    Id makeId(std::uint64_t salt) const { return mCtx->currentId().with(salt); }
    // For widgets without a natural salt (labels): unique by call order within the frame.
    Id autoId() { return mCtx->autoId(); }
    void pushId(std::string_view salt) { mCtx->pushId(makeId(salt)); }
    void pushId(std::uint64_t index) { mCtx->pushId(makeId(index)); }
    void popId() { mCtx->popId(); }
    void withId(std::string_view salt, const UiFn& fn);
    void withId(std::uint64_t index, const UiFn& fn);

    // Containers (ui.cpp, containers.cpp).
    void horizontal(const UiFn& fn);
    void vertical(const UiFn& fn);
    void indent(const UiFn& fn);
    // Cells fill `columns` columns row by row; a column is as wide as its widest cell of the
    // previous frame (remembered under the grid's id), so rows line up from the second frame.
    void grid(std::string_view idSalt, int columns, const UiFn& fn);
    // Content taller than maxHeight scrolls (wheel, draggable bar); the offset is remembered.
    void scrollArea(std::string_view idSalt, float maxHeight, const UiFn& fn);
    // A clickable header that shows `fn`'s content, indented, while open (remembered).
    // "Text##key": shows Text, keyed by the "##key" part (stays open while Text changes).
    Response collapsingHeader(std::string_view label, const UiFn& fn, bool defaultOpen = false);
    // If popup `popupId` is open (Context::openPopup), shows `fn` in a frame below `anchor` in
    // the foreground layer, and closes it on Escape, a press outside both, or (closeOnClick) a
    // click inside. Returns whether it was shown.
    bool popupBelow(Id popupId, Rect anchor, const UiFn& fn, bool closeOnClick = true);

    // Basic widgets (widgets_basic.cpp).
    Response label(std::string_view text);
    // The text in as many lines as the available width needs (ui/text_wrap.h): for messages
    // that must be read whole (a path, an error).
    Response wrappedLabel(std::string_view text);
    Response wrappedColoredLabel(std::string_view text, Color32 color);
    Response coloredLabel(std::string_view text, Color32 color);
    // A widget's label "text##key" shows text; the whole label is the id (so "##a" and "##b" are
    // two boxes). So do every widget's labels (ui/types.h, shownLabel).
    Response button(std::string_view label);
    Response checkbox(bool& checked, std::string_view label);
    Response radio(bool selected, std::string_view label);
    template <class T>
    Response radioValue(T& current, T value, std::string_view text) {
        Response r = radio(current == value, text);
        if (r.clicked() && !(current == value)) {
            current = value;
            r.markChanged();
        }
        return r;
    }
    // A full-width row that highlights when selected (list and combo box items).
    Response selectable(bool selected, std::string_view label);
    void separator();
    Response progressBar(float fraction, std::string_view text = {});
    Response image(TextureId texture, Vec2 size, Rect uv = {{0.0f, 0.0f}, {1.0f, 1.0f}});

    // Value widgets (widgets_values.cpp). A slider is [track][value] label; its Response's rect
    // is the track (sliderWidth, or SliderOptions::trackWidth, × interactHeight).
    Response slider(std::string_view label, float& value, float min, float max,
                    const SliderOptions& options = {});
    Response slider(std::string_view label, int& value, int min, int max,
                    const SliderOptions& options = {});
    // Dragging horizontally changes the value by `speed` per point moved.
    Response dragValue(std::string_view label, float& value, float speed,
                       float min = -std::numeric_limits<float>::infinity(),
                       float max = std::numeric_limits<float>::infinity(), int decimals = 3);
    Response dragValue(std::string_view label, int& value, float speed,
                       int min = std::numeric_limits<int>::min(),
                       int max = std::numeric_limits<int>::max());
    // [selected text ▾] label; a click opens a popup list filled by `fn` (selectables), which
    // closes on a pick, Escape or a press outside.
    Response comboBox(std::string_view label, std::string_view selectedText, const UiFn& fn);
    // Items: anything indexable whose elements convert to std::string_view.
    template <class Items>
    Response comboBox(std::string_view label, int& selected, const Items& items) {
        const int count = int(std::size(items));
        const std::string_view current = selected >= 0 && selected < count
                                             ? std::string_view(items[std::size_t(selected)])
                                             : std::string_view();
        bool picked = false;
        Response r = comboBox(label, current, [&](Ui& ui) {
            for (int i = 0; i < count; ++i) {
                ui.pushId(std::uint64_t(i));
                if (ui.selectable(i == selected, items[std::size_t(i)]).clicked() &&
                    i != selected) {
                    selected = i;
                    picked = true;
                }
                ui.popId();
            }
        });
        return picked ? r.markChanged() : r;
    }

    // How an interactive widget with response `r` is drawn (inactive, hovered, active).
    const WidgetVisuals& visuals(const Response& r) const;

private:
    struct GridLayout;
    Ui(Ui& parent, Rect maxRect, Direction dir);

    Context* mCtx;
    Painter mPainter;
    Layer mLayer;
    Direction mDir = Direction::Vertical;
    Rect mMaxRect;
    Vec2 mCursor{0.0f};
    Rect mMinRect;
    float mRowHeight = 0.0f;
    GridLayout* mGrid = nullptr;
};

}  // namespace grass::ui
