// Containers with state across frames: scroll areas, collapsing headers and popups.
#include "ui/ui.h"

namespace grass::ui {

namespace {

constexpr float UNBOUNDED = 1.0e9f;

struct ScrollState {
    float offset = 0.0f;
    // Last frame's content height; < 0 before the first frame.
    float contentHeight = -1.0f;
};

struct PopupState {
    Rect frame;  // last frame's, empty before it was first shown
};

}  // namespace

void Ui::scrollArea(std::string_view idSalt, float maxHeight, const UiFn& fn) {
    const Id id = makeId(idSalt);
    ScrollState& st = mCtx->state<ScrollState>(id);
    const Style& s = style();
    const Vec2 origin = nextItemPos();
    const float width = std::max(0.0f, mMaxRect.max.x - origin.x);
    // Shrinks to content that fits, known from the last frame.
    const float viewHeight =
        st.contentHeight >= 0.0f ? std::min(maxHeight, st.contentHeight) : maxHeight;
    const Rect view = Rect::fromMinSize(origin, {width, viewHeight});
    const bool needBar = st.contentHeight > viewHeight;
    const float contentWidth =
        std::max(0.0f, width - (needBar ? s.scrollBarWidth + 0.5f * s.itemSpacing.x : 0.0f));
    const float maxOffset = std::max(0.0f, st.contentHeight - viewHeight);
    st.offset = std::clamp(st.offset, 0.0f, maxOffset);

    const float top = origin.y - st.offset;
    Ui child(*this, {{origin.x, top}, {origin.x + contentWidth, UNBOUNDED}}, Direction::Vertical);
    child.mPainter.pushClip(view);
    mCtx->pushId(id);
    fn(child);
    mCtx->popId();
    const float contentHeight = child.mMinRect.max.y - top;

    // The wheel scrolls the innermost area under the pointer: inner areas ran (and consumed
    // it) first. The new offset shows from the next frame.
    const Rect visibleView = view.intersect(mPainter.clipRect());
    const Vec2 pointer = mCtx->pointerPos();
    if (mCtx->input().hasPointer && visibleView.contains(pointer) &&
        mCtx->input().scrollDelta.y != 0.0f) {
        st.offset -= mCtx->consumeScroll().y;
    }
    if (needBar) {
        const Rect track{{view.max.x - s.scrollBarWidth, view.min.y}, view.max};
        const float handleHeight =
            std::clamp(viewHeight * viewHeight / st.contentHeight,
                       std::min(s.scrollBarMinHandle, viewHeight), viewHeight);
        const float travel = viewHeight - handleHeight;
        const float handleTop =
            track.min.y + (maxOffset > 0.0f ? st.offset / maxOffset : 0.0f) * travel;
        const Rect handle{{track.min.x, handleTop}, {track.max.x, handleTop + handleHeight}};
        const Response bar = interact(handle, id.with("bar"), Sense::dragOnly());
        if (bar.dragged() && travel > 0.0f) {
            st.offset += bar.dragDelta().y * maxOffset / travel;
        }
        mPainter.rect(track, 0.5f * s.scrollBarWidth, s.scrollBarTrack);
        mPainter.rect(handle, 0.5f * s.scrollBarWidth, visuals(bar).bgFill);
    }
    st.contentHeight = contentHeight;
    st.offset = std::clamp(st.offset, 0.0f, std::max(0.0f, contentHeight - viewHeight));
    advance(view);
}

Response Ui::collapsingHeader(std::string_view label, const UiFn& fn, bool defaultOpen) {
    // "Text##key" shows Text and is keyed by "##key" alone: a header that counts its items
    // ("Cameras (2)##cameras") stays open when the count changes.
    const std::size_t keyAt = label.find("##");
    const Id id = makeId(keyAt == std::string_view::npos ? label : label.substr(keyAt));
    const std::string_view shown = label.substr(0, keyAt);
    bool& open = mCtx->state<bool>(id, defaultOpen);
    const Style& s = style();
    const Rect rect = allocate({std::max(availableWidth(), s.iconSize), s.interactHeight});
    Response r = interact(rect, id, Sense::clickOnly());
    if (r.clicked()) {
        open = !open;
        r.markChanged();
    }
    const WidgetVisuals& v = visuals(r);
    if (r.hovered()) {
        mPainter.rect(rect, s.rounding, v.bgFill);
    }
    // A triangle pointing right (closed) or down (open).
    const Vec2 c{rect.min.x + 0.5f * s.iconSize, rect.centre().y};
    const float h = 0.3f * s.iconSize;
    std::vector<Vec2> tri =
        open ? std::vector<Vec2>{{c.x - h, c.y - 0.6f * h},
                                 {c.x + h, c.y - 0.6f * h},
                                 {c.x, c.y + 0.7f * h}}
             : std::vector<Vec2>{
                   {c.x - 0.6f * h, c.y - h}, {c.x + 0.7f * h, c.y}, {c.x - 0.6f * h, c.y + h}};
    mPainter.path(std::move(tri), true, v.text, {});
    mPainter.text({rect.min.x + s.iconSize + s.iconSpacing, rect.centre().y}, shown, s.textSizePt,
                  v.text, {0.0f, 0.5f});
    if (open) {
        mCtx->pushId(id);
        indent(fn);
        mCtx->popId();
    }
    return r;
}

bool Ui::popupBelow(Id popupId, Rect anchor, const UiFn& fn, bool closeOnClick) {
    if (!mCtx->isPopupOpen(popupId)) {
        return false;
    }
    const Style& s = style();
    PopupState& st = mCtx->state<PopupState>(popupId.with("popup"));
    const Rect screen = mCtx->screenRect();
    // Blocks the widgets below from the pointer. The frame's size is known only after the
    // content, so this uses last frame's: it is registered first, under the items.
    if (!st.frame.empty()) {
        mCtx->interact(st.frame, screen, Layer::Popups, popupId.with("frame"), Sense::hover());
        mCtx->registerArea(st.frame);
    }
    Painter painter = mCtx->painter(Layer::Popups, screen);
    const std::size_t background = painter.addPlaceholder();
    const float pad = s.popupPadding;
    Vec2 origin{anchor.min.x + pad, anchor.max.y + pad + 2.0f};
    // Opens upwards when last frame's list would run off the bottom of the screen.
    if (!st.frame.empty() && origin.y - pad + st.frame.height() > screen.max.y) {
        origin.y = std::max(screen.min.y, anchor.min.y - 2.0f - st.frame.height()) + pad;
    }
    const float width = std::max(anchor.width(), st.frame.width()) - 2.0f * pad;
    Ui child(*mCtx, {origin, {origin.x + std::max(width, 0.0f), UNBOUNDED}}, Layer::Popups);
    child.mPainter = painter;
    mCtx->pushId(popupId);
    fn(child);
    mCtx->popId();
    const Rect content = child.mMinRect;
    const Rect frame{origin - Vec2(pad), glm::max(content.max, origin + Vec2(width, 0.0f)) + pad};
    painter.set(background, RectShape{frame, s.rounding, s.popupFill, s.popupStroke});
    const bool hadFrame = !st.frame.empty();
    st.frame = frame;

    const Vec2 p = mCtx->pointerPos();
    const bool inside = mCtx->input().hasPointer && frame.contains(p);
    const bool onAnchor = mCtx->input().hasPointer && anchor.contains(p);
    if (mCtx->consumeKey(Key::Escape) || (mCtx->buttonPressed() && !inside && !onAnchor) ||
        (closeOnClick && hadFrame && inside && mCtx->buttonReleased())) {
        mCtx->closePopup();
        st.frame = Rect{};
    }
    return true;
}

}  // namespace grass::ui
