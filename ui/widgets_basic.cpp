// Basic widgets: text, buttons, toggles, separators, progress bars, images and tooltips.
#include <algorithm>
#include <string>
#include <vector>

#include "ui/text_wrap.h"
#include "ui/ui.h"

namespace grass::ui {

Response& Response::onHoverText(std::string_view text) {
    // Hidden while anything is dragged, and while the widget is typed into: the tooltip would
    // cover what is being edited (and a refused entry's reason under it); and beside an open
    // popup, whose list it would cover.
    if (mCtx == nullptr || !mHovered || mHasFocus || mCtx->activeId().value != 0 ||
        mCtx->pointerBesideOpenPopup()) {
        return *this;
    }
    const Style& s = mCtx->style();
    const Rect screen = mCtx->screenRect();
    Painter painter = mCtx->painter(Layer::Tooltips, screen);
    const float widest =
        std::max(std::min(s.tooltipMaxWidth, screen.width() - 2.0f * s.buttonPadding.x), 1.0f);
    // Its own line breaks kept, each paragraph wrapped.
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::vector<std::string> wrapped =
            wrapText(mCtx->fonts(), s.textSizePt, text.substr(start, end - start), widest);
        lines.insert(lines.end(), wrapped.begin(), wrapped.end());
        start = end + 1;
    }
    const float lineHeight = mCtx->fonts().lineHeight(s.textSizePt);
    Vec2 textSize(0.0f, lineHeight * static_cast<float>(lines.size()));
    for (const std::string& line : lines)
        textSize.x = std::max(textSize.x, mCtx->fonts().textSize(line, s.textSizePt).x);
    const Vec2 size = textSize + 2.0f * s.buttonPadding;
    Vec2 pos = mCtx->pointerPos() + s.tooltipOffset;
    // Kept on screen: flipped left/up of the pointer near the right/bottom edge.
    if (pos.x + size.x > screen.max.x) {
        pos.x = std::max(screen.min.x, mCtx->pointerPos().x - size.x);
    }
    if (pos.y + size.y > screen.max.y) {
        pos.y = std::max(screen.min.y, mCtx->pointerPos().y - size.y);
    }
    const Rect frame = Rect::fromMinSize(pos, size);
    painter.rect(frame, s.rounding, s.popupFill, s.popupStroke);
    for (std::size_t i = 0; i < lines.size(); ++i)
        painter.text(frame.min + s.buttonPadding + Vec2(0.0f, lineHeight * static_cast<float>(i)),
                     lines[i], s.textSizePt, s.text);
    return *this;
}

Response& Response::unite(const Response& o) {
    mRect = {glm::min(mRect.min, o.mRect.min), glm::max(mRect.max, o.mRect.max)};
    mDragDelta = mDragged ? mDragDelta : o.mDragDelta;
    mHovered = mHovered || o.mHovered;
    mClicked = mClicked || o.mClicked;
    mDoubleClicked = mDoubleClicked || o.mDoubleClicked;
    mSecondaryClicked = mSecondaryClicked || o.mSecondaryClicked;
    mDragged = mDragged || o.mDragged;
    mDragStarted = mDragStarted || o.mDragStarted;
    mDragStopped = mDragStopped || o.mDragStopped;
    mChanged = mChanged || o.mChanged;
    mHasFocus = mHasFocus || o.mHasFocus;
    mGainedFocus = mGainedFocus || o.mGainedFocus;
    mLostFocus = mLostFocus || o.mLostFocus;
    return *this;
}

Response Ui::label(std::string_view text) {
    return coloredLabel(text, style().text);
}

Response Ui::wrappedLabel(std::string_view text) {
    return wrappedColoredLabel(text, style().text);
}

Response Ui::wrappedColoredLabel(std::string_view text, Color32 color) {
    const std::vector<std::string> lines =
        wrapText(mCtx->fonts(), style().textSizePt, text, std::max(availableWidth(), 1.0f));
    if (lines.empty())
        return coloredLabel("", color);
    Response whole = coloredLabel(lines.front(), color);
    for (std::size_t i = 1; i < lines.size(); ++i)
        whole.unite(coloredLabel(lines[i], color));
    return whole;
}

Response Ui::coloredLabel(std::string_view text, Color32 color) {
    const Style& s = style();
    const Rect rect = allocate(mCtx->fonts().textSize(text, s.textSizePt));
    mPainter.text(rect.min, text, s.textSizePt, color);
    return interact(rect, autoId(), Sense::hover());
}

Response Ui::button(std::string_view label) {
    const Style& s = style();
    const std::string_view text = shownLabel(label);
    const Vec2 textSize = mCtx->fonts().textSize(text, s.textSizePt);
    Vec2 size = textSize + 2.0f * s.buttonPadding;
    size.y = std::max(size.y, s.interactHeight);
    const Rect rect = allocate(size);
    const Response r = interact(rect, makeId(label), Sense::clickOnly());
    const WidgetVisuals& v = visuals(r);
    mPainter.rect(rect, s.rounding, v.bgFill, v.bgStroke);
    mPainter.text(rect.centre(), text, s.textSizePt, v.text, {0.5f, 0.5f});
    return r;
}

