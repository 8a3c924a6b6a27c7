// Top bar, side panels and floating windows (window.h).
#include "ui/window.h"

#include <algorithm>
#include <vector>

namespace grass::ui {

namespace {

// Space inside panels and windows around their content.
constexpr float PANEL_PADDING = 6.0f;
// Half the width of a side panel's grab strip on its inner edge.
constexpr float RESIZE_GRAB = 3.0f;
constexpr float PANEL_MIN_WIDTH = 80.0f;
constexpr float GRIP_SIZE = 14.0f;

// What panels have left of the screen; reset on the first panel call of each frame.
struct AreaLayout {
    std::uint64_t frame = 0;
    Rect remaining;
};

struct TopBarState {
    float height = -1.0f;  // last frame's content height; < 0 before
};

struct PanelState {
    float width = -1.0f;  // < 0: not yet shown (defaultWidth)
    float grabOffset = 0.0f;
};

struct WindowState {
    Rect rect;
};

struct WindowEntry {
    Id id;
    Rect rect;
    std::uint64_t lastFrame = 0;
};

// Windows back to front: the last entry shown recently is the front window.
struct WindowStack {
    std::vector<WindowEntry> order;
};

AreaLayout& areaLayout(Context& ctx) {
    AreaLayout& l = ctx.state<AreaLayout>(Id::fromString("grass::ui::areas"));
    if (l.frame != ctx.frameNumber()) {
        l.frame = ctx.frameNumber();
        l.remaining = ctx.screenRect();
    }
    return l;
}

// Shown this frame or the last: entries of closed windows stay but must not block or be front.
bool recent(const WindowEntry& e, std::uint64_t frame) {
    return e.lastFrame + 1 >= frame;
}

Rect keepOnScreen(Rect r, Rect screen) {
    const Vec2 size = glm::min(glm::max(r.size(), WINDOW_MIN_SIZE), screen.size());
    const Vec2 min = glm::clamp(r.min, screen.min, glm::max(screen.min, screen.max - size));
    return Rect::fromMinSize(min, size);
}

}  // namespace

Rect centralRect(Context& ctx) {
    return areaLayout(ctx).remaining;
}

Rect topBar(Context& ctx, std::string_view idSalt, const UiFn& fn) {
    const Style& s = ctx.style();
    AreaLayout& layout = areaLayout(ctx);
    const Id id = ctx.currentId().with(idSalt);
    TopBarState& st = ctx.state<TopBarState>(id);
    const float height =
        st.height >= 0.0f ? st.height : s.interactHeight + 2.0f * s.buttonPadding.y;
    const Rect rect{layout.remaining.min,
                    {layout.remaining.max.x, layout.remaining.min.y + height}};
    Painter bg = ctx.painter(Layer::Panels, rect);
    bg.rect(rect, 0.0f, s.panelFill);
    bg.line({rect.min.x, rect.max.y - 0.5f}, {rect.max.x, rect.max.y - 0.5f}, {1.0f, s.separator});
    ctx.interact(rect, ctx.screenRect(), Layer::Panels, id, Sense::hover());
    ctx.registerArea(rect);

    const Vec2 pad = s.buttonPadding;
    Ui ui(ctx, {rect.min + pad, {rect.max.x - pad.x, rect.max.y}}, Layer::Panels);
    ctx.pushId(id);
    fn(ui);
    ctx.popId();
    // Sized to the content from the next frame on.
    st.height = std::max(ui.minRect().max.y - rect.min.y + pad.y, s.interactHeight);
    layout.remaining.min.y = rect.max.y;
    return rect;
}

Rect sidePanel(Context& ctx, std::string_view idSalt, Side side, float defaultWidth,
               const UiFn& fn) {
    const Style& s = ctx.style();
    AreaLayout& layout = areaLayout(ctx);
    const Rect area = layout.remaining;
    const Id id = ctx.currentId().with(idSalt);
    PanelState& st = ctx.state<PanelState>(id);
    // Never wider than what is left, so a small window still shows some viewport.
    const float maxWidth = std::max(PANEL_MIN_WIDTH, area.width() - PANEL_MIN_WIDTH);
    const float width =
        std::clamp(st.width >= 0.0f ? st.width : defaultWidth, PANEL_MIN_WIDTH, maxWidth);
    const bool left = side == Side::Left;
    const Rect rect = left ? Rect{area.min, {area.min.x + width, area.max.y}}
                           : Rect{{area.max.x - width, area.min.y}, area.max};
    Painter bg = ctx.painter(Layer::Panels, rect);
    bg.rect(rect, 0.0f, s.panelFill);
    ctx.interact(rect, ctx.screenRect(), Layer::Panels, id, Sense::hover());
    ctx.registerArea(rect);

    Ui ui(ctx, rect.expand(-PANEL_PADDING), Layer::Panels);
    ctx.pushId(id);
    fn(ui);
    ctx.popId();

    // The grab strip straddles the inner edge; registered after the content so it is on top.
    const float edge = left ? rect.max.x : rect.min.x;
    const Rect grab{{edge - RESIZE_GRAB, rect.min.y}, {edge + RESIZE_GRAB, rect.max.y}};
    const Response r =
        ctx.interact(grab, ctx.screenRect(), Layer::Panels, id.with("resize"), Sense::dragOnly());
    const float pointerWidth = left ? r.pointerPos().x - rect.min.x : rect.max.x - r.pointerPos().x;
    if (r.dragStarted()) {
        // Keeps the edge where it was grabbed rather than snapping it to the pointer.
        st.grabOffset = width - pointerWidth;
    }
    st.width = width;
    if (r.dragged()) {
        st.width = std::clamp(pointerWidth + st.grabOffset, PANEL_MIN_WIDTH, maxWidth);
    }
    const bool hot = r.hovered() || r.dragged();
    if (hot) {
        ctx.output().cursor = CursorIcon::ResizeHorizontal;
    }
    bg.line({edge, rect.min.y}, {edge, rect.max.y},
            {hot ? 2.0f : 1.0f, hot ? s.accent : s.separator});
    if (left) {
        layout.remaining.min.x = rect.max.x;
    } else {
        layout.remaining.max.x = rect.min.x;
    }
    return rect;
}

Rect windowRect(Context& ctx, std::string_view title) {
    const WindowState* st = ctx.findState<WindowState>(ctx.currentId().with(title));
    return st != nullptr ? st->rect : Rect{};
}

bool window(Context& ctx, std::string_view title, bool* open, const UiFn& fn, Rect defaultRect) {
    if (open != nullptr && !*open) {
        return false;
    }
    const Style& s = ctx.style();
    const Rect screen = ctx.screenRect();
    const std::uint64_t frame = ctx.frameNumber();
    const Id id = ctx.currentId().with(title);
    WindowState& st = ctx.state<WindowState>(id, WindowState{defaultRect});
    Rect r = keepOnScreen(st.rect, screen);

    // Z order: a press inside the window, where no window above it (shown recently) covers the
    // pointer, brings it to the front. Newly shown windows start in front.
    std::vector<WindowEntry>& order =
        ctx.state<WindowStack>(Id::fromString("grass::ui::windows")).order;
    auto it =
        std::find_if(order.begin(), order.end(), [&](const WindowEntry& e) { return e.id == id; });
    if (it == order.end() || !recent(*it, frame)) {
        if (it != order.end()) {
            order.erase(it);
        }
        order.push_back({id, r, frame});
        it = order.end() - 1;
    }
    it->lastFrame = frame;
    const Vec2 p = ctx.pointerPos();
    if (ctx.buttonPressed() && ctx.input().hasPointer && it->rect.contains(p) &&
        std::none_of(it + 1, order.end(), [&](const WindowEntry& e) {
            return recent(e, frame) && e.rect.contains(p);
        })) {
        std::rotate(it, it + 1, order.end());
        it = order.end() - 1;
    }
    const auto front = std::find_if(order.rbegin(), order.rend(),
                                    [&](const WindowEntry& e) { return recent(e, frame); });
    const Layer layer =
        front != order.rend() && front->id == id ? Layer::Foreground : Layer::Panels;

    const float titleHeight = s.interactHeight;
    // Hit areas: the whole window first (blocks what is below), then its title bar and close
    // button; the content and the resize grip come after, on top.
    ctx.interact(r, screen, layer, id, Sense::hover());
    ctx.registerArea(r);
    const Rect titleRect{r.min, {r.max.x, r.min.y + titleHeight}};
    const Response drag =
        ctx.interact(titleRect, screen, layer, id.with("title"), Sense::dragOnly());
    if (drag.dragged()) {
        r = keepOnScreen(Rect{r.min + drag.dragDelta(), r.max + drag.dragDelta()}, screen);
    }
    const Rect bar{r.min, {r.max.x, r.min.y + titleHeight}};
    Painter p2 = ctx.painter(layer, screen);
    p2.rect(r, s.rounding, s.popupFill, s.popupStroke);
    p2.rect(bar, s.rounding, layer == Layer::Foreground ? s.selectionFill : s.inactive.bgFill);
    p2.text({bar.min.x + PANEL_PADDING, bar.centre().y}, title, s.textSizePt, s.textStrong,
            {0.0f, 0.5f});
    if (open != nullptr) {
        const Rect close =
            Rect::fromMinSize({bar.max.x - titleHeight, bar.min.y}, Vec2(titleHeight));
        const Response c = ctx.interact(close, screen, layer, id.with("close"), Sense::clickOnly());
        const Vec2 m = close.centre();
        const float k = 0.22f * titleHeight;
        const Stroke x{c.hovered() ? 2.0f : 1.5f, c.hovered() ? s.textStrong : s.text};
        p2.line(m - Vec2(k), m + Vec2(k), x);
        p2.line({m.x - k, m.y + k}, {m.x + k, m.y - k}, x);
        if (c.clicked()) {
            *open = false;
        }
    }

    const Rect content{{r.min.x + PANEL_PADDING, bar.max.y + PANEL_PADDING},
                       r.max - Vec2(PANEL_PADDING)};
    Ui ui(ctx, content, layer);
    ctx.pushId(id);
    fn(ui);
    ctx.popId();

    const Rect grip{r.max - Vec2(GRIP_SIZE), r.max};
    const Response g = ctx.interact(grip, screen, layer, id.with("resize"), Sense::dragOnly());
    if (g.dragged()) {
        r = keepOnScreen(Rect{r.min, r.max + g.dragDelta()}, screen);
    }
    if (g.hovered() || g.dragged()) {
        ctx.output().cursor = CursorIcon::ResizeHorizontal;
    }
    // Three diagonal strokes: the usual look of a resize grip.
    const Color32 gripColor = g.hovered() || g.dragged() ? s.textStrong : s.textWeak;
    for (int i = 1; i <= 3; ++i) {
        const float d = 4.0f * float(i);
        p2.line({grip.max.x - d, grip.max.y - 1.0f}, {grip.max.x - 1.0f, grip.max.y - d},
                {1.0f, gripColor});
    }
    st.rect = r;
    // Found again: content that shows windows of its own may have grown the stack.
    for (WindowEntry& e : ctx.state<WindowStack>(Id::fromString("grass::ui::windows")).order) {
        if (e.id == id) {
            e.rect = r;
        }
    }
    return true;
}

}  // namespace grass::ui
