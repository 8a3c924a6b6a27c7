// Records shapes (shape.h) into one layer of the frame's output, each tagged with the clip rect
// in force (a stack: pushClip narrows, popClip restores). Shapes entirely outside the clip rect
// are dropped here, so widgets scrolled out of view cost no tessellation. Points, y down.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "font.h"
#include "shape.h"

namespace grass::ui {

class Painter {
public:
    Painter(std::vector<ClippedShape>& out, const FontAtlas& fonts, Rect clip)
        : mOut(&out), mFonts(&fonts), mClip(clip) {}

    Rect clipRect() const { return mClip; }
    // The new clip rect is the intersection with the current one.
    void pushClip(Rect clip);
    void popClip();
    bool isVisible(Rect bounds) const;
    const FontAtlas& fonts() const { return *mFonts; }

    // Adds any shape; culled against the clip rect when its bounds are cheap to know.
    void add(Shape shape);
    // Reserves a slot painted before anything added after it, to be filled once its size is
    // known (frames behind popups and windows whose content is laid out after the slot).
    std::size_t addPlaceholder();
    void set(std::size_t slot, Shape shape);

    void rect(Rect r, float rounding, Color32 fill, Stroke stroke = {});
    void circle(Vec2 centre, float radius, Color32 fill, Stroke stroke = {});
    void line(Vec2 a, Vec2 b, Stroke stroke);
    void path(std::vector<Vec2> points, bool closed, Color32 fill, Stroke stroke);
    // Text whose bounding box has `anchor` (0,0 top-left .. 1,1 bottom-right) at `pos`; returns
    // the box (painted or culled).
    Rect text(Vec2 pos, std::string_view text, float sizePt, Color32 color,
              Vec2 anchor = Vec2(0.0f));
    void image(Rect r, TextureId texture, Rect uv = {{0.0f, 0.0f}, {1.0f, 1.0f}},
               Color32 tint = Color32::rgb(255, 255, 255));

private:
    std::vector<ClippedShape>* mOut;
    const FontAtlas* mFonts;
    Rect mClip;
    // Saved clip rects; empty (no allocation) unless pushClip is used.
    std::vector<Rect> mSaved;
};

}  // namespace grass::ui
