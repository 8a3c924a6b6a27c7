// What a widget reports about the current frame's interaction with it: hover, clicks, drags
// (dragDelta in points), focus, and whether the widget changed the value it edits. Produced by
// Context::interact; widgets add markChanged(). Cheap to copy.
#pragma once

#include <string_view>

#include "types.h"

namespace grass::ui {

class Context;

class Response {
public:
    Response() = default;

    Rect rect() const { return mRect; }
    Id id() const { return mId; }
    // The pointer is over the widget, inside its clip rect, and no widget above it (or being
    // dragged) claims the pointer.
    bool hovered() const { return mHovered; }
    // Primary button pressed and released on the widget (both inside it).
    bool clicked() const { return mClicked; }
    bool doubleClicked() const { return mDoubleClicked; }
    bool secondaryClicked() const { return mSecondaryClicked; }
    // Pressed on this widget and still held (widgets that sense drags), or released this pass
    // after moving farther than a click (the drag's last stretch, with dragStopped()).
    bool dragged() const { return mDragged; }
    bool dragStarted() const { return mDragStarted; }
    bool dragStopped() const { return mDragStopped; }
    // Pointer movement this frame while dragged, points.
    Vec2 dragDelta() const { return mDragDelta; }
    // The pointer position while hovered or dragged (points); where a slider maps its value.
    Vec2 pointerPos() const { return mPointerPos; }
    bool changed() const { return mChanged; }
    bool hasFocus() const { return mHasFocus; }
    bool gainedFocus() const { return mGainedFocus; }
    bool lostFocus() const { return mLostFocus; }

    Response& markChanged() {
        mChanged = true;
        return *this;
    }
    // Shows `text` in a tooltip next to the pointer while the widget is hovered (and nothing is
    // being dragged). Defined in widgets_basic.cpp.
    Response& onHoverText(std::string_view text);
    // Merges another response of the same widget (e.g. its label and its body): or-ed flags,
    // union of rects.
    Response& unite(const Response& other);

private:
    friend class Context;

    Context* mCtx = nullptr;
    Rect mRect;
    Id mId;
    Vec2 mDragDelta{0.0f};
    Vec2 mPointerPos{0.0f};
    bool mHovered = false;
    bool mClicked = false;
    bool mDoubleClicked = false;
    bool mSecondaryClicked = false;
    bool mDragged = false;
    bool mDragStarted = false;
    bool mDragStopped = false;
    bool mChanged = false;
    bool mHasFocus = false;
    bool mGainedFocus = false;
    bool mLostFocus = false;
};

}  // namespace grass::ui
