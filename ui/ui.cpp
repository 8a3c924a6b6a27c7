#include "ui/ui.h"

#include <utility>
#include <vector>

namespace grass::ui {

namespace {

// Child Uis extend down without limit: their parent (or a scroll area) bounds them.
constexpr float UNBOUNDED = 1.0e9f;

Rect unite(Rect a, Rect b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

}  // namespace

// Grid bookkeeping shared by the grid's Ui; column widths of the previous frame come from the
// context state so that every row of this frame uses the same column positions.
struct Ui::GridLayout {
    int columns = 1;
    int cell = 0;
    float originX = 0.0f;
    std::vector<float>* lastWidths = nullptr;
    std::vector<float> widths;

    float columnWidth(int c) const {
        const std::size_t i = std::size_t(c);
        return std::max(widths[i], i < lastWidths->size() ? (*lastWidths)[i] : 0.0f);
    }
};

Ui::Ui(Context& ctx, Rect maxRect, Layer layer)
    : mCtx(&ctx),
      mPainter(ctx.painter(layer, maxRect)),
      mLayer(layer),
      mMaxRect(maxRect),
      mCursor(maxRect.min),
      mMinRect{maxRect.min, maxRect.min} {}

Ui::Ui(Ui& parent, Rect maxRect, Direction dir)
    : mCtx(parent.mCtx),
      mPainter(parent.mPainter),
      mLayer(parent.mLayer),
      mDir(dir),
      mMaxRect(maxRect),
      mCursor(maxRect.min),
      mMinRect{maxRect.min, maxRect.min} {}

Rect Ui::availableRect() const {
    const Vec2 pos = nextItemPos();
    return {pos, glm::max(pos, mMaxRect.max)};
}

Vec2 Ui::nextItemPos() const {
    if (mGrid == nullptr) {
        return mCursor;
    }
    const int column = mGrid->cell % mGrid->columns;
    float x = mGrid->originX;
    for (int c = 0; c < column; ++c) {
        x += mGrid->columnWidth(c) + style().itemSpacing.x;
    }
    return {x, mCursor.y};
}

Rect Ui::allocate(Vec2 size) {
    const Vec2 pos = nextItemPos();
    if (mDir == Direction::Vertical && mGrid == nullptr) {
        const Rect r = Rect::fromMinSize(pos, size);
        advance(r);
        return r;
    }
    // Rows are at least one interact height tall; smaller items sit in the middle so a label's
    // text lines up with a button's.
    const float rowHeight = std::max(size.y, style().interactHeight);
    advance(Rect::fromMinSize(pos, {size.x, rowHeight}));
    return Rect::fromMinSize({pos.x, pos.y + 0.5f * (rowHeight - size.y)}, size);
}

void Ui::advance(Rect used) {
    mMinRect = unite(mMinRect, used);
    const Vec2 spacing = style().itemSpacing;
    if (mGrid != nullptr) {
        GridLayout& g = *mGrid;
        const std::size_t column = std::size_t(g.cell % g.columns);
        const Vec2 origin = nextItemPos();
        g.widths[column] = std::max(g.widths[column], used.max.x - origin.x);
        mRowHeight = std::max(mRowHeight, used.max.y - mCursor.y);
        if (++g.cell % g.columns == 0) {
            mCursor.y += mRowHeight + spacing.y;
            mRowHeight = 0.0f;
        }
    } else if (mDir == Direction::Vertical) {
        mCursor.y = std::max(mCursor.y, used.max.y + spacing.y);
    } else {
        mCursor.x = std::max(mCursor.x, used.max.x + spacing.x);
        mRowHeight = std::max(mRowHeight, used.max.y - mCursor.y);
    }
}

void Ui::addSpace(float points) {
    if (mDir == Direction::Vertical) {
        mCursor.y += points;
    } else {
        mCursor.x += points;
    }
}

Response Ui::interact(Rect rect, Id id, Sense sense) {
    return mCtx->interact(rect, mPainter.clipRect(), mLayer, id, sense);
}

void Ui::withId(std::string_view salt, const UiFn& fn) {
    pushId(salt);
    fn(*this);
    popId();
}

void Ui::withId(std::uint64_t index, const UiFn& fn) {
    pushId(index);
    fn(*this);
    popId();
}

const WidgetVisuals& Ui::visuals(const Response& r) const {
    const Style& s = style();
    if (r.dragged() || (mCtx->activeId() == r.id() && r.id().value != 0)) {
        return s.active;
    }
    return r.hovered() ? s.hovered : s.inactive;
}

void Ui::horizontal(const UiFn& fn) {
    const Vec2 origin = nextItemPos();
    Ui child(*this, {origin, glm::max(origin, mMaxRect.max)}, Direction::Horizontal);
    fn(child);
    advance({origin, glm::max(origin, child.mMinRect.max)});
}

void Ui::vertical(const UiFn& fn) {
    const Vec2 origin = nextItemPos();
    Ui child(*this, {origin, {std::max(origin.x, mMaxRect.max.x), UNBOUNDED}}, Direction::Vertical);
    fn(child);
    advance({origin, glm::max(origin, child.mMinRect.max)});
}

void Ui::indent(const UiFn& fn) {
    const Vec2 origin = nextItemPos();
    const Vec2 start{origin.x + style().indent, origin.y};
    Ui child(*this, {start, {std::max(start.x, mMaxRect.max.x), UNBOUNDED}}, Direction::Vertical);
    fn(child);
    advance({origin, glm::max(origin, child.mMinRect.max)});
}

void Ui::grid(std::string_view idSalt, int columns, const UiFn& fn) {
    const Id id = makeId(idSalt);
    GridLayout layout;
    layout.columns = std::max(columns, 1);
    layout.widths.assign(std::size_t(layout.columns), 0.0f);
    layout.lastWidths = &mCtx->state<std::vector<float>>(id);
    const Vec2 origin = nextItemPos();
    layout.originX = origin.x;

    Ui child(*this, {origin, {std::max(origin.x, mMaxRect.max.x), UNBOUNDED}}, Direction::Vertical);
    child.mGrid = &layout;
    mCtx->pushId(id);
    fn(child);
    mCtx->popId();
    // Still valid: fn may have added state entries, but unordered_map never moves its elements.
    *layout.lastWidths = std::move(layout.widths);
    advance({origin, glm::max(origin, child.mMinRect.max)});
}

}  // namespace grass::ui