Response Ui::checkbox(bool& checked, std::string_view label) {
    // "shown##key": the id comes from the whole label, the box shows the part before "##".
    const std::string_view text = shownLabel(label);
    const Style& s = style();
    const Vec2 textSize = mCtx->fonts().textSize(text, s.textSizePt);
    const Rect rect = allocate({s.iconSize + (text.empty() ? 0.0f : s.iconSpacing + textSize.x),
                                std::max(s.iconSize, textSize.y)});
    Response r = interact(rect, makeId(label), Sense::clickOnly());
    if (r.clicked()) {
        checked = !checked;
        r.markChanged();
    }
    const WidgetVisuals& v = visuals(r);
    const Rect box =
        Rect::fromMinSize({rect.min.x, rect.centre().y - 0.5f * s.iconSize}, Vec2(s.iconSize));
    mPainter.rect(box, s.rounding, v.bgFill, v.bgStroke);
    if (checked) {
        const Vec2 o = box.min;
        const float k = s.iconSize;
        mPainter.path({o + Vec2(0.2f * k, 0.5f * k), o + Vec2(0.42f * k, 0.72f * k),
                       o + Vec2(0.8f * k, 0.28f * k)},
                      false, Color32::transparent(), {2.0f, v.text});
    }
    mPainter.text({box.max.x + s.iconSpacing, rect.centre().y}, text, s.textSizePt, v.text,
                  {0.0f, 0.5f});
    return r;
}

Response Ui::radio(bool selected, std::string_view label) {
    const Style& s = style();
    const std::string_view text = shownLabel(label);
    const Vec2 textSize = mCtx->fonts().textSize(text, s.textSizePt);
    const Rect rect = allocate({s.iconSize + (text.empty() ? 0.0f : s.iconSpacing + textSize.x),
                                std::max(s.iconSize, textSize.y)});
    const Response r = interact(rect, makeId(label), Sense::clickOnly());
    const WidgetVisuals& v = visuals(r);
    const Vec2 centre{rect.min.x + 0.5f * s.iconSize, rect.centre().y};
    mPainter.circle(centre, 0.5f * s.iconSize, v.bgFill, v.bgStroke);
    if (selected) {
        mPainter.circle(centre, 0.22f * s.iconSize, v.text);
    }
    mPainter.text({rect.min.x + s.iconSize + s.iconSpacing, rect.centre().y}, text, s.textSizePt,
                  v.text, {0.0f, 0.5f});
    return r;
}

Response Ui::selectable(bool selected, std::string_view label) {
    const Style& s = style();
    const std::string_view text = shownLabel(label);
    const Vec2 textSize = mCtx->fonts().textSize(text, s.textSizePt);
    const Vec2 size{std::max(availableWidth(), textSize.x + 2.0f * s.buttonPadding.x),
                    std::max(textSize.y + 2.0f * s.buttonPadding.y, s.interactHeight)};
    const Rect rect = allocate(size);
    const Response r = interact(rect, makeId(label), Sense::clickOnly());
    const WidgetVisuals& v = visuals(r);
    if (selected) {
        mPainter.rect(rect, s.rounding, s.selectionFill);
    } else if (r.hovered()) {
        mPainter.rect(rect, s.rounding, v.bgFill);
    }
    mPainter.text({rect.min.x + s.buttonPadding.x, rect.centre().y}, text, s.textSizePt,
                  selected ? s.textStrong : v.text, {0.0f, 0.5f});
    return r;
}

void Ui::separator() {
    const Style& s = style();
    const Stroke stroke{1.0f, s.separator};
    if (mDir == Direction::Horizontal) {
        const Rect r = allocate({s.separatorSpace, s.interactHeight});
        mPainter.line({r.centre().x, r.min.y}, {r.centre().x, r.max.y}, stroke);
    } else {
        const Rect r = allocate({availableWidth(), s.separatorSpace});
        mPainter.line({r.min.x, r.centre().y}, {r.max.x, r.centre().y}, stroke);
    }
}

Response Ui::progressBar(float fraction, std::string_view text) {
    const Style& s = style();
    const float f = std::clamp(fraction, 0.0f, 1.0f);
    const Rect rect = allocate({availableWidth(), s.interactHeight});
    const Response r = interact(rect, autoId(), Sense::hover());
    mPainter.rect(rect, s.rounding, s.extremeBg);
    if (f > 0.0f) {
        const Rect filled{rect.min, {rect.min.x + f * rect.width(), rect.max.y}};
        mPainter.rect(filled, s.rounding, s.selectionFill);
    }
    if (!text.empty()) {
        mPainter.text(rect.centre(), text, s.textSizePt, s.text, {0.5f, 0.5f});
    }
    return r;
}

Response Ui::image(TextureId texture, Vec2 size, Rect uv) {
    const Rect rect = allocate(size);
    mPainter.image(rect, texture, uv);
    return interact(rect, autoId(), Sense::hover());
}

}  // namespace grass::ui
