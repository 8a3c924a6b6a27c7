#include "ui/painter.h"

#include <utility>

namespace grass::ui {

namespace {

// Bounds of shapes whose extent is cheap to know; text is culled in Painter::text, where it is
// measured anyway.
bool boundsOf(const Shape& shape, Rect* bounds) {
    if (const auto* r = std::get_if<RectShape>(&shape)) {
        *bounds = r->rect.expand(r->stroke.width);
    } else if (const auto* c = std::get_if<CircleShape>(&shape)) {
        *bounds = Rect{c->centre, c->centre}.expand(c->radius + c->stroke.width);
    } else if (const auto* p = std::get_if<PathShape>(&shape)) {
        if (p->points.empty()) {
            return false;
        }
        Rect b{p->points.front(), p->points.front()};
        for (Vec2 q : p->points) {
            b.min = glm::min(b.min, q);
            b.max = glm::max(b.max, q);
        }
        *bounds = b.expand(p->stroke.width);
    } else if (const auto* i = std::get_if<ImageShape>(&shape)) {
        *bounds = i->rect;
    } else {
        return false;
    }
    return true;
}

}  // namespace

void Painter::pushClip(Rect clip) {
    mSaved.push_back(mClip);
    mClip = mClip.intersect(clip);
}

void Painter::popClip() {
    if (!mSaved.empty()) {
        mClip = mSaved.back();
        mSaved.pop_back();
    }
}

bool Painter::isVisible(Rect bounds) const {
    // Touching edges count as outside: nothing of the shape would be drawn.
    return !mClip.intersect(bounds).empty();
}

void Painter::add(Shape shape) {
    Rect bounds;
    if (boundsOf(shape, &bounds) && !isVisible(bounds)) {
        return;
    }
    mOut->push_back({mClip, std::move(shape)});
}

std::size_t Painter::addPlaceholder() {
    mOut->push_back({mClip, RectShape{}});
    return mOut->size() - 1;
}

void Painter::set(std::size_t slot, Shape shape) {
    (*mOut)[slot].shape = std::move(shape);
}

void Painter::rect(Rect r, float rounding, Color32 fill, Stroke stroke) {
    add(RectShape{r, rounding, fill, stroke});
}

void Painter::circle(Vec2 centre, float radius, Color32 fill, Stroke stroke) {
    add(CircleShape{centre, radius, fill, stroke});
}

void Painter::line(Vec2 a, Vec2 b, Stroke stroke) {
    add(PathShape{{a, b}, false, Color32::transparent(), stroke});
}

void Painter::path(std::vector<Vec2> points, bool closed, Color32 fill, Stroke stroke) {
    add(PathShape{std::move(points), closed, fill, stroke});
}

Rect Painter::text(Vec2 pos, std::string_view text, float sizePt, Color32 color, Vec2 anchor) {
    const Vec2 size = mFonts->textSize(text, sizePt);
    const Rect box = Rect::fromMinSize(pos - anchor * size, size);
    if (!text.empty() && isVisible(box)) {
        mOut->push_back({mClip, TextShape{box.min, std::string(text), sizePt, color}});
    }
    return box;
}

void Painter::image(Rect r, TextureId texture, Rect uv, Color32 tint) {
    add(ImageShape{r, texture, uv, tint});
}

}  // namespace grass::ui
